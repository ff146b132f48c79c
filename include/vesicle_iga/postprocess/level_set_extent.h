#pragma once

#include <deal.II/base/point.h>

#include <vesicle_iga/spline/spline_space.h>

#include <vector>

namespace vesicle_iga
{
  /**
   * The zero crossings of a scalar spline field (coefficients in natural
   * numbering) along the line through @p through parallel to axis @p d,
   * found by sampling 20 points per element and bisection, in increasing
   * order (spec section 3.11: the axis lengths of the phi = 0 level set).
   */
  template <int dim>
  std::vector<double>
  zero_crossings_along_axis(const SplineSpace<dim>    &space,
                            const std::vector<double> &coefficients,
                            const dealii::Point<dim>  &through,
                            const unsigned int         d);

  /// Distance between the first and the last zero crossing (0 if there are
  /// fewer than two): the extent of the vesicle along axis d.
  template <int dim>
  double
  zero_level_set_extent(const SplineSpace<dim>    &space,
                        const std::vector<double> &coefficients,
                        const dealii::Point<dim>  &through,
                        const unsigned int         d);
} // namespace vesicle_iga
