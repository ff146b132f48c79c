#pragma once

#include <deal.II/base/point.h>

#include <array>

namespace vesicle_iga
{

  /**
   * Signed distance from y to the ellipsoid (ellipse in 2D) with semi-axes
   * a centred at the origin, negative inside. The closest point is
   * x_k = a_k^2 y_k / (a_k^2 + t) with t the root of
   * F(t) = sum (a_k y_k / (a_k^2 + t))^2 - 1, monotone for t > -min a_k^2;
   * found by bisection, so it is robust for thin shapes. The tanh profile
   * (E1) needs the true distance: an approximate one with |grad d| != 1 on
   * the surface is not the equilibrium profile and inflates the bending
   * energy like 1/epsilon.
   */
  template <int dim>
  double
  signed_distance_to_ellipsoid(const dealii::Point<dim>      &y,
                               const std::array<double, dim> &a);
} // namespace vesicle_iga
