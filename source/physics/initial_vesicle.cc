// Initial vesicles of Part H, spec (H22)-(H23) and 4.11, in 2D and 3D.

#include <deal.II/base/quadrature_lib.h>

#include <vesicle_iga/physics/ellipsoid_distance.h>
#include <vesicle_iga/physics/initial_vesicle.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vesicle_iga
{
  using namespace dealii;

  double
  InitialVesicleBase::ellipse_perimeter(const double a, const double b)
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
  InitialVesicleBase::prolate_spheroid_area(const double c, const double a)
  {
    const double e = std::sqrt(std::max(0., 1 - a * a / (c * c)));
    // A = 2 pi a^2 (1 + c asin(e) / (a e)); asin(e) / e -> 1 as e -> 0.
    const double ratio = e < 1e-8 ? 1 + e * e / 6 : std::asin(e) / e;
    return 2 * M_PI * a * a * (1 + c / a * ratio);
  }


  namespace
  {
    /// The reduced area (2D) or volume (3D) of the shape with stretch g
    /// and equal-measure radius 1.
    template <int dim>
    double
    reduced_measure(const double g)
    {
      if constexpr (dim == 2)
        {
          const double P = InitialVesicleBase::ellipse_perimeter(1 / g, g);
          return 4 * M_PI * M_PI / (P * P);
        }
      else
        {
          const double A
            = InitialVesicleBase::prolate_spheroid_area(g * g, 1 / g);
          return 6 * std::sqrt(M_PI) * (4 * M_PI / 3) / std::pow(A, 1.5);
        }
    }
  } // namespace


  template <int dim>
  InitialVesicle<dim>::InitialVesicle(const Point<dim>     &centre,
                                      const double          radius,
                                      const double          reduced,
                                      const double          angle_degrees,
                                      const StretchFormula  formula,
                                      const DistanceFormula distance)
    : centre(centre)
    , radius(radius)
    , gamma(stretch_for(reduced, formula))
    , angle(angle_degrees * M_PI / 180.)
    , distance(distance)
  {}


  template <int dim>
  double
  InitialVesicle<dim>::stretch_for(const double         reduced,
                                   const StretchFormula formula)
  {
    if (reduced >= 1)
      return 1;
    if (dim == 2 && formula == StretchFormula::quadratic_mean)
      // Perimeter 2 pi sqrt((a^2 + b^2) / 2) in (H22) (spec 4.11).
      return std::sqrt((1 + std::sqrt(1 - reduced * reduced)) / reduced);
    // The reduced measure decreases from 1 at g = 1: bisection.
    double lo = 1, hi = 2;
    while (reduced_measure<dim>(hi) > reduced)
      hi *= 2;
    for (unsigned int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it)
      {
        const double mid                                = 0.5 * (lo + hi);
        (reduced_measure<dim>(mid) > reduced ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }


  template <int dim>
  double
  InitialVesicle<dim>::actual_reduced_measure() const
  {
    return reduced_measure<dim>(gamma);
  }


  template <int dim>
  double
  InitialVesicle<dim>::major_semi_axis() const
  {
    // Equal measure: (R / g) (g R) = R^2 in 2D, (R / g)^2 (g^2 R) = R^3.
    return (dim == 2 ? gamma : gamma * gamma) * radius;
  }


  template <int dim>
  double
  InitialVesicle<dim>::minor_semi_axis() const
  {
    return radius / gamma;
  }


  template <int dim>
  Tensor<1, dim>
  InitialVesicle<dim>::major_axis() const
  {
    Tensor<1, dim> t;
    t[0] = std::cos(angle);
    t[1] = std::sin(angle);
    return t;
  }


  template <int dim>
  Tensor<1, dim>
  InitialVesicle<dim>::minor_axis(const unsigned int k) const
  {
    Tensor<1, dim> t;
    if (k == 0)
      {
        t[0] = std::sin(angle);
        t[1] = -std::cos(angle);
      }
    else
      t[2] = 1;
    return t;
  }


  template <int dim>
  double
  InitialVesicle<dim>::signed_distance(const Point<dim> &x) const
  {
    switch (distance)
      {
        case DistanceFormula::radial:
          return radial_distance(x);
        case DistanceFormula::level_set:
          return level_set_distance(x);
        case DistanceFormula::exact:
          return exact_distance(x);
      }
    return 0;
  }


  template <int dim>
  double
  InitialVesicle<dim>::centre_jump(const double eps) const
  {
    if (distance != DistanceFormula::radial)
      return 0;
    // Along the major axis d -> -c at the centre, along a minor one -> -a.
    return std::tanh(major_semi_axis() / (std::sqrt(2.) * eps))
           - std::tanh(minor_semi_axis() / (std::sqrt(2.) * eps));
  }


  template <int dim>
  double
  InitialVesicle<dim>::outline_slope() const
  {
    // The shape is a body of revolution about the major axis (2D: mirror
    // symmetric), so one quarter meridian holds every slope.
    const double c = major_semi_axis(), a = minor_semi_axis();
    const double step    = 1e-6 * radius;
    double       largest = 0;
    for (unsigned int k = 0; k <= 400; ++k)
      {
        const double theta = 0.5 * numbers::PI * k / 400;
        const double rho   = c * a
                           / std::sqrt(std::pow(a * std::cos(theta), 2)
                                       + std::pow(c * std::sin(theta), 2));
        const Point<dim> x = centre
                             + rho
                                 * (std::cos(theta) * major_axis()
                                    + std::sin(theta) * minor_axis(0));
        double grad2 = 0;
        for (unsigned int d = 0; d < dim; ++d)
          {
            Tensor<1, dim> e;
            e[d] = step;
            const double g
              = (signed_distance(x + e) - signed_distance(x - e)) / (2 * step);
            grad2 += g * g;
          }
        largest = std::max(largest, std::sqrt(grad2));
      }
    return largest;
  }


  template <int dim>
  double
  InitialVesicle<dim>::level_set_distance(const Point<dim> &x) const
  {
    // F = (x'_major / c)^2 + sum_k (x'_minor,k / a)^2 - 1 and d = F / |grad
    // F|: one Newton step towards the surface from F's own scale, so that
    // |grad d| = grad F / |grad F| has unit length on F = 0.
    const Tensor<1, dim> r = x - centre;
    const double         c = major_semi_axis(), a = minor_semi_axis();
    const double         major = r * major_axis();
    double               F     = major * major / (c * c) - 1,
           grad2               = std::pow(2 * major / (c * c), 2);
    for (unsigned int k = 0; k + 1 < dim; ++k)
      {
        const double minor = r * minor_axis(k);
        F += minor * minor / (a * a);
        grad2 += std::pow(2 * minor / (a * a), 2);
      }
    if (grad2 == 0)
      return -std::numeric_limits<double>::infinity();
    return F / std::sqrt(grad2);
  }


  template <int dim>
  double
  InitialVesicle<dim>::exact_distance(const Point<dim> &x) const
  {
    // In the axes' coordinates the surface is the ellipsoid with semi-axes
    // (c, a, a) centred at the origin.
    const Tensor<1, dim>    r = x - centre;
    Point<dim>              y;
    std::array<double, dim> semi_axes;
    y[0]         = r * major_axis();
    semi_axes[0] = major_semi_axis();
    for (unsigned int k = 0; k + 1 < dim; ++k)
      {
        y[k + 1]         = r * minor_axis(k);
        semi_axes[k + 1] = minor_semi_axis();
      }
    return signed_distance_to_ellipsoid<dim>(y, semi_axes);
  }


  template <int dim>
  double
  InitialVesicle<dim>::radial_distance(const Point<dim> &x) const
  {
    // rho = R on the surface: with x' the coordinates along the axes,
    // rho^2 = g^2 x'_minor^2 + x'_major^2 / g^2 (2D) and g^2 |x'_minor|^2 +
    // x'_major^2 / g^4 (3D).
    const Tensor<1, dim> r     = x - centre;
    const double         major = r * major_axis();
    double               rho;
    if constexpr (dim == 2)
      {
        const double minor = r * minor_axis(0);
        rho                = std::sqrt(gamma * gamma * minor * minor
                        + major * major / (gamma * gamma));
      }
    else
      {
        double minor2 = 0;
        for (unsigned int k = 0; k + 1 < dim; ++k)
          minor2 += std::pow(r * minor_axis(k), 2);
        rho = std::sqrt(gamma * gamma * minor2
                        + major * major / std::pow(gamma, 4));
      }
    const double a = minor_semi_axis();
    if (rho == 0)
      return -a;
    return r.norm() / rho * (rho - radius);
  }


  template <int dim>
  double
  InitialVesicle<dim>::phase_field(const Point<dim> &x, const double eps) const
  {
    return std::tanh(-signed_distance(x) / (std::sqrt(2.) * eps));
  }


  template <int dim>
  double
  InitialVesicle<dim>::mirrored_phase_field(
    const Point<dim>            &x,
    const double                 eps,
    const Point<dim>            &lower,
    const Point<dim>            &upper,
    const std::array<bool, dim> &mirror) const
  {
    // Per direction the point itself and its reflections in the lower and
    // upper wall: 3^dim images, of which those in unmirrored directions
    // are skipped.
    double       indicator = 0;
    unsigned int n_images  = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_images *= 3;
    for (unsigned int image = 0; image < n_images; ++image)
      {
        Point<dim>   y    = x;
        unsigned int code = image;
        bool         used = true;
        for (unsigned int d = 0; d < dim; ++d, code /= 3)
          if (code % 3 != 0)
            {
              used = used && mirror[d];
              y[d] = 2 * (code % 3 == 1 ? lower[d] : upper[d]) - x[d];
            }
        if (used)
          indicator += 0.5 * (1 + phase_field(y, eps));
      }
    return 2 * indicator - 1;
  }


  template <int dim>
  double
  InitialVesicle<dim>::wall_gap(const Point<dim>            &lower,
                                const Point<dim>            &upper,
                                const std::array<bool, dim> &mirror) const
  {
    double gap = std::numeric_limits<double>::infinity();
    for (const auto &x : outline(dim == 2 ? 720 : 2000))
      for (unsigned int d = 0; d < dim; ++d)
        if (mirror[d])
          gap = std::min({gap, x[d] - lower[d], upper[d] - x[d]});
    return gap;
  }


  template <int dim>
  std::vector<Point<dim>>
  InitialVesicle<dim>::outline(const unsigned int n) const
  {
    std::vector<Point<dim>> points;
    const double            a = minor_semi_axis(), c = major_semi_axis();
    if constexpr (dim == 2)
      for (unsigned int k = 0; k < n; ++k)
        {
          const double t = 2 * M_PI * k / n;
          points.push_back(centre + a * std::cos(t) * minor_axis(0)
                           + c * std::sin(t) * major_axis());
        }
    else
      {
        // Latitudes from pole to pole along the major axis, each circle
        // with as many points as keeps the spacing about even.
        const unsigned int n_lat = std::max(3u, unsigned(std::sqrt(n / 2.)));
        for (unsigned int i = 0; i <= n_lat; ++i)
          {
            const double       s = M_PI * i / n_lat;
            const unsigned int n_lon
              = std::max(1u, unsigned(2 * n_lat * std::sin(s) + 0.5));
            for (unsigned int j = 0; j < n_lon; ++j)
              {
                const double t = 2 * M_PI * j / n_lon;
                points.push_back(centre + c * std::cos(s) * major_axis()
                                 + a * std::sin(s)
                                     * (std::cos(t) * minor_axis(0)
                                        + std::sin(t) * minor_axis(1)));
              }
          }
      }
    return points;
  }


  template class InitialVesicle<2>;
  template class InitialVesicle<3>;
} // namespace vesicle_iga
