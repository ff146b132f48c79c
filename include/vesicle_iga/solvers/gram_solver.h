#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/spline_dof_handler.h>

#include <functional>

namespace vesicle_iga
{
  /**
   * The Gram matrix (v_i, v_j) of one scalar field on a spline space, as the
   * Jacobian of a rate term with respect to the rate, assembled through
   * @p constraints (homogeneous; empty for none) into @p matrix.
   */
  template <int dim>
  void
  assemble_gram_matrix(const SplineDofHandler<dim>             &dofs,
                       const dealii::Quadrature<1>             &quadrature,
                       const dealii::AffineConstraints<double> &constraints,
                       dealii::TrilinosWrappers::SparseMatrix  &matrix);


  /**
   * The L2 projection onto one scalar spline space with homogeneous strong
   * conditions (such as d phi / dn = 0): y = M^-1 b for the Gram matrix M of
   * the constrained basis, by CG with ILU(0) to 1e-12 relative. b holds
   * (psi_j, .) for the constrained basis psi_j (zero in constrained rows, as
   * an assembly through the same constraints leaves it); so does y, whose
   * dot product with such a b' is then (P b, P b') with P the projection.
   * Numbered as one component of a field of the same space (basis b of
   * that field: index b here). Used by VesicleHydrodynamics for the exact
   * discrete rates of (H13).
   */
  template <int dim>
  class GramSolver
  {
  public:
    /// @p conditions adds the strong conditions of the field to the
    /// constraints of this one-component handler.
    GramSolver(const PatchMesh<dim>        &mesh,
               const SplineSpace<dim>      &space,
               const dealii::Quadrature<1> &quadrature,
               const std::function<void(const SplineDofHandler<dim> &,
                                        dealii::AffineConstraints<double> &)>
                 &conditions);

    const dealii::IndexSet &
    locally_owned_dofs() const
    {
      return dofs.locally_owned_dofs();
    }
    /// y = M^-1 b (both owned, non-ghosted).
    void
    solve(const dealii::TrilinosWrappers::MPI::Vector &b,
          dealii::TrilinosWrappers::MPI::Vector       &y) const;

  private:
    const SplineDofHandler<dim>               dofs;
    dealii::AffineConstraints<double>         constraints;
    dealii::TrilinosWrappers::SparseMatrix    mass;
    dealii::TrilinosWrappers::PreconditionILU ilu;
  };
} // namespace vesicle_iga
