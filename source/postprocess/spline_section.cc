#include <deal.II/base/exceptions.h>

#include <vesicle_iga/postprocess/spline_section.h>

namespace vesicle_iga
{
  SplineSection
  section_at_z(const SplineSpace<3>      &space,
               const std::vector<double> &natural,
               const unsigned int         n_components,
               const double               z)
  {
    const KnotVector &kz = space.knot_vector(2);
    AssertThrow(z >= kz.breakpoints().front() && z <= kz.breakpoints().back(),
                dealii::ExcMessage("section_at_z: z outside the box"));
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
        for (std::size_t a = 0; a < section.size(); ++a)
          section[a] += values[j] * natural[offset + a];
      }
    return {plane, section};
  }
} // namespace vesicle_iga
