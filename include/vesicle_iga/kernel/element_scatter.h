#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace vesicle_iga
{
  /**
   * Adds element matrices and vectors into the global Trilinos objects
   * (doc/performance.md, "The scatter"). An element whose constrained
   * degrees of freedom, if any, are all fixed to zero (every element of
   * a study with homogeneous Dirichlet increments, i.e. nearly every
   * element) takes the direct path: its dofs are translated to the matrix's
   * local row and column numbers once per element (n lookups instead of the n^2
   * of a global insertion), its columns sorted once, and every locally owned
   * row is added by one forward walk through that row of the compressed
   * matrix; a constrained row gets the diagonal AffineConstraints would
   * give it. Rows owned by another rank go through the matrix's insertion,
   * and an element with a dof tied to others (periodicity, hanging
   * constraints) through AffineConstraints::distribute_local_to_global as
   * before. Each global entry receives the same additions in the same
   * order as through the constraints, so the assembled matrix is the same
   * to the last bit.
   *
   * One object serves one assembly pass (it keeps its buffers); it is used
   * from the copier, which WorkStream runs on one thread at a time.
   */
  class ElementScatter
  {
  public:
    /// Either @p matrix or @p vector may be null.
    ElementScatter(const dealii::AffineConstraints<double> &constraints,
                   dealii::TrilinosWrappers::SparseMatrix  *matrix,
                   dealii::TrilinosWrappers::MPI::Vector   *vector);

    /// Adds @p local_matrix (if there is a global matrix) and @p local_vector
    /// (if there is a global vector) of the element with the global dofs
    /// @p indices.
    void
    add(const dealii::FullMatrix<double>                   &local_matrix,
        const dealii::Vector<double>                       &local_vector,
        const std::vector<dealii::types::global_dof_index> &indices);

    /// How many elements took the direct path so far.
    unsigned int
    n_direct_elements() const
    {
      return n_direct;
    }

  private:
    /// The direct path for the matrix; false if it does not apply (a
    /// dof outside the matrix's column map or repeated).
    bool
    add_matrix_directly(
      const dealii::FullMatrix<double>                   &local_matrix,
      const std::vector<dealii::types::global_dof_index> &indices);

    /// Adds row @p i of the element matrix (its unconstrained columns).
    void
    add_row(const dealii::FullMatrix<double>                   &local_matrix,
            const std::vector<dealii::types::global_dof_index> &indices,
            const unsigned int                                  i);

    const dealii::AffineConstraints<double> &constraints;
    dealii::TrilinosWrappers::SparseMatrix  *matrix;
    dealii::TrilinosWrappers::MPI::Vector   *vector;
    /// Whether the matrix is compressed with sorted local column indices,
    /// which the direct path needs.
    bool         direct_matrix;
    unsigned int n_direct = 0;

    std::vector<int> row_lid, column_lid;
    /// The element's unconstrained dofs in the order of their local column
    /// numbers.
    std::vector<unsigned int> column_order;
    std::vector<bool>         constrained;
    /// A row owned by another rank: its columns and values.
    std::vector<dealii::types::global_dof_index> columns_to_add;
    std::vector<double>                          values_to_add;
  };
} // namespace vesicle_iga
