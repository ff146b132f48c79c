// The rank-0 output of an MPI test: rank 0 writes the test's "output", the
// other ranks write to a sink.
#pragma once

#include <deal.II/base/mpi.h>

#include <fstream>
#include <string>

/// Whether this is rank 0, which writes the test's output.
inline bool
root_rank()
{
  return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
}

/// The test's "output" on rank 0, a sink on the others.
inline std::ofstream
root_output()
{
  return std::ofstream(root_rank() ? "output" : "/dev/null");
}

/// "ok" or "FAILED", the verdict of a check in a test's output.
inline std::string
verdict(const bool ok)
{
  return ok ? "ok" : "FAILED";
}
