// The initial vesicles of (H23) in 3D (and the 2D ones unchanged), against
// quantities computed here independently of the class:
// - the reduced volume v = 6 sqrt(pi) V / A^{3/2} of the prolate spheroid
//   built for v = 0.6, 0.9, 1, with V = (4/3) pi a^2 c and A integrated
//   numerically over the surface parametrisation X(s, t) (Gauss-Legendre in
//   s and t of |X_s x X_t|, not the closed form the class uses), equals the
//   v asked for to 1e-10;
// - its volume is that of the sphere of radius R_0 (equal-volume radius);
// - the outline lies on the zero level set of the signed distance (1e-12),
//   the ends of the long axis are at centre +- c (cos angle, sin angle, 0)
//   and those of the short axes at centre +- a e_z: the distance is 0
//   there, negative at the centre (-a) and positive outside;
// - 2D: the ellipse of reduced area 0.84 has the stretch 1.41626 the 2D
//   studies printed before the class became dimension-generic, and its
//   perimeter, integrated here over the parametrisation (not by the
//   class's ellipse_perimeter), gives back 0.84.

#include <deal.II/base/quadrature_lib.h>

#include <vesicle_iga/physics/initial_vesicle.h>

#include <cmath>
#include <fstream>

#include "../root_output.h"

using namespace vesicle_iga;
using namespace dealii;

namespace
{
  /// The area of the spheroid with semi-axes c (along e_0), a, a by
  /// Gauss-Legendre quadrature of |X_s x X_t| over s in (0, pi), t in
  /// (0, 2 pi).
  double
  numerical_area(const double c, const double a)
  {
    const QGauss<1> gauss(40);
    double          sum = 0;
    for (unsigned int i = 0; i < gauss.size(); ++i)
      for (unsigned int j = 0; j < gauss.size(); ++j)
        {
          const double s = M_PI * gauss.point(i)[0];
          const double t = 2 * M_PI * gauss.point(j)[0];
          Tensor<1, 3> Xs, Xt;
          Xs[0] = -c * std::sin(s);
          Xs[1] = a * std::cos(s) * std::cos(t);
          Xs[2] = a * std::cos(s) * std::sin(t);
          Xt[1] = -a * std::sin(s) * std::sin(t);
          Xt[2] = a * std::sin(s) * std::cos(t);
          sum += cross_product_3d(Xs, Xt).norm() * gauss.weight(i)
                 * gauss.weight(j) * 2 * M_PI * M_PI;
        }
    return sum;
  }
} // namespace

int
main()
{
  std::ofstream  out("output");
  const double   R     = 0.7;
  const double   angle = 30;
  const Point<3> centre(0.1, -0.2, 0.3);
  for (const double v : {0.6, 0.9, 1.0})
    {
      const InitialVesicle<3> vesicle(centre, R, v, angle);
      const double            g = vesicle.stretch();
      const double            c = g * g * R, a = R / g;
      const double            V = 4 * M_PI / 3 * a * a * c;
      const double            reduced
        = 6 * std::sqrt(M_PI) * V / std::pow(numerical_area(c, a), 1.5);
      double on_surface = 0;
      for (const auto &x : vesicle.outline(2000))
        on_surface = std::max(on_surface, std::abs(vesicle.signed_distance(x)));
      const double   phi = angle * M_PI / 180;
      const Point<3> tip(centre[0] + c * std::cos(phi),
                         centre[1] + c * std::sin(phi),
                         centre[2]);
      const Point<3> side(centre[0], centre[1], centre[2] - a);
      const double   axes = std::max(std::abs(vesicle.signed_distance(tip)),
                                   std::abs(vesicle.signed_distance(side)));
      const Point<3> outside(centre[0], centre[1], centre[2] + 1.1 * a);
      out << "v = " << v << ": reduced volume (numerical area) = v (1e-10): "
          << verdict(std::abs(reduced - v) < 1e-10)
          << "; volume = 4/3 pi R_0^3 (1e-12): "
          << verdict(std::abs(V / (4 * M_PI / 3 * R * R * R) - 1) < 1e-12)
          << "; outline on the zero level set (1e-12): "
          << verdict(on_surface < 1e-12) << "; axes: " << verdict(axes < 1e-12)
          << "; d(centre) = -a, d(outside) > 0: "
          << verdict(std::abs(vesicle.signed_distance(centre) + a) < 1e-12
                     && vesicle.signed_distance(outside) > 0)
          << '\n';
    }
  const InitialVesicle<2> ellipse(Point<2>(0, 0), 0.863, 0.84, 90);
  const double            g = ellipse.stretch();
  double                  P = 0;
  const QGauss<1>         gauss(60);
  for (unsigned int q = 0; q < gauss.size(); ++q)
    {
      const double t = 2 * M_PI * gauss.point(q)[0];
      P += std::hypot(0.863 / g * std::sin(t), 0.863 * g * std::cos(t))
           * gauss.weight(q) * 2 * M_PI;
    }
  out << "2D: stretch 1.41626 (5e-6): " << verdict(std::abs(g - 1.41626) < 5e-6)
      << "; reduced area 4 pi^2 R^2 / P^2 = 0.84 (1e-12): "
      << verdict(std::abs(4 * M_PI * M_PI * 0.863 * 0.863 / (P * P) - 0.84)
                 < 1e-12)
      << '\n';
}
