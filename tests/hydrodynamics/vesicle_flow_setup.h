// Set-up shared by the hydrodynamics tests: the flow coefficients of spec
// Part H for cubic splines and strong velocity conditions on every wall.
#pragma once

#include <deal.II/base/function.h>

#include <vesicle_iga/models/vesicle_hydrodynamics.h>

#include <cmath>
#include <memory>
#include <vector>

namespace vesicle_iga
{
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
