#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <memory>
#include <string>

namespace dealii
{
  class TimerOutput;
}

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

    /// The timer of one run: prints its summary on rank 0 at the end when
    /// 'Print details' is on. Its sections time each rank on its own (rank
    /// 0's times are printed): a timer on the communicator would synchronise
    /// in every section's end, so a run that fails on one rank would hang
    /// while unwinding instead of stopping with its error.
    std::unique_ptr<dealii::TimerOutput>
    make_timer() const;
  };
} // namespace vesicle_iga
