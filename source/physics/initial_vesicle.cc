// Initial vesicles of Part H, spec (H22)-(H23) and 4.11.

#include <deal.II/base/quadrature_lib.h>

#include <vesicle_iga/physics/initial_vesicle.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  InitialVesicle::InitialVesicle(const Point<2>      &centre,
                                 const double         radius,
                                 const double         reduced_area,
                                 const double         angle_degrees,
                                 const StretchFormula formula)
    : centre(centre)
    , radius(radius)
    , gamma(stretch_for(reduced_area, formula))
    , angle(angle_degrees * M_PI / 180.)
  {}


  double
  InitialVesicle::ellipse_perimeter(const double a, const double b)
  {
    // P = 4 int_0^{pi/2} sqrt(a^2 sin^2 t + b^2 cos^2 t) dt: the integrand
    // is analytic, so composite Gauss converges exponentially.
    const QGauss<1>    gauss(20);
    const unsigned int pieces = 16;
    double             sum    = 0;
    for (unsigned int k = 0; k < pieces; ++k)
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const double t = 0.5 * M_PI * (k + gauss.point(q)[0]) / pieces;
          sum += std::sqrt(std::pow(a * std::sin(t), 2)
                           + std::pow(b * std::cos(t), 2))
                 * gauss.weight(q) * 0.5 * M_PI / pieces;
        }
    return 4 * sum;
  }


  double
  InitialVesicle::stretch_for(const double chi, const StretchFormula formula)
  {
    if (chi >= 1)
      return 1;
    if (formula == StretchFormula::quadratic_mean)
      // Perimeter 2 pi sqrt((a^2 + b^2) / 2) in (H22) (spec 4.11).
      return std::sqrt((1 + std::sqrt(1 - chi * chi)) / chi);
    // chi(gamma) = 4 pi (pi R^2) / P^2 with semi-axes R / gamma, gamma R
    // decreases from 1 at gamma = 1: bisection.
    const auto reduced = [](const double g) {
      const double P = ellipse_perimeter(1 / g, g);
      return 4 * M_PI * M_PI / (P * P);
    };
    double lo = 1, hi = 2;
    while (reduced(hi) > chi)
      hi *= 2;
    for (unsigned int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it)
      {
        const double mid               = 0.5 * (lo + hi);
        (reduced(mid) > chi ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }


  double
  InitialVesicle::actual_reduced_area() const
  {
    const double P = ellipse_perimeter(radius / gamma, radius * gamma);
    return 4 * M_PI * M_PI * radius * radius / (P * P);
  }


  double
  InitialVesicle::signed_distance(const Point<2> &x) const
  {
    // Coordinates along the minor (x') and major (y') axes.
    const Tensor<1, 2> r  = x - centre;
    const double       xp = r[0] * std::sin(angle) - r[1] * std::cos(angle);
    const double       yp = r[0] * std::cos(angle) + r[1] * std::sin(angle);
    const double       rho
      = std::sqrt(gamma * gamma * xp * xp + yp * yp / (gamma * gamma));
    if (rho == 0)
      return -radius / gamma;
    return r.norm() / rho * (rho - radius);
  }


  double
  InitialVesicle::phase_field(const Point<2> &x, const double eps) const
  {
    return std::tanh(-signed_distance(x) / (std::sqrt(2.) * eps));
  }


  std::vector<Point<2>>
  InitialVesicle::outline(const unsigned int n) const
  {
    std::vector<Point<2>> points;
    const Tensor<1, 2>    minor({std::sin(angle), -std::cos(angle)});
    const Tensor<1, 2>    major({std::cos(angle), std::sin(angle)});
    for (unsigned int k = 0; k < n; ++k)
      {
        const double t = 2 * M_PI * k / n;
        points.push_back(centre + radius / gamma * std::cos(t) * minor
                         + radius * gamma * std::sin(t) * major);
      }
    return points;
  }
} // namespace vesicle_iga
