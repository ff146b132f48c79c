#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vesicle_iga
{
  using namespace dealii;

  /// What every study gets from the program: where to write, how much to
  /// print, the communicator.
  struct RunContext
  {
    MPI_Comm     communicator;
    unsigned int dimension;
    std::string  output_directory;
    /// Print iteration counts and timings (test .prm files turn this off so
    /// that outputs do not depend on the machine or the partition).
    bool               print_details;
    ConditionalOStream pcout;
  };

  /// A study: what one .prm file runs (set Study = <name>).
  class Study
  {
  public:
    virtual ~Study() = default;
    virtual void
    run()
      = 0;
  };

  /// One entry of the list of studies: its .prm name, a one-line summary,
  /// its parameter declarations and its factory.
  struct StudyDescription
  {
    std::string                             name;
    std::string                             summary;
    std::function<void(ParameterHandler &)> declare_parameters;
    std::function<std::unique_ptr<Study>(ParameterHandler &, RunContext &)>
      create;
  };

  /// The studies this program can run (source/studies/study_list.cc).
  const std::vector<StudyDescription> &
  available_studies();
} // namespace vesicle_iga
