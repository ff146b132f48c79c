// Shared by the solver tests on small algebraic systems: the unknowns 0..n-1
// split evenly among the ranks, and the inverse of the diagonal of the
// matrix it was built for (Jacobi) as a caller's preconditioner, counting
// its builds.
#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/solvers/spline_multigrid.h>

#include <string>

/// This rank's part of n unknowns split evenly among the ranks of @p comm.
inline dealii::IndexSet
evenly_split(const unsigned int n, const MPI_Comm comm)
{
  const unsigned int ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
  const unsigned int rank  = dealii::Utilities::MPI::this_mpi_process(comm);
  dealii::IndexSet   owned(n);
  owned.add_range(rank * n / ranks, (rank + 1) * n / ranks);
  return owned;
}


class InverseDiagonal : public vesicle_iga::MatrixPreconditioner
{
public:
  /// @p builds (optional): incremented at every build.
  explicit InverseDiagonal(unsigned int *builds = nullptr)
    : builds(builds)
  {}
  void
  initialize(const dealii::TrilinosWrappers::SparseMatrix &matrix) override
  {
    if (builds)
      ++*builds;
    inverse.reinit(matrix.locally_owned_range_indices(),
                   matrix.get_mpi_communicator());
    for (const auto i : matrix.locally_owned_range_indices())
      inverse[i] = 1. / matrix.diag_element(i);
    inverse.compress(dealii::VectorOperation::insert);
  }
  void
  vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
        const dealii::TrilinosWrappers::MPI::Vector &src) const override
  {
    dst = src;
    dst.scale(inverse);
  }
  std::string
  description() const override
  {
    return "inverse diagonal";
  }

private:
  unsigned int                         *builds;
  dealii::TrilinosWrappers::MPI::Vector inverse;
};
