#include <vesicle_iga/physics/ellipsoid_distance.h>

#include <algorithm>
#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  double
  signed_distance_to_ellipsoid(const Point<dim>              &y_in,
                               const std::array<double, dim> &a)
  {
    // A point exactly on a symmetry plane makes the closest point
    // ambiguous; a perturbation far below any mesh size removes the tie.
    Point<dim> y     = y_in;
    double     a_min = a[0], a_max = a[0];
    for (unsigned int k = 0; k < dim; ++k)
      {
        a_min = std::min(a_min, a[k]);
        a_max = std::max(a_max, a[k]);
        if (std::abs(y[k]) < 1e-13 * a[k])
          y[k] = 1e-13 * a[k];
      }
    const auto F = [&](const double t) {
      double s = 0;
      for (unsigned int k = 0; k < dim; ++k)
        s += std::pow(a[k] * y[k] / (a[k] * a[k] + t), 2);
      return s - 1;
    };
    const bool outside = F(0.) > 0;
    double     lo      = outside ? 0. : -a_min * a_min;
    double     hi      = outside ? a_max * y.norm() + 1. : 0.;
    for (unsigned int i = 0; i < 200 && hi - lo > 1e-15 * (1 + std::abs(hi));
         ++i)
      {
        const double m       = 0.5 * (lo + hi);
        (F(m) > 0 ? lo : hi) = m;
      }
    const double t  = 0.5 * (lo + hi);
    double       d2 = 0;
    for (unsigned int k = 0; k < dim; ++k)
      d2 += std::pow(y[k] - a[k] * a[k] * y[k] / (a[k] * a[k] + t), 2);
    return (outside ? 1. : -1.) * std::sqrt(d2);
  }

  template double
  signed_distance_to_ellipsoid<2>(const Point<2> &,
                                  const std::array<double, 2> &);
  template double
  signed_distance_to_ellipsoid<3>(const Point<3> &,
                                  const std::array<double, 3> &);
} // namespace vesicle_iga
