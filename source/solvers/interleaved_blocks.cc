// Groups of components of an interleaved monolithic system: vectors and
// matrix blocks of their own. See the header.

#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vesicle_iga/solvers/interleaved_blocks.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>

namespace vesicle_iga
{
  using namespace dealii;

  void
  for_each_row_entry(
    const TrilinosWrappers::SparseMatrix                       &matrix,
    const types::global_dof_index                               row,
    const std::function<void(types::global_dof_index, double)> &f)
  {
    const Epetra_CrsMatrix &m = matrix.trilinos_matrix();
    int                     n = 0;
    double                 *values;
    int                    *columns;
    m.ExtractMyRowView(m.LRID(
                         static_cast<TrilinosWrappers::types::int_type>(row)),
                       n,
                       values,
                       columns);
    for (int k = 0; k < n; ++k)
      f(types::global_dof_index(
          TrilinosWrappers::global_column_index(m, columns[k])),
        values[k]);
  }


  void
  make_distributed_matrix(const IndexSet                 &row_set,
                          const IndexSet                 &column_set,
                          const MPI_Comm                  comm,
                          std::vector<MatrixRow>         &rows,
                          TrilinosWrappers::SparseMatrix &matrix)
  {
    TrilinosWrappers::SparsityPattern    sparsity(row_set, column_set, comm);
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  values;
    for (std::size_t k = 0; k < rows.size(); ++k)
      {
        // Sort and sum repeated columns.
        MatrixRow &row = rows[k];
        std::sort(row.begin(), row.end());
        std::size_t n = 0;
        for (std::size_t e = 0; e < row.size(); ++e)
          if (n > 0 && row[n - 1].first == row[e].first)
            row[n - 1].second += row[e].second;
          else
            row[n++] = row[e];
        row.resize(n);
        columns.clear();
        for (const auto &entry : row)
          columns.push_back(entry.first);
        sparsity.add_entries(row_set.nth_index_in_set(k),
                             columns.begin(),
                             columns.end());
      }
    sparsity.compress();
    matrix.reinit(sparsity);
    for (std::size_t k = 0; k < rows.size(); ++k)
      {
        columns.clear();
        values.clear();
        for (const auto &entry : rows[k])
          {
            columns.push_back(entry.first);
            values.push_back(entry.second);
          }
        if (!columns.empty())
          matrix.set(row_set.nth_index_in_set(k),
                     columns.size(),
                     columns.data(),
                     values.data());
      }
    matrix.compress(VectorOperation::insert);
  }


  InterleavedBlocks::InterleavedBlocks(
    const IndexSet                               &owned,
    const unsigned int                            n_components,
    const std::vector<std::vector<unsigned int>> &group_components,
    const MPI_Comm                                comm)
    : n_components(n_components)
    , monolithic_owned(owned)
    , comm(comm)
  {
    const types::global_dof_index n_basis = owned.size() / n_components;
    for (const auto &components : group_components)
      {
        Group g;
        g.position.assign(n_components, -1);
        g.size = components.size();
        for (unsigned int k = 0; k < components.size(); ++k)
          g.position[components[k]] = k;
        g.owned            = IndexSet(n_basis * g.size);
        unsigned int local = 0;
        for (const auto i : owned)
          {
            const int k = g.position[i % n_components];
            if (k >= 0)
              {
                g.owned.add_index(i / n_components * g.size + k);
                g.full_local.push_back(local);
              }
            ++local;
          }
        g.owned.compress();
        groups.push_back(std::move(g));
      }
  }


  TrilinosWrappers::MPI::Vector
  InterleavedBlocks::make_vector(const unsigned int g) const
  {
    return TrilinosWrappers::MPI::Vector(groups[g].owned, comm);
  }


  void
  InterleavedBlocks::extract(const TrilinosWrappers::MPI::Vector &full,
                             const unsigned int                   g,
                             TrilinosWrappers::MPI::Vector       &part) const
  {
    const auto &map = groups[g].full_local;
    const auto *f   = full.begin();
    auto       *p   = part.begin();
    for (std::size_t k = 0; k < map.size(); ++k)
      p[k] = f[map[k]];
  }


  void
  InterleavedBlocks::insert(const TrilinosWrappers::MPI::Vector &part,
                            const unsigned int                   g,
                            TrilinosWrappers::MPI::Vector       &full) const
  {
    const auto &map = groups[g].full_local;
    auto       *f   = full.begin();
    const auto *p   = part.begin();
    for (std::size_t k = 0; k < map.size(); ++k)
      f[map[k]] = p[k];
  }


  void
  InterleavedBlocks::extract_blocks(
    const TrilinosWrappers::SparseMatrix                &matrix,
    const unsigned int                                   row,
    const std::vector<unsigned int>                     &columns,
    const std::vector<TrilinosWrappers::SparseMatrix *> &blocks) const
  {
    AssertDimension(columns.size(), blocks.size());
    const Group                        &r = groups[row];
    std::vector<std::vector<MatrixRow>> rows(
      columns.size(), std::vector<MatrixRow>(r.full_local.size()));
    for (std::size_t k = 0; k < r.full_local.size(); ++k)
      for_each_row_entry(
        matrix,
        monolithic_owned.nth_index_in_set(r.full_local[k]),
        [&](const types::global_dof_index j, const double value) {
          const auto b = j / n_components;
          const auto c = j % n_components;
          for (std::size_t m = 0; m < columns.size(); ++m)
            {
              const Group &g = groups[columns[m]];
              if (g.position[c] >= 0)
                rows[m][k].emplace_back(b * g.size + g.position[c], value);
            }
        });
    for (std::size_t m = 0; m < columns.size(); ++m)
      make_distributed_matrix(
        r.owned, groups[columns[m]].owned, comm, rows[m], *blocks[m]);
  }


  std::vector<unsigned int>
  InterleavedBlocks::local_positions(
    const unsigned int                                  g,
    const std::function<bool(types::global_dof_index)> &select) const
  {
    std::vector<unsigned int> positions;
    const auto               &map = groups[g].full_local;
    for (std::size_t k = 0; k < map.size(); ++k)
      if (select(monolithic_owned.nth_index_in_set(map[k])))
        positions.push_back(k);
    return positions;
  }
} // namespace vesicle_iga
