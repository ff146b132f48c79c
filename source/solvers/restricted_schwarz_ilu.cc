#include <deal.II/base/exceptions.h>

#include <vesicle_iga/solvers/restricted_schwarz_ilu.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#include <Epetra_Map.h>
#include <Epetra_MultiVector.h>
#include <Epetra_Operator.h>
#include <Ifpack_OverlappingRowMatrix.h>
#include <algorithm>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

namespace vesicle_iga
{
  namespace
  {
    void
    check(const int code, const std::string &what)
    {
      AssertThrow(code == 0,
                  dealii::ExcMessage("RestrictedSchwarzILU: " + what
                                     + " failed with code "
                                     + std::to_string(code) + "."));
    }
  } // namespace


  /**
   * The Epetra operator: the rank's overlapped rows as one local CSR matrix
   * in natural order, factored in place by ILU(0), and the import of the
   * ghost entries of a vector. Only the factors are kept (about the size of
   * the rank's rows plus the overlap); Ifpack's overlapped matrix, local
   * copy and ILU graph held 5x the rank's part of the matrix
   * (doc/performance.md).
   */
  class RestrictedSchwarzILU::Operator : public Epetra_Operator
  {
  public:
    Operator(const Epetra_CrsMatrix              &matrix,
             const unsigned int                   overlap,
             const std::function<dealii::types::global_dof_index(
               dealii::types::global_dof_index)> &natural_index)
      : matrix(matrix)
      , n_own(matrix.NumMyRows())
    {
      AssertThrow(matrix.RowMatrixRowMap().GlobalIndicesInt(),
                  dealii::ExcMessage(
                    "RestrictedSchwarzILU: 32-bit global indices only."));
      std::unique_ptr<Ifpack_OverlappingRowMatrix> overlapped;
      if (overlap > 0 && matrix.Comm().NumProc() > 1)
        overlapped = std::make_unique<Ifpack_OverlappingRowMatrix>(
          Teuchos::rcp(&matrix, false), static_cast<int>(overlap));
      const Epetra_RowMatrix &rows
        = overlapped ? static_cast<const Epetra_RowMatrix &>(*overlapped) :
                       static_cast<const Epetra_RowMatrix &>(matrix);
      const Epetra_Map &row_map = rows.RowMatrixRowMap();
      // Ifpack puts the rank's own rows first, in the matrix's order; the
      // restriction in ApplyInverse relies on it.
      for (int i = 0; i < n_own; ++i)
        AssertThrow(row_map.GID(i) == matrix.RowMap().GID(i),
                    dealii::ExcInternalError());
      sort_rows(row_map, natural_index);
      copy_rows(rows);
      factor();
      if (overlapped)
        {
          overlap_map = std::make_unique<Epetra_Map>(row_map);
          importer
            = std::make_unique<Epetra_Import>(*overlap_map, matrix.RowMap());
        }
    }

    int
    ApplyInverse(const Epetra_MultiVector &X,
                 Epetra_MultiVector       &Y) const override
    {
      const int                 n      = order.size();
      const Epetra_MultiVector *source = &X;
      if (importer)
        {
          if (!overlapped_x || overlapped_x->NumVectors() != X.NumVectors())
            overlapped_x = std::make_unique<Epetra_MultiVector>(*overlap_map,
                                                                X.NumVectors());
          check(overlapped_x->Import(X, *importer, Insert), "Import");
          source = overlapped_x.get();
        }
      work.resize(n);
      for (int v = 0; v < X.NumVectors(); ++v)
        {
          for (int k = 0; k < n; ++k)
            work[k] = (*source)[v][order[k]];
          solve(work);
          // The restriction: only the rank's own rows keep their correction.
          for (int k = 0; k < n; ++k)
            if (order[k] < n_own)
              Y[v][order[k]] = work[k];
        }
      return 0;
    }

    int
    Apply(const Epetra_MultiVector &, Epetra_MultiVector &) const override
    {
      return -1;
    }
    int
    SetUseTranspose(bool) override
    {
      return -1;
    }
    double
    NormInf() const override
    {
      return 0.;
    }
    const char *
    Label() const override
    {
      return "restricted additive Schwarz ILU(0)";
    }
    bool
    UseTranspose() const override
    {
      return false;
    }
    bool
    HasNormInf() const override
    {
      return false;
    }
    const Epetra_Comm &
    Comm() const override
    {
      return matrix.Comm();
    }
    const Epetra_Map &
    OperatorDomainMap() const override
    {
      return matrix.DomainMap();
    }
    const Epetra_Map &
    OperatorRangeMap() const override
    {
      return matrix.RangeMap();
    }

  private:
    /// order[k]: the overlapped row at position k of the natural order.
    void
    sort_rows(const Epetra_Map                    &row_map,
              const std::function<dealii::types::global_dof_index(
                dealii::types::global_dof_index)> &natural_index)
    {
      const int                                    n = row_map.NumMyElements();
      std::vector<dealii::types::global_dof_index> key(n);
      for (int i = 0; i < n; ++i)
        key[i] = natural_index(row_map.GID(i));
      order.resize(n);
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](const int a, const int b) {
        return key[a] < key[b];
      });
    }

    /// The overlapped rows in natural order, without the columns outside
    /// the overlapped set, columns sorted.
    void
    copy_rows(const Epetra_RowMatrix &rows)
    {
      const Epetra_Map &row_map = rows.RowMatrixRowMap();
      const Epetra_Map &col_map = rows.RowMatrixColMap();
      const int         n       = order.size();
      std::vector<int>  position(n);
      for (int k = 0; k < n; ++k)
        position[order[k]] = k;
      std::vector<double>                 values(rows.MaxNumEntries());
      std::vector<int>                    columns(rows.MaxNumEntries());
      std::vector<std::pair<int, double>> row;
      row_start.assign(1, 0);
      diagonal.resize(n);
      // Reserved once (an upper bound: dropped columns only shrink it): grown
      // by push_back, the arrays would peak at 2-3 times their size.
      column.clear();
      value.clear();
      column.reserve(rows.NumMyNonzeros());
      value.reserve(rows.NumMyNonzeros());
      row_start.reserve(n + 1);
      for (int k = 0; k < n; ++k)
        {
          int length = 0;
          check(rows.ExtractMyRowCopy(order[k],
                                      values.size(),
                                      length,
                                      values.data(),
                                      columns.data()),
                "ExtractMyRowCopy");
          row.clear();
          for (int j = 0; j < length; ++j)
            {
              const int r = row_map.LID(col_map.GID(columns[j]));
              if (r >= 0) // columns outside the extended set are dropped
                row.emplace_back(position[r], values[j]);
            }
          std::sort(row.begin(), row.end());
          diagonal[k] = -1;
          for (const auto &[c, v] : row)
            {
              if (c == k)
                diagonal[k] = column.size();
              column.push_back(c);
              value.push_back(v);
            }
          AssertThrow(diagonal[k] >= 0,
                      dealii::ExcMessage("RestrictedSchwarzILU: a matrix row "
                                         "has no diagonal entry."));
          row_start.push_back(column.size());
        }
    }

    /// ILU(0) in place, row by row (the IKJ variant): L unit lower below
    /// the diagonal, U on and above it.
    void
    factor()
    {
      const int        n = order.size();
      std::vector<int> where(n, -1);
      for (int i = 0; i < n; ++i)
        {
          for (int a = row_start[i]; a < row_start[i + 1]; ++a)
            where[column[a]] = a;
          for (int a = row_start[i]; a < diagonal[i]; ++a)
            {
              const int k = column[a];
              value[a] /= value[diagonal[k]];
              const double l = value[a];
              for (int b = diagonal[k] + 1; b < row_start[k + 1]; ++b)
                if (where[column[b]] >= 0)
                  value[where[column[b]]] -= l * value[b];
            }
          AssertThrow(value[diagonal[i]] != 0.,
                      dealii::ExcMessage(
                        "RestrictedSchwarzILU: zero pivot in ILU(0)."));
          for (int a = row_start[i]; a < row_start[i + 1]; ++a)
            where[column[a]] = -1;
        }
    }

    /// x = U^-1 L^-1 x.
    void
    solve(std::vector<double> &x) const
    {
      const int n = order.size();
      for (int i = 0; i < n; ++i)
        {
          double s = x[i];
          for (int a = row_start[i]; a < diagonal[i]; ++a)
            s -= value[a] * x[column[a]];
          x[i] = s;
        }
      for (int i = n - 1; i >= 0; --i)
        {
          double s = x[i];
          for (int a = diagonal[i] + 1; a < row_start[i + 1]; ++a)
            s -= value[a] * x[column[a]];
          x[i] = s / value[diagonal[i]];
        }
    }

    const Epetra_CrsMatrix                     &matrix;
    const int                                   n_own;
    std::vector<int>                            order;
    std::vector<int>                            row_start, column, diagonal;
    std::vector<double>                         value;
    std::unique_ptr<Epetra_Map>                 overlap_map;
    std::unique_ptr<Epetra_Import>              importer;
    mutable std::unique_ptr<Epetra_MultiVector> overlapped_x;
    mutable std::vector<double>                 work;
  };


  void
  RestrictedSchwarzILU::initialize(
    const dealii::TrilinosWrappers::SparseMatrix &matrix,
    const unsigned int                            overlap,
    const std::function<dealii::types::global_dof_index(
      dealii::types::global_dof_index)>          &natural_index)
  {
    preconditioner.reset();
    preconditioner = Teuchos::rcp(
      new Operator(matrix.trilinos_matrix(), overlap, natural_index));
  }
} // namespace vesicle_iga
