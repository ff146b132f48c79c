#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/spline_dof_handler.h>
#include <vesicle_iga/spline/spline_cell_values.h>

#include <functional>
#include <memory>
#include <vector>

namespace vesicle_iga
{
  /**
   * Integrate quantities of a computed field over the locally owned
   * elements and sum over all ranks, for error norms against exact
   * solutions given as functions of x (postprocessing, with the full basis
   * tables; assembly and monitored functionals go through the engine's
   * SystemAssembler). @p integrand receives the element values, a
   * quadrature point and the field's local coefficients (one vector per
   * component) and adds its contributions (already multiplied by JxW) to
   * @p sums, which has @p n_sums entries.
   */
  template <int dim>
  std::vector<double>
  integrate_field(
    const SplineDofHandler<dim>                      &dof_handler,
    std::shared_ptr<const NurbsGeometry<dim>>         geometry,
    const dealii::Quadrature<1>                      &quadrature_1d,
    const unsigned int                                derivative_order,
    const dealii::TrilinosWrappers::MPI::Vector      &ghosted_solution,
    const unsigned int                                n_sums,
    const std::function<void(const SplineCellValues<dim> &,
                             const unsigned int,
                             const std::vector<std::vector<double>> &,
                             std::vector<double> &)> &integrand);

  /**
   * Error norms of a scalar spline field against an exact solution:
   * ||u - u_h||_L2, |u - u_h|_H1 and, for @p order 2, |u - u_h|_H2 (the
   * L2 norms of the differences of the gradients and Hessians), with the
   * exact derivatives from @p exact (value, gradient, hessian).
   */
  template <int dim>
  std::vector<double>
  scalar_error_norms(const SplineDofHandler<dim>                 &dof_handler,
                     const dealii::Function<dim>                 &exact,
                     const dealii::Quadrature<1>                 &quadrature_1d,
                     const unsigned int                           order,
                     const dealii::TrilinosWrappers::MPI::Vector &solution);
} // namespace vesicle_iga
