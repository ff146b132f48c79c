#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <vesicle_iga/base/run_context.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vesicle_iga
{


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
    std::string                                     name;
    std::string                                     summary;
    std::function<void(dealii::ParameterHandler &)> declare_parameters;
    std::function<std::unique_ptr<Study>(dealii::ParameterHandler &,
                                         RunContext &)>
      create;
  };

  /// The studies this program can run (source/studies/study_list.cc).
  const std::vector<StudyDescription> &
  available_studies();
} // namespace vesicle_iga
