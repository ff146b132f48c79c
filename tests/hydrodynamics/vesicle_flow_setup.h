// Set-up shared by the hydrodynamics tests: cubic uniform knot vectors of a
// box, the flow coefficients of spec Part H for cubic splines and strong
// velocity conditions on every wall.
#pragma once

#include <deal.II/base/function.h>

#include <vesicle_iga/models/vesicle_hydrodynamics.h>
#include <vesicle_iga/spline/knot_vector.h>

#include <array>
#include <cmath>
#include <memory>
#include <vector>

namespace vesicle_iga
{
  /// Cubic C^2 knot vectors of [x_0, x_1] x [y_0, y_1] with n_x x n_y
  /// uniform elements.
  inline std::array<KnotVector, 2>
  cubic_box_knots(const unsigned int n_x,
                  const double       x_0,
                  const double       x_1,
                  const unsigned int n_y,
                  const double       y_0,
                  const double       y_1)
  {
    return {KnotVector::uniform(3, n_x, x_0, x_1),
            KnotVector::uniform(3, n_y, y_0, y_1)};
  }

  /// The same on the square [lower, upper]^2 with n x n elements.
  inline std::array<KnotVector, 2>
  cubic_box_knots(const unsigned int n, const double lower, const double upper)
  {
    return cubic_box_knots(n, lower, upper, n, lower, upper);
  }

  /// Re of (H4) from the membrane coefficients and the inverse-estimate
  /// constant C_I = 6 p^4 of (H19) for p = 3.
  inline FlowCoefficients<2>
  cubic_flow_coefficients(const MembraneCoefficients &membrane)
  {
    FlowCoefficients<2> flow;
    flow.reynolds_number           = membrane.reynolds_number;
    flow.inverse_estimate_constant = 6. * std::pow(3., 4);
    return flow;
  }

  /// @p velocity (dim velocity components and a pressure slot) strongly on
  /// every wall.
  inline std::vector<VelocityCondition<2>>
  strong_walls(std::shared_ptr<dealii::Function<2>> velocity)
  {
    return {{BoundarySelection<2>("all", "walls"), velocity, false}};
  }
} // namespace vesicle_iga
