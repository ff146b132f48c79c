// One rank fails, all stop (issue 17, item 4). In a 2-rank run of the
// cavity (studies.h), rank 1 alone throws after its 3rd step (test-only
// fault "rank-1-throws"), while rank 0 goes on into the next collective.
// The job must end within seconds (program.cc: the failed rank waits 5 s
// for the others to join the error, then ends the job) with the message of
// the rank that failed, never hang: the test allows 120 s. The test starts
// the job itself (serial test, 2-rank job).
//
// Expected output checked by hand: the contract above.

#include <iostream>

#include "studies.h"
#include "subprocess.h"

int
main()
{
  std::ofstream       out("output");
  const auto          start = std::chrono::steady_clock::now();
  const ProcessResult r     = run_process(
    program_command(2, write_prm("case.prm", cavity_flow(100, "run"))),
    120,
    {"VESICLE_IGA_TEST_FAULT=rank-1-throws:3"});
  const double seconds
    = std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
  out << "ended before the 120 s limit: " << (r.timed_out ? "no" : "yes")
      << "\nexit code non-zero: " << (r.exit_code != 0 ? "yes" : "no")
      << "\nmessage of rank 1: " << contains(r.output, "error on rank 1") << ' '
      << contains(r.output, "test fault: rank 1 fails after step 3")
      << "\nended within 60 s: " << (seconds < 60 ? "yes" : "no") << '\n';
}
