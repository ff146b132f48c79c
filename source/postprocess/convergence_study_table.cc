#include <vesicle_iga/io/checked_output.h>
#include <vesicle_iga/postprocess/convergence_study_table.h>

#include <cmath>
#include <fstream>
#include <iomanip>

namespace vesicle_iga
{
  using namespace dealii;

  ConvergenceStudyTable::ConvergenceStudyTable(
    const unsigned int              dim,
    const std::vector<std::string> &norm_names)
    : dim(dim)
    , norms(norm_names)
  {}


  void
  ConvergenceStudyTable::add_row(const unsigned int         degree,
                                 const unsigned int         cells,
                                 const unsigned long long   dofs,
                                 const double               h,
                                 const std::vector<double> &errors)
  {
    rows.push_back({degree, cells, dofs, h, errors});
  }


  void
  ConvergenceStudyTable::print(std::ostream &out) const
  {
    std::vector<unsigned int> degrees;
    for (const auto &r : rows)
      if (degrees.empty() || degrees.back() != r.degree)
        degrees.push_back(r.degree);
    for (const unsigned int p : degrees)
      {
        ConvergenceTable table;
        for (const auto &r : rows)
          if (r.degree == p)
            {
              table.add_value("cells", r.cells);
              table.add_value("dofs", r.dofs);
              table.add_value("h", r.h);
              for (unsigned int i = 0; i < norms.size(); ++i)
                table.add_value(norms[i], r.errors[i]);
            }
        table.set_scientific("h", true);
        table.set_precision("h", 3);
        for (const auto &n : norms)
          {
            table.set_scientific(n, true);
            table.set_precision(n, 3);
            table.evaluate_convergence_rates(
              n, "cells", ConvergenceTable::reduction_rate_log2, dim);
          }
        out << "degree p = " << p << std::endl;
        table.write_text(out, TableHandler::org_mode_table);
      }
  }


  void
  ConvergenceStudyTable::write_csv(const std::string &filename) const
  {
    std::ofstream f(filename);
    f << "degree,cells,dofs,h";
    for (const auto &n : norms)
      f << ',' << n;
    f << '\n' << std::setprecision(10);
    for (const auto &r : rows)
      {
        f << r.degree << ',' << r.cells << ',' << r.dofs << ',' << r.h;
        for (const double e : r.errors)
          f << ',' << e;
        f << '\n';
      }
    check_written(f, filename);
  }


  void
  ConvergenceStudyTable::report(const ConditionalOStream &out,
                                const MPI_Comm            comm,
                                const std::string        &directory) const
  {
    if (out.is_active())
      print(out.get_stream());
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      write_csv(directory + "/convergence.csv");
  }
} // namespace vesicle_iga
