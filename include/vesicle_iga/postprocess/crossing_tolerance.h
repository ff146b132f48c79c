#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/spline_dof_handler.h>

#include <vector>

namespace vesicle_iga
{
  /**
   * The tolerance on |phi| to which zero_contours() and
   * zero_set_measures() place a crossing on an element edge: 1e-12 of the
   * largest coefficient of the component, so that it scales with the
   * field (a phase field of range 1 or a level set in micrometres alike).
   *
   * This overload takes the coefficients of a whole field, @p n_components
   * interleaved, and looks at @p component.
   */
  double
  crossing_tolerance(const std::vector<double> &natural,
                     const unsigned int         n_components,
                     const unsigned int         component);

  /**
   * The same from a distributed field: the largest coefficient of
   * @p component over each rank's own elements, maximised over the ranks.
   */
  template <int dim>
  double
  crossing_tolerance(const SplineDofHandler<dim>                 &dofs,
                     const dealii::TrilinosWrappers::MPI::Vector &ghosted,
                     const unsigned int                           component);
} // namespace vesicle_iga
