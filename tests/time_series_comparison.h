// Shared by the tests that run whole studies: run vesicle-iga on a
// parameter text, read a time-series.csv, and (restart tests) compare the
// time series of a run made at once with that of the same run stopped and
// restarted from its checkpoint.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <vesicle_iga/app/program.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "root_output.h"

struct StudyRun
{
  int         exit_code;
  std::string log; ///< what the program printed (rank 0)

  /// The first printed line that starts with @p start, or "".
  std::string
  line_starting_with(const std::string &start) const
  {
    std::istringstream lines(log);
    for (std::string line; std::getline(lines, line);)
      if (line.rfind(start, 0) == 0)
        return line;
    return "";
  }
};

/// Run vesicle-iga on the parameter text @p prm (written to case.prm by
/// rank 0) and capture what it prints.
inline StudyRun
run_study(const std::string &prm)
{
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::ofstream("case.prm") << prm;
  MPI_Barrier(MPI_COMM_WORLD);
  std::ostringstream captured;
  auto              *old  = std::cout.rdbuf(captured.rdbuf());
  const int          code = vesicle_iga::run_program({"case.prm"});
  std::cout.rdbuf(old);
  return {code, captured.str()};
}

/// As run_study, its terminal output discarded; returns the exit code.
inline int
run_study_quietly(const std::string &prm)
{
  return run_study(prm).exit_code;
}


/// A time-series.csv with its column names.
struct NamedTimeSeries
{
  std::vector<std::string>         columns;
  std::vector<std::vector<double>> rows;

  /// Column @p name of row @p i (the last row by default); NaN if absent.
  double
  value(const std::string &name, const int i = -1) const
  {
    for (unsigned int j = 0; j < columns.size(); ++j)
      if (columns[j] == name && !rows.empty())
        return rows[i < 0 ? rows.size() - 1 : i][j];
    return std::nan("");
  }
};

inline NamedTimeSeries
read_named_time_series(const std::string &name)
{
  std::ifstream   f(name);
  std::string     line;
  NamedTimeSeries s;
  std::getline(f, line);
  s.columns = dealii::Utilities::split_string_list(line, ',');
  while (std::getline(f, line))
    s.rows.push_back(dealii::Utilities::string_to_double(
      dealii::Utilities::split_string_list(line, ',')));
  return s;
}


inline std::vector<std::vector<double>>
read_time_series(const std::string &name)
{
  return read_named_time_series(name).rows;
}

/// Prints whether both series have the same rows and the largest relative
/// difference over all of them ("below 1e-9" when the restart reproduces
/// the uninterrupted run to round-off). The rows themselves are not printed:
/// step sizes and iteration counts move with round-off from CPU to CPU.
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
  out << "largest relative difference over all rows: "
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
