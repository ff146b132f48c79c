// What the tests of killed and failed runs share: a study as a function of
// its step count, directory and extra time-stepping lines (studies.h), run
// as a separate process, and the check that a restart from the checkpoint
// a run left continues the trajectory of the run made at once.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "../time_series_comparison.h"
#include "studies.h"
#include "subprocess.h"

using Study = std::string (*)(unsigned int       steps,
                              const std::string &directory,
                              const std::string &time_stepping);

/// Runs @p study for @p steps steps into a new @p directory on @p ranks
/// ranks, with the extra @p environment ("NAME=value").
inline ProcessResult
run_fresh(const Study                     study,
          const unsigned int              ranks,
          const unsigned int              steps,
          const std::string              &directory,
          const std::vector<std::string> &environment = {})
{
  std::filesystem::remove_all(directory);
  return run_process(program_command(ranks,
                                     write_prm(directory + ".prm",
                                               study(steps, directory, ""))),
                     600,
                     environment);
}

/// Restarts @p study from @p directory/checkpoint.h5 to step @p steps and
/// prints its exit code and the comparison of its time series with that
/// of straight/ (the run made at once).
inline void
restart_and_compare(std::ostream      &out,
                    const Study        study,
                    const unsigned int ranks,
                    const unsigned int steps,
                    const std::string &directory)
{
  const ProcessResult restart = run_process(
    program_command(ranks,
                    write_prm("restart.prm",
                              study(steps,
                                    directory,
                                    "set Restart from = " + directory
                                      + "/checkpoint.h5\n"))),
    600);
  out << "restart exit code " << restart.exit_code << "; ";
  report_restart_equivalence(out,
                             "straight/time-series.csv",
                             directory + "/time-series.csv");
}
