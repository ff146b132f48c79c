#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/spline_dof_handler.h>

#include <cstdint>
#include <utility>
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
   * The locally owned unknowns of @p dofs as pairs (natural index, index in
   * the numbering of @p dofs), ascending in the natural index (n_components
   * values per function, component fastest): what a rank reads and writes
   * of a field in a checkpoint.
   */
  template <int dim>
  std::vector<std::pair<std::uint64_t, dealii::types::global_dof_index>>
  owned_natural_entries(const SplineDofHandler<dim> &dofs);

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
