#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/mpi.h>

#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace vesicle_iga
{

  /**
   * Error norms of a sequence of refinements for several degrees: printed
   * per degree as a deal.II ConvergenceTable with rates log2(e_{r-1}/e_r)
   * per halving of h (computed against the number of cells, which grows by
   * 2^dim per uniform refinement), and written as one CSV file with the
   * columns degree, cells, dofs, h, <norms...>.
   */
  class ConvergenceStudyTable
  {
  public:
    ConvergenceStudyTable(const unsigned int              dim,
                          const std::vector<std::string> &norm_names);

    void
    add_row(const unsigned int         degree,
            const unsigned int         cells,
            const unsigned long long   dofs,
            const double               h,
            const std::vector<double> &errors);

    void
    print(std::ostream &out) const;
    void
    write_csv(const std::string &filename) const;
    /// What every convergence study ends with: the table on @p out if it is
    /// active, directory/convergence.csv written by rank 0 of @p comm.
    void
    report(const dealii::ConditionalOStream &out,
           const MPI_Comm                    comm,
           const std::string                &directory) const;


  private:
    struct Row
    {
      unsigned int        degree, cells;
      unsigned long long  dofs;
      double              h;
      std::vector<double> errors;
    };
    unsigned int             dim;
    std::vector<std::string> norms;
    std::vector<Row>         rows;
  };
} // namespace vesicle_iga
