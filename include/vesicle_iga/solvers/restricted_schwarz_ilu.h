#pragma once

#include <deal.II/base/types.h>

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <functional>

namespace vesicle_iga
{
  /**
   * Restricted additive Schwarz (Cai and Sarkis, SIAM J. Sci. Comput. 21
   * (1999) 792-797) with ILU(0) subdomain solves: every rank takes the
   * matrix rows of its own unknowns extended by @p overlap layers of matrix
   * neighbours (dropping the columns outside that set), factors them by
   * ILU(0) in the order of @p natural_index, applies the factors to the
   * residual on the extended set, and keeps the correction on its own rows
   * only.
   *
   * Why: the ILU of each rank alone (block Jacobi across ranks) drops every
   * coupling across a rank interface; the stencils of spline spaces are
   * wide (7^3 entries per row for cubic C^2 in 3D), so as a multigrid
   * smoother it needed 12x more Krylov iterations on 2 ranks than on 1
   * (doc/performance.md). Adding the overlapping corrections instead of
   * restricting them (deal.II's PreconditionILU with overlap) counts the
   * overlap twice and over-corrects as a smoother. Ifpack's own restricted
   * Schwarz factors the ghost rows after the rank's own rows; ILU(0) of a
   * spline matrix is strong in the lexicographic order of the tensor-product
   * basis and weak in that one (the 2D biharmonic of
   * tests/solvers/schwarz_smoother: 16 GMRES iterations on 2 ranks with one
   * layer, 33 with two, against 4 on one rank), hence the ordering here.
   *
   * The operator is not symmetric (GMRES, not CG). On one rank, or with
   * @p overlap = 0, it is ILU(0) of the rank's rows in @p natural_index
   * order.
   */
  class RestrictedSchwarzILU : public dealii::TrilinosWrappers::PreconditionBase
  {
  public:
    /// @p natural_index maps a global row of @p matrix to its sort key.
    void
    initialize(const dealii::TrilinosWrappers::SparseMatrix &matrix,
               const unsigned int                            overlap,
               const std::function<dealii::types::global_dof_index(
                 dealii::types::global_dof_index)>          &natural_index);

  private:
    class Operator;
  };
} // namespace vesicle_iga
