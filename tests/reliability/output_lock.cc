// Two runs, one output directory (issue 17, item 9). While a run of the
// cavity (studies.h) is going, a second run into the same directory must
// refuse to start (exit code 1) and name the first's host and pid. After
// the first has ended (by SIGTERM, with its checkpoint), its restart into
// the same directory starts. A lock left by a run killed with SIGKILL
// (same host, no such process) is taken over by the next run. The test
// starts the runs itself (serial runs).
//
// Expected output checked by hand: the contract above.

#include <iostream>
#include <unistd.h>

#include "studies.h"
#include "subprocess.h"

namespace
{
  /// Starts the cavity into run/ for many steps and waits for 3 rows.
  pid_t
  start_long_run()
  {
    const pid_t pid = start_process(
      program_command(1, write_prm("first.prm", cavity_flow(100000, "run"))),
      "first.log");
    const auto start = std::chrono::steady_clock::now();
    while (count_lines("run/time-series.csv") < 4
           && std::chrono::steady_clock::now() - start
                < std::chrono::seconds(300))
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return pid;
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  std::filesystem::remove_all("run");
  const pid_t first = start_long_run();

  const ProcessResult second = run_process(
    program_command(1, write_prm("second.prm", cavity_flow(4, "run"))), 120);
  char host[256] = {};
  gethostname(host, sizeof(host) - 1);
  out << "second run while the first runs: exit code " << second.exit_code
      << "; names the first's host and pid: "
      << contains(second.output,
                  "the run of process " + std::to_string(first) + " on host "
                    + host)
      << '\n';

  kill(first, SIGTERM);
  const ProcessResult ended   = wait_process(first, 300, "first.log");
  const auto          steps   = count_lines("run/time-series.csv") - 1;
  const ProcessResult resumed = run_process(
    program_command(1,
                    write_prm("resume.prm",
                              cavity_flow(steps + 2,
                                          "run",
                                          "set Restart from = "
                                          "run/checkpoint.h5\n"))),
    120);
  out << "first ended by SIGTERM: exit code " << ended.exit_code
      << "; its restart into the same directory: exit code "
      << resumed.exit_code << '\n';

  std::filesystem::remove_all("run");
  const pid_t again = start_long_run();
  kill(again, SIGKILL);
  wait_process(again, 60, "first.log");
  out << "lock left by a killed run: "
      << (std::filesystem::exists("run/.vesicle-iga.lock") ? "yes" : "no");
  const ProcessResult after_kill = run_process(
    program_command(1, write_prm("after.prm", cavity_flow(2, "run"))), 120);
  out << "; next run takes it over: exit code " << after_kill.exit_code << '\n';
}
