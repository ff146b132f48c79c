// Bad numbers in the solution (issue 17, item 5). The test-only fault
// "nan-residual" (base/fault_injection.h) puts a NaN into the last rank's
// part of the residual at a chosen Newton iteration. Once ("nan-residual:10",
// the 10th Newton iteration of the run): the step is rejected and retried
// with a smaller dt, and the run ends normally. From then on ("...:10+"):
// dt is cut down to Min dt, then the run stops with exit code 1, a message
// that says the residual is not finite, and the checkpoint of the last
// accepted step; a restart from it without the fault reproduces the run
// made at once (below 1e-9 relative in every row). Serial (circle flow)
// and on 2 ranks (cavity), started by the test itself.
//
// Expected output checked by hand: the contract above; the failing step's
// number is not printed (the fault counts Newton iterations, whose number
// moves with round-off). The cavity steps at a fixed dt: after the
// rejection its steps run at dt / 4 for 'Increase delay' = 3 steps and then
// at dt again (the rejection falls on step 3 of 8, 2-3 Newton iterations per
// step, so the run ends at dt whichever step it falls on up to step 5).

#include <algorithm>
#include <iostream>

#include "restart_check.h"

namespace
{
  std::string
  circle(unsigned int steps, const std::string &dir, const std::string &ts)
  {
    return circle_flow(steps, dir, ts) + "set Print details = true\n";
  }

  std::string
  cavity(unsigned int steps, const std::string &dir, const std::string &ts)
  {
    return cavity_flow(steps, dir, ts) + "set Print details = true\n";
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  for (const auto &[name, study, ranks] :
       {std::make_tuple("circle flow, 1 rank", Study(circle), 1u),
        std::make_tuple("cavity, 2 ranks", Study(cavity), 2u)})
    {
      out << name << ":\n";
      run_fresh(study, ranks, 8, "straight");

      const ProcessResult once = run_fresh(
        study, ranks, 8, "once", {"VESICLE_IGA_TEST_FAULT=nan-residual:10"});
      out << "  one NaN: exit code " << once.exit_code
          << "; the step was rejected: "
          << contains(once.output, "the residual is not finite")
          << "; steps: " << read_time_series("once/time-series.csv").size()
          << '\n';
      if (ranks == 2)
        {
          // The cavity steps at a fixed dt = 0.01: the retry runs at
          // dt / 4, and after 'Increase delay' = 3 converged steps the
          // step returns to 0.01 (it used to stay at dt / 4 for good).
          const auto   series = read_named_time_series("once/time-series.csv");
          unsigned int short_steps = 0;
          double       smallest    = 1;
          for (unsigned int i = 0; i < series.rows.size(); ++i)
            {
              short_steps += series.value("dt", i) < 0.01 * (1 - 1e-12);
              smallest = std::min(smallest, series.value("dt", i));
            }
          out << "  fixed dt after the rejection: " << short_steps
              << " steps at " << smallest << ", last dt " << series.value("dt")
              << '\n';
        }

      const ProcessResult stopped
        = run_fresh(study,
                    ranks,
                    8,
                    "stopped",
                    {"VESICLE_IGA_TEST_FAULT=nan-residual:10+"});
      out << "  NaN from then on: exit code " << stopped.exit_code
          << "; dt cut to Min dt: "
          << contains(stopped.output, "cannot be cut below Min dt")
          << "; names the NaN: "
          << contains(stopped.output, "the residual is not finite")
          << "; names the checkpoint: "
          << contains(stopped.output,
                      "last accepted state in stopped/checkpoint.h5")
          << '\n';
      out << "  ";
      restart_and_compare(out, study, ranks, 8, "stopped");
    }
}
