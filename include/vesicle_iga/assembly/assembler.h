#pragma once

#include <deal.II/base/quadrature.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/assembly/assembly_term.h>
#include <vesicle_iga/parallel/spline_dof_handler.h>

#include <functional>
#include <memory>
#include <vector>

namespace vesicle_iga
{
  /**
   * Assemble matrix and right-hand side of a linear problem as the sum of
   * @p terms, over the locally owned elements (WorkStream with
   * ScratchData = SplineCellValues for cells and faces, CopyData = element
   * matrix, vector and indices), then condense with @p constraints
   * (inhomogeneous Dirichlet values included) while distributing.
   */
  template <int dim>
  void
  assemble_linear_system(const SplineDofHandler<dim>              &dof_handler,
                         std::shared_ptr<const NurbsGeometry<dim>> geometry,
                         const Quadrature<1> &quadrature_1d,
                         const std::vector<const AssemblyTerm<dim> *> &terms,
                         const AffineConstraints<double> &constraints,
                         TrilinosWrappers::SparseMatrix  &matrix,
                         TrilinosWrappers::MPI::Vector   &rhs);

  /**
   * The right-hand side alone (terms still receive a matrix argument, which
   * is discarded; terms that know they are asked for a vector only, such as
   * a Newton residual, skip their matrix work).
   */
  template <int dim>
  void
  assemble_vector(const SplineDofHandler<dim>                  &dof_handler,
                  std::shared_ptr<const NurbsGeometry<dim>>     geometry,
                  const Quadrature<1>                          &quadrature_1d,
                  const std::vector<const AssemblyTerm<dim> *> &terms,
                  const AffineConstraints<double>              &constraints,
                  TrilinosWrappers::MPI::Vector                &rhs);

  /**
   * Integrate quantities of a computed field over the locally owned
   * elements and sum over all ranks. @p integrand receives the element
   * values, a quadrature point and the field's local coefficients (one
   * vector per component) and adds its contributions (already multiplied
   * by JxW) to @p sums, which has @p n_sums entries.
   */
  template <int dim>
  std::vector<double>
  integrate_field(
    const SplineDofHandler<dim>                      &dof_handler,
    std::shared_ptr<const NurbsGeometry<dim>>         geometry,
    const Quadrature<1>                              &quadrature_1d,
    const unsigned int                                derivative_order,
    const TrilinosWrappers::MPI::Vector              &ghosted_solution,
    const unsigned int                                n_sums,
    const std::function<void(const SplineCellValues<dim> &,
                             const unsigned int,
                             const std::vector<std::vector<double>> &,
                             std::vector<double> &)> &integrand);

  /// Local coefficients of an element, one vector per component.
  template <int dim>
  void
  get_element_coefficients(const SplineDofHandler<dim>         &dof_handler,
                           const TrilinosWrappers::MPI::Vector &ghosted,
                           const unsigned int                   element,
                           std::vector<std::vector<double>>    &coefficients);
} // namespace vesicle_iga
