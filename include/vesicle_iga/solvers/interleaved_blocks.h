#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <utility>
#include <vector>

namespace vesicle_iga
{
  /// The entries of one matrix row: (global column, value).
  using MatrixRow
    = std::vector<std::pair<dealii::types::global_dof_index, double>>;

  /// Call @p f(column, value) for the entries of the locally owned row
  /// @p row (global indices). Through Epetra's row view: deal.II's row
  /// iterators allocate a buffer of the global column count per row.
  void
  for_each_row_entry(
    const dealii::TrilinosWrappers::SparseMatrix                       &matrix,
    const dealii::types::global_dof_index                               row,
    const std::function<void(dealii::types::global_dof_index, double)> &f);

  /// A distributed matrix with the locally owned rows @p rows (the k-th is
  /// the k-th element of @p row_set; global column indices, any order,
  /// repeated columns summed); @p column_set is its domain.
  void
  make_distributed_matrix(const dealii::IndexSet                 &row_set,
                          const dealii::IndexSet                 &column_set,
                          const MPI_Comm                          comm,
                          std::vector<MatrixRow>                 &rows,
                          dealii::TrilinosWrappers::SparseMatrix &matrix);


  /**
   * The unknowns of a monolithic system interleaved per spline basis
   * function (global index b n_components + c, every rank owning whole
   * basis functions, SplineDofHandler) seen as groups of components: group
   * g is a vector and a set of matrix blocks of its own, numbered b |g| + k
   * for the k-th component of the group. Groups may share components (the
   * flow group u, p and the velocity group u). The maps keep the local
   * order, so vectors and rows move between the layouts without
   * communication.
   */
  class InterleavedBlocks
  {
  public:
    InterleavedBlocks(const dealii::IndexSet &owned,
                      const unsigned int      n_components,
                      const std::vector<std::vector<unsigned int>> &groups,
                      const MPI_Comm                                comm);

    unsigned int
    n_groups() const
    {
      return groups.size();
    }
    /// The locally owned unknowns of group @p g in its own numbering.
    const dealii::IndexSet &
    owned(const unsigned int g) const
    {
      return groups[g].owned;
    }
    /// A vector of group @p g (locally owned entries only).
    dealii::TrilinosWrappers::MPI::Vector
    make_vector(const unsigned int g) const;
    /// The entries of group @p g of @p full.
    void
    extract(const dealii::TrilinosWrappers::MPI::Vector &full,
            const unsigned int                           g,
            dealii::TrilinosWrappers::MPI::Vector       &part) const;
    /// Write @p part into the entries of group @p g of @p full.
    void
    insert(const dealii::TrilinosWrappers::MPI::Vector &part,
           const unsigned int                           g,
           dealii::TrilinosWrappers::MPI::Vector       &full) const;
    /// The blocks (rows of group @p row) x (columns of group @p columns[k])
    /// of @p matrix, in one pass over its locally owned rows.
    void
    extract_blocks(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                   const unsigned int                            row,
                   const std::vector<unsigned int>              &columns,
                   const std::vector<dealii::TrilinosWrappers::SparseMatrix *>
                     &blocks) const;
    /// The local positions (in the group's vector) of the unknowns of group
    /// @p g whose monolithic index satisfies @p select.
    std::vector<unsigned int>
    local_positions(
      const unsigned int                                          g,
      const std::function<bool(dealii::types::global_dof_index)> &select) const;

  private:
    struct Group
    {
      /// Position of each component in the group, -1 if not in it.
      std::vector<int> position;
      unsigned int     size;
      dealii::IndexSet owned;
      /// For the k-th entry of the group's local vector: the local index of
      /// the monolithic vector.
      std::vector<unsigned int> full_local;
    };
    const unsigned int     n_components;
    const dealii::IndexSet monolithic_owned;
    const MPI_Comm         comm;
    std::vector<Group>     groups;
  };
} // namespace vesicle_iga
