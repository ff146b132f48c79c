// Shared by the restart tests: compare the time-series.csv of a run made
// at once with that of the same run stopped and restarted from its
// checkpoint.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <vesicle_iga/app/program.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

/// Run vesicle-iga on the parameter text @p prm (written to case.prm by
/// rank 0), its terminal output discarded; returns the exit code.
inline int
run_study_quietly(const std::string &prm)
{
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::ofstream("case.prm") << prm;
  MPI_Barrier(MPI_COMM_WORLD);
  std::ostringstream captured;
  auto              *old  = std::cout.rdbuf(captured.rdbuf());
  const int          code = vesicle_iga::run_program({"case.prm"});
  std::cout.rdbuf(old);
  return code;
}


inline std::vector<std::vector<double>>
read_time_series(const std::string &name)
{
  std::ifstream                    f(name);
  std::string                      line;
  std::vector<std::vector<double>> rows;
  std::getline(f, line); // header
  while (std::getline(f, line))
    rows.push_back(dealii::Utilities::string_to_double(
      dealii::Utilities::split_string_list(line, ',')));
  return rows;
}

/// Prints the row counts, both final rows and the largest relative
/// difference over all rows ("below 1e-9" when the restart reproduces the
/// uninterrupted run to round-off).
inline void
report_restart_equivalence(std::ostream      &out,
                           const std::string &straight_file,
                           const std::string &restarted_file)
{
  const auto straight  = read_time_series(straight_file);
  const auto restarted = read_time_series(restarted_file);
  out << "rows: " << straight.size() << " and " << restarted.size() << '\n';
  double diff = 0;
  for (unsigned int i = 0; i < std::min(straight.size(), restarted.size()); ++i)
    for (unsigned int j = 0; j < straight[i].size(); ++j)
      diff = std::max(diff,
                      std::abs(straight[i][j] - restarted[i][j])
                        / (1e-3 + std::abs(straight[i][j])));
  out << "final row, uninterrupted:";
  for (const double x : straight.back())
    out << ' ' << x;
  out << "\nfinal row, restarted:   ";
  for (const double x : restarted.back())
    out << ' ' << x;
  out << "\nlargest relative difference over all rows: "
      << (diff < 1e-9 ? "below 1e-9" : std::to_string(diff)) << '\n';
}
