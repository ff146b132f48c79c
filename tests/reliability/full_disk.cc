// Full disk or quota (issue 17, item 6). A run of the circle flow
// (studies.h) writes run/checkpoint.h5 at step 4. Its restart to step 8 is
// then made under a file size limit of 30 kB (setrlimit, as `ulimit -f`
// does; the checkpoint has 42 kB): writing the next checkpoint fails. The
// run must stop with exit code 1 and a message naming the file, and leave
// the previous checkpoint as it was (byte for byte) and no temporary file.
// Without the limit, a restart from that checkpoint reproduces the run made
// at once (below 1e-9 relative in every row). The limit is set in this
// process after MPI has started (Open MPI's own start-up files need more),
// so that the test also runs on 2 ranks.
//
// Expected output checked by hand: the contract above.

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <fstream>
#include <sys/resource.h>

#include "../root_output.h"
#include "../time_series_comparison.h"
#include "in_process.h"
#include "studies.h"
#include "subprocess.h"

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                            out = root_output();

  run_in_process(circle_flow(8, "straight"));
  run_in_process(circle_flow(4, "run"));
  const std::string before  = file_content("run/checkpoint.h5");
  const std::string restart = "set Restart from = run/checkpoint.h5\n";

  rlimit normal;
  getrlimit(RLIMIT_FSIZE, &normal);
  rlimit limited   = normal;
  limited.rlim_cur = 30 * 1024;
  setrlimit(RLIMIT_FSIZE, &limited);
  const InProcessRun full = run_in_process(circle_flow(8, "run", restart));
  setrlimit(RLIMIT_FSIZE, &normal);
  MPI_Barrier(MPI_COMM_WORLD);

  out << "under the limit: exit code " << full.exit_code
      << "\n  message names the checkpoint: "
      << contains(full.output, "cannot write the checkpoint run/checkpoint.h5")
      << "\n  previous checkpoint unchanged: "
      << (file_content("run/checkpoint.h5") == before ? "yes" : "no")
      << "\n  temporary file left: "
      << (std::filesystem::exists("run/checkpoint.h5.tmp") ? "yes" : "no")
      << '\n';
  const InProcessRun again = run_in_process(circle_flow(8, "run", restart));
  out << "without the limit: restart exit code " << again.exit_code << "; ";
  report_restart_equivalence(out,
                             "straight/time-series.csv",
                             "run/time-series.csv");
}
