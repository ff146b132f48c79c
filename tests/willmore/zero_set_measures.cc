// The sharp measures of a zero level set (issue 16, item 1: the reduced
// volume of a 3D phase field measured on its zero surface, not by the
// diffuse functionals (E9)), zero_set_measures(), against exact geometry on
// cubic C^2 spaces. How the expected values were checked:
//  - a linear field phi = z - 0.3 (x - 0.3 in 2D) on [-1, 1]^d is reproduced
//    exactly by the spline and by every simplex, so the zero set is the plane
//    of area 4 (the segment of length 2) and the part below it has volume
//    2 * 2 * 1.3 = 5.2 (area 2 * 1.3 = 2.6), to round-off (1e-12);
//  - a sphere of radius R = 1 (circle in 2D) as the tanh profile (E3) with
//    eps = 0.2, centred off the grid at (0.03, -0.02, 0.05), interpolated at
//    the Greville points of 24 elements per direction on [-1.5, 1.5]^d
//    (h = 0.125): area 4 pi R^2 and volume 4/3 pi R^3 (length 2 pi R, area
//    pi R^2) within 1e-3 relative with 4 samples per element. The surface is
//    inscribed in the spline's zero set, so with s samples per element its
//    error is O((h/s)^2) plus the interpolation error of the zero set, which
//    does not depend on s: the differences between s = 2, 4 and 8 fall by
//    a factor 4 (checked: between 3 and 5), and the reduced volume (area)
//    is 1 within 2e-3. Measured relative errors for s = 2, 4, 8: 3D area
//    -4.1e-4, -1.5e-4, -8.1e-5 and volume -1.0e-3, -3.3e-4, -1.5e-4
//    (ratios of the differences 4.1 and 4.0); 2D length -9.2e-5, -4.3e-5,
//    -2.8e-5 and area -3.2e-4, -1.2e-4, -6.6e-5 (ratios 3.4 and 3.4).

#include <deal.II/base/point.h>

#include <vesicle_iga/postprocess/zero_set_measures.h>

#include <cmath>
#include <fstream>

using namespace vesicle_iga;
using namespace dealii;

namespace
{
  template <int dim>
  SplineSpace<dim>
  box(const unsigned int elements, const double half_width)
  {
    std::array<KnotVector, dim> kv;
    for (unsigned int d = 0; d < dim; ++d)
      kv[d] = KnotVector::uniform(3, elements, -half_width, half_width);
    return SplineSpace<dim>(kv);
  }

  template <int dim, typename Function>
  std::vector<double>
  interpolate(const SplineSpace<dim> &space, const Function &f)
  {
    std::vector<double> at_greville;
    for (unsigned int i = 0; i < space.n_basis(); ++i)
      at_greville.push_back(f(space.greville_point(i)));
    return interpolate_at_greville_points(space, at_greville, 1);
  }

  const char *
  verdict(const bool ok)
  {
    return ok ? "ok" : "FAILED";
  }

  template <int dim>
  void
  check(std::ostream &out)
  {
    const char *boundary = dim == 3 ? "area" : "length";
    const char *inside   = dim == 3 ? "volume" : "area";
    out << dim << "D\n";

    // Linear field: exact.
    {
      const auto   space          = box<dim>(8, 1.);
      const auto   phi            = interpolate(space, [](const Point<dim> &x) {
        return x[dim - 1] - 0.3;
      });
      const auto   m              = zero_set_measures(space, phi, 1, 0, 3);
      const double exact_boundary = dim == 3 ? 4. : 2.;
      const double exact_inside   = dim == 3 ? 5.2 : 2.6;
      out << "  plane: " << boundary << " and " << inside << " exact to 1e-12: "
          << verdict(std::abs(m.boundary - exact_boundary) < 1e-12
                     && std::abs(m.inside - exact_inside) < 1e-12)
          << '\n';
    }

    // Sphere / circle.
    const auto   space = box<dim>(24, 1.5);
    Point<dim>   centre;
    const double offset[3] = {0.03, -0.02, 0.05};
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = offset[d];
    const double eps = 0.2, R = 1.;
    const auto   phi            = interpolate(space, [&](const Point<dim> &x) {
      return std::tanh((x.distance(centre) - R) / (std::sqrt(2.) * eps));
    });
    const double exact_boundary = dim == 3 ? 4 * M_PI * R * R : 2 * M_PI * R;
    const double exact_inside
      = dim == 3 ? 4. / 3 * M_PI * R * R * R : M_PI * R * R;
    ZeroSetMeasures m[3];
    for (unsigned int k = 0; k < 3; ++k)
      m[k] = zero_set_measures(space, phi, 1, 0, 2u << k);
    out << "  sphere: " << boundary << " within 1e-3 with 4 samples: "
        << verdict(std::abs(m[1].boundary / exact_boundary - 1) < 1e-3) << '\n';
    out << "  sphere: " << inside << " within 1e-3 with 4 samples: "
        << verdict(std::abs(m[1].inside / exact_inside - 1) < 1e-3) << '\n';
    const double rate_boundary
      = (m[0].boundary - m[1].boundary) / (m[1].boundary - m[2].boundary),
      rate_inside = (m[0].inside - m[1].inside) / (m[1].inside - m[2].inside);
    out << "  sphere: differences s = 2, 4, 8 fall by 3 to 5 (second "
           "order): "
        << verdict(rate_boundary > 3 && rate_boundary < 5 && rate_inside > 3
                   && rate_inside < 5)
        << '\n';
    out << "  sphere: reduced " << inside
        << " 1 within 2e-3: " << verdict(std::abs(m[1].reduced(dim) - 1) < 2e-3)
        << '\n';
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  check<2>(out);
  check<3>(out);
}
