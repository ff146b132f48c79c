#pragma once

#include <stdexcept>
#include <string>

namespace vesicle_iga
{
  /**
   * What schedulers and users send before they kill a run: SIGTERM (the
   * wall-time limit), SIGINT (Ctrl-C), SIGUSR1 (Slurm's --signal). While an
   * InterruptHandler exists (the time loop holds one), the first of them
   * only sets a flag: the time loop finishes the step it is in, writes the
   * checkpoint and the time series, says where it stopped and ends the
   * program with exit code 3. A second signal ends the process at once
   * (exit code 128 + signal). Outside the time loop the signals keep their
   * default meaning.
   */
  class InterruptHandler
  {
  public:
    InterruptHandler();
    ~InterruptHandler();
    InterruptHandler(const InterruptHandler &) = delete;
    InterruptHandler &
    operator=(const InterruptHandler &)
      = delete;

    /// The signal received, or 0.
    static int
    signal_received();
    /// "SIGTERM", ...
    static std::string
    name(const int signal);
  };


  /// A run that stopped on a signal after saving its state (exit code 3).
  class RunInterrupted : public std::runtime_error
  {
  public:
    explicit RunInterrupted(const std::string &what)
      : std::runtime_error(what)
    {}
  };
} // namespace vesicle_iga
