#include <deal.II/base/exceptions.h>

#include <vesicle_iga/kernel/element_scatter.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <algorithm>
#include <numeric>

namespace vesicle_iga
{
  using namespace dealii;

  ElementScatter::ElementScatter(const AffineConstraints<double> &constraints,
                                 TrilinosWrappers::SparseMatrix  *matrix,
                                 TrilinosWrappers::MPI::Vector   *vector)
    : constraints(constraints)
    , matrix(matrix)
    , vector(vector)
    , direct_matrix(false)
  {
    if (matrix)
      {
        // Epetra sorts the column indices of every row when it compresses
        // a matrix; the walk in add_matrix_directly() relies on it, so it is
        // checked (O(non-zeros), once per assembly pass).
        const Epetra_CrsMatrix &A = matrix->trilinos_matrix();
        direct_matrix             = A.Filled() && A.IndicesAreLocal();
        for (int r = 0; r < A.NumMyRows() && direct_matrix; ++r)
          {
            int     length;
            double *values;
            int    *columns;
            A.ExtractMyRowView(r, length, values, columns);
            direct_matrix = std::is_sorted(columns, columns + length);
          }
      }
  }


  void
  ElementScatter::add(const FullMatrix<double>                   &local_matrix,
                      const Vector<double>                       &local_vector,
                      const std::vector<types::global_dof_index> &indices)
  {
    // The direct path only for elements whose constrained dofs, if any,
    // are fixed to zero (an empty constraint line without inhomogeneity:
    // their rows and columns are dropped and their diagonal set, nothing
    // is distributed to other dofs).
    bool plain = matrix && direct_matrix;
    constrained.resize(indices.size());
    for (unsigned int i = 0; i < indices.size() && plain; ++i)
      {
        const auto *line = constraints.get_constraint_entries(indices[i]);
        constrained[i]   = line != nullptr;
        plain            = !line
                || (line->empty()
                    && !constraints.is_inhomogeneously_constrained(indices[i]));
      }
    if (plain && add_matrix_directly(local_matrix, indices))
      {
        ++n_direct;
        if (vector)
          constraints.distribute_local_to_global(local_vector,
                                                 indices,
                                                 *vector);
      }
    else if (matrix && vector)
      constraints.distribute_local_to_global(
        local_matrix, local_vector, indices, *matrix, *vector);
    else if (matrix)
      constraints.distribute_local_to_global(local_matrix, indices, *matrix);
    else if (vector)
      constraints.distribute_local_to_global(local_vector, indices, *vector);
  }


  bool
  ElementScatter::add_matrix_directly(
    const FullMatrix<double>                   &local_matrix,
    const std::vector<types::global_dof_index> &indices)
  {
    using int_type               = TrilinosWrappers::types::int_type;
    const Epetra_CrsMatrix &A    = matrix->trilinos_matrix();
    const Epetra_Map       &rows = A.RowMap(), &columns = A.ColMap();
    const unsigned int      n = indices.size();
    row_lid.resize(n);
    column_lid.resize(n);
    column_order.clear();
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto g  = static_cast<int_type>(indices[i]);
        row_lid[i]    = rows.LID(g);
        column_lid[i] = columns.LID(g);
        if (column_lid[i] < 0)
          return false;
        if (!constrained[i])
          column_order.push_back(i);
      }
    // The columns in the order of the matrix's local column numbers, so
    // that one forward walk through a row finds them all. A dof twice in
    // the element goes the general way (deal.II sums repeated rows first).
    std::sort(column_order.begin(),
              column_order.end(),
              [&](const unsigned int a, const unsigned int b) {
                return column_lid[a] < column_lid[b];
              });
    for (unsigned int k = 1; k < column_order.size(); ++k)
      if (column_lid[column_order[k]] == column_lid[column_order[k - 1]])
        return false;

    for (unsigned int i = 0; i < n; ++i)
      if (!constrained[i])
        add_row(local_matrix, indices, i);

    if (column_order.size() == n)
      return true; // nothing constrained: no diagonal to set

    // The diagonal of a constrained row, as AffineConstraints sets it: the
    // element's own diagonal entry, or the mean absolute diagonal.
    double mean_diagonal = 0;
    for (unsigned int i = 0; i < n; ++i)
      mean_diagonal += std::abs(local_matrix(i, i));
    mean_diagonal /= n;
    if (mean_diagonal == 0.)
      {
        mean_diagonal = local_matrix.l1_norm() / n;
        if (mean_diagonal == 0.)
          mean_diagonal = 1.;
      }
    for (unsigned int i = 0; i < n; ++i)
      if (constrained[i])
        {
          const double diagonal = local_matrix(i, i) != 0. ?
                                    std::abs(local_matrix(i, i)) :
                                    mean_diagonal;
          matrix->add(indices[i], indices[i], diagonal);
        }
    return true;
  }


  void
  ElementScatter::add_row(const FullMatrix<double> &local_matrix,
                          const std::vector<types::global_dof_index> &indices,
                          const unsigned int                          i)
  {
    const double *local_row = &local_matrix(i, 0);
    if (row_lid[i] < 0)
      {
        // A row another rank owns: through the matrix's own insertion, with
        // the values deal.II's constraints would give it (zeros left out).
        columns_to_add.clear();
        values_to_add.clear();
        for (const unsigned int j : column_order)
          if (local_row[j] != 0.)
            {
              columns_to_add.push_back(indices[j]);
              values_to_add.push_back(local_row[j]);
            }
        if (!columns_to_add.empty())
          matrix->add(indices[i],
                      columns_to_add.size(),
                      columns_to_add.data(),
                      values_to_add.data(),
                      false,
                      false);
        return;
      }
    int     length;
    double *values;
    int    *columns_of_row;
    matrix->trilinos_matrix().ExtractMyRowView(row_lid[i],
                                               length,
                                               values,
                                               columns_of_row);
    // The element's columns come in runs of consecutive local numbers
    // (consecutive dofs along direction 0), which are consecutive in the
    // row too: a run costs one binary search from where the last one ended.
    int *const end      = columns_of_row + length;
    int        position = 0;
    for (const unsigned int j : column_order)
      {
        if (position >= length || columns_of_row[position] != column_lid[j])
          position
            = std::lower_bound(columns_of_row + position, end, column_lid[j])
              - columns_of_row;
        AssertThrow(position < length
                      && columns_of_row[position] == column_lid[j],
                    ExcMessage("An element couples two degrees of freedom "
                               "that the sparsity pattern of the matrix "
                               "does not hold."));
        // deal.II's constraints leave zeros out too.
        if (local_row[j] != 0.)
          values[position] += local_row[j];
        ++position;
      }
  }
} // namespace vesicle_iga
