// kill -9 at any moment (issue 17, item 2). The run is killed (SIGKILL, by
// the test-only fault switch VESICLE_IGA_TEST_FAULT, base/fault_injection.h)
// in the middle of writing its second checkpoint, a row of the time series,
// or its VTU files; then restarted from the checkpoint.h5 it left. The
// restart must continue the same trajectory: the time series equal to
// that of the run made at once to round-off (below 1e-9 relative in every
// entry of every row). The half-written checkpoint.h5.tmp must be refused
// as a restart file. Serial runs of the circle flow and 2-rank runs of the
// cavity (studies.h); the test starts them itself.
//
// Expected output checked by hand: kills show as signal 9; every restart
// reproduces the straight run (the restart tests of willmore/ and flow/
// show the same to round-off); the refusal names the damaged file.

#include <iostream>

#include "restart_check.h"

namespace
{
  std::string
  circle(unsigned int steps, const std::string &dir, const std::string &ts)
  {
    return circle_flow(steps, dir, ts + "set VTU interval = 1\n");
  }

  std::string
  cavity(unsigned int steps, const std::string &dir, const std::string &ts)
  {
    return cavity_flow(steps, dir, ts + "set VTU interval = 1\n");
  }

  void
  kill_and_restart(std::ostream      &out,
                   const Study        study,
                   const unsigned int ranks,
                   const std::string &fault)
  {
    const ProcessResult killed = run_fresh(
      study, ranks, 8, "killed", {"VESICLE_IGA_TEST_FAULT=" + fault});
    // One rank: killed by signal 9; mpirun: exit code 128 + 9.
    out << "  " << fault << ": ended by SIGKILL: "
        << (killed.signal == SIGKILL || killed.exit_code == 128 + SIGKILL ?
              "yes" :
              "no")
        << "; ";
    restart_and_compare(out, study, ranks, 8, "killed");
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
      // The 2nd checkpoint is that of step 4; the 5th row that of step 5;
      // VTU 5 that of step 4 (VTU 1 is the initial state), before its
      // checkpoint: the restarts continue from steps 2, 4 and 2.
      for (const std::string fault :
           {"checkpoint-write:2", "series-write:5", "vtu-write:5"})
        kill_and_restart(out, study, ranks, fault);
    }

  // What a kill in the middle of a checkpoint leaves is never read.
  run_fresh(
    circle, 1, 8, "killed", {"VESICLE_IGA_TEST_FAULT=checkpoint-write:1"});
  const ProcessResult refused = run_process(
    program_command(1,
                    write_prm("restart.prm",
                              circle(8,
                                     "refused",
                                     "set Restart from = "
                                     "killed/checkpoint.h5.tmp\n"))),
    600);
  out << "restart from the half-written killed/checkpoint.h5.tmp: exit code "
      << refused.exit_code << ", message names the damaged file: "
      << contains(refused.output, "truncated or damaged file") << '\n';
}
