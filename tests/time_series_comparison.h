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


/// The restart check of both restart tests: @p common (a study's
/// parameters with its time-stepping subsection left open) run for 8 steps
/// into straight/, for 4 steps into restarted/ and then restarted from
/// restarted/checkpoint.h5 to step 8; prints the exit codes and the
/// comparison of the two time series. @p close ends the open subsections.
inline void
check_restart_equivalence(std::ostream      &out,
                          const std::string &common,
                          const std::string &close)
{
  const auto run = [&](const std::string &steps, const std::string &dir) {
    return run_study_quietly(common + steps + close
                             + "set Output directory = " + dir + "\n");
  };
  const int a = run("set Max steps = 8\n", "straight");
  const int b = run("set Max steps = 4\n", "restarted");
  const int c
    = run("set Max steps = 8\nset Restart from = restarted/checkpoint.h5\n",
          "restarted");
  out << "exit codes " << a << ' ' << b << ' ' << c << '\n';
  report_restart_equivalence(out,
                             "straight/time-series.csv",
                             "restarted/time-series.csv");
}
