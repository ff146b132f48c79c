#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <string>

namespace vesicle_iga
{
  /// What every study and the time loop get from the program: where to
  /// write, how much to print, the communicator.
  struct RunContext
  {
    MPI_Comm     communicator;
    unsigned int dimension;
    std::string  output_directory;
    /// Print iteration counts and timings (test .prm files turn this off so
    /// that outputs do not depend on the machine or the partition).
    bool                       print_details;
    dealii::ConditionalOStream pcout;
  };
} // namespace vesicle_iga
