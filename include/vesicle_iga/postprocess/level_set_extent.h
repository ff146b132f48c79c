#pragma once

#include <deal.II/base/point.h>

#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/spline_dof_handler.h>
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

  /**
   * The first and the last zero crossing of component @p component of a
   * distributed field (@p ghosted: locally relevant coefficients in the
   * numbering of @p dofs) along the same line, each rank searching its own
   * elements with their own coefficients (20 samples per element and
   * bisection, as above); empty when the line crosses the zero level set
   * fewer than twice. Collective; no rank holds the whole field.
   */
  template <int dim>
  std::vector<double>
  zero_crossing_bounds(const SplineDofHandler<dim>                 &dofs,
                       const dealii::TrilinosWrappers::MPI::Vector &ghosted,
                       const unsigned int                           component,
                       const dealii::Point<dim>                    &through,
                       const unsigned int                           d);
} // namespace vesicle_iga
