#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/spline_dof_handler.h>

#include <vector>

namespace vesicle_iga
{
  /**
   * Spline coefficients in the natural (tensor-product) numbering of
   * SplineSpace, as initial shapes, checkpoints and point evaluation use
   * them, and the distributed vectors in the SplineDofHandler numbering
   * that the solvers use. One place converts between the two.
   */

  /**
   * Writes the locally owned entries of @p owned (a vector without ghosts
   * in the numbering of @p dofs) from the complete natural coefficient vector
   * @p natural (n_components values per function, component fastest), and
   * compresses.
   */
  template <int dim>
  void
  scatter_natural(const SplineDofHandler<dim>           &dofs,
                  const std::vector<double>             &natural,
                  dealii::TrilinosWrappers::MPI::Vector &owned);

  /**
   * As scatter_natural(), from the complete natural coefficient vector held
   * on rank 0 only (the other ranks pass an empty vector): no rank but 0
   * ever holds the whole field. A collective call.
   */
  template <int dim>
  void
  scatter_natural_from_rank_0(const SplineDofHandler<dim>           &dofs,
                              const std::vector<double>             &natural,
                              dealii::TrilinosWrappers::MPI::Vector &owned);

  /**
   * The complete natural coefficient vector of @p v (n_components values
   * per function, component fastest) on rank 0, an empty vector on the
   * other ranks: for what rank 0 writes (checkpoints, samples, profiles).
   * A collective call; @p v may be ghosted.
   */
  template <int dim>
  std::vector<double>
  gather_natural_on_rank_0(const SplineDofHandler<dim>                 &dofs,
                           const dealii::TrilinosWrappers::MPI::Vector &v);
} // namespace vesicle_iga
