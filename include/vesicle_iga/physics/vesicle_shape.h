#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <vesicle_iga/spline/spline_space.h>

#include <array>
#include <string>
#include <vector>

namespace vesicle_iga
{

  /**
   * The initial vesicle of spec Part E: a sphere (circle) or an ellipsoid
   * (spheroid, ellipse) with the tanh profile (E1)/(E3) of the exact signed
   * distance, phi = +1 outside (Part E sign convention, spec section 7.1).
   * Declared in the subsection of the study; refuses bad input naming the
   * parameter.
   */
  template <int dim>
  struct VesicleShape
  {
    std::string             shape = "sphere";
    dealii::Point<dim>      center;
    std::array<double, dim> semi_axes{};

    static void
    declare(dealii::ParameterHandler &prm);
    void
    parse(dealii::ParameterHandler &prm);

    /// Signed distance to the surface, positive outside.
    double
    signed_distance(const dealii::Point<dim> &x) const;

    /// Refuses a shape whose gap to a face of the box [lower, upper] is
    /// below 2.08 epsilon (phi_0 < 0.9 where (E15) sets phi = 1) and warns
    /// below 5.4 epsilon (phi_0 < 0.999).
    void
    check_fits(const dealii::Point<dim>         &lower,
               const dealii::Point<dim>         &upper,
               const double                      epsilon,
               const dealii::ConditionalOStream &out) const;

    /// Coefficients (natural numbering) of the spline interpolant at the
    /// Greville points of phi_0 = tanh(d / (sqrt2 epsilon)) (E1).
    std::vector<double>
    phase_field(const SplineSpace<dim> &space, const double epsilon) const;
  };
} // namespace vesicle_iga
