// Runs the program in this process (so that the test can run on several
// ranks under mpirun) and captures what rank 0 prints to stdout and stderr.
#pragma once

#include <deal.II/base/mpi.h>

#include <vesicle_iga/app/program.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

struct InProcessRun
{
  int         exit_code;
  std::string output;
};

inline InProcessRun
run_in_process(const std::string &prm)
{
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::ofstream("case.prm") << prm;
  MPI_Barrier(MPI_COMM_WORLD);
  std::ostringstream captured;
  auto              *old_out = std::cout.rdbuf(captured.rdbuf());
  auto              *old_err = std::cerr.rdbuf(captured.rdbuf());
  const int          code    = vesicle_iga::run_program({"case.prm"});
  std::cout.rdbuf(old_out);
  std::cerr.rdbuf(old_err);
  return {code, captured.str()};
}

/// The line of @p text that contains "error", without the program's
/// prefix; "" if none.
inline std::string
error_line(const std::string &text)
{
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    {
      const auto pos = line.find("vesicle-iga: error: ");
      if (pos != std::string::npos)
        return line.substr(pos + 20);
    }
  return "";
}
