#include <deal.II/base/exceptions.h>

#include <vesicle_iga/postprocess/spline_section.h>

#include <cmath>
#include <string>

namespace vesicle_iga
{
  SplineSection
  section_at_z(const SplineSpace<3>      &space,
               const std::vector<double> &natural,
               const unsigned int         n_components,
               double                     z)
  {
    const KnotVector &kz = space.knot_vector(2);
    const double      a = kz.breakpoints().front(), b = kz.breakpoints().back();
    // A periodic direction has no ends: a centroid computed from circular
    // moments may come out a round-off outside [a, b).
    if (kz.is_periodic())
      z = a + std::fmod(std::fmod(z - a, b - a) + (b - a), b - a);
    AssertThrow(z >= a && z <= b,
                dealii::ExcMessage("section_at_z: z = " + std::to_string(z)
                                   + " outside the box"));
    AssertDimension(natural.size(), space.n_basis() * n_components);
    const SplineSpace<2> plane(
      std::array<KnotVector, 2>{{space.knot_vector(0), space.knot_vector(1)}});
    const unsigned int n_plane = plane.n_basis();
    const unsigned int e       = kz.find_element(z);
    const auto         values  = kz.evaluate_on_element(e, z, 0)[0];

    std::vector<double> section(n_plane * n_components, 0.);
    for (unsigned int j = 0; j <= kz.degree(); ++j)
      {
        // Natural numbering, first direction fastest: the layer k of the
        // 3D coefficients is the block [k n_plane, (k + 1) n_plane).
        const std::size_t offset
          = std::size_t(kz.global_index(e, j)) * n_plane * n_components;
        for (std::size_t c = 0; c < section.size(); ++c)
          section[c] += values[j] * natural[offset + c];
      }
    return {plane, section};
  }
} // namespace vesicle_iga
