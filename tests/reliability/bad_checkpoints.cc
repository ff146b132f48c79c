// Checkpoints that do not fit (issue 17, item 3). A run of the circle flow
// (studies.h) leaves checkpoint.h5 and time-series.csv in "run/"; a flow
// study leaves its checkpoint in "cavity/". Restarts into "run/" from
// checkpoints of another study, dimension, degree and mesh, from a
// truncated file, a file that is not HDF5 and a missing file must each stop
// with exit code 1 and one message naming what does not match, and leave
// run/checkpoint.h5 and run/time-series.csv as they were. The last case, a
// restart that fits, must succeed. Serial and on 2 ranks (rank 0 reads the
// file and every rank agrees on the error).
//
// Expected output checked by hand: each message names the file and the
// entry (dimension 2 vs 3, degree 3 vs 2, 32 vs 16 elements, the missing
// vector of another study, not HDF5, truncated) against the parameters of
// the case.

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <fstream>

#include "../root_output.h"
#include "in_process.h"
#include "studies.h"
#include "subprocess.h"

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root = root_rank();
  std::ofstream                            out  = root_output();

  run_in_process(circle_flow(4, "run"));
  run_in_process(cavity_flow(2, "cavity"));
  if (root)
    {
      const std::string whole = file_content("run/checkpoint.h5");
      std::ofstream("truncated.h5", std::ios::binary)
        << whole.substr(0, whole.size() / 2);
      std::ofstream("text.h5") << "not a checkpoint\n";
    }
  MPI_Barrier(MPI_COMM_WORLD);
  const std::string checkpoint = file_content("run/checkpoint.h5");
  const std::string series     = file_content("run/time-series.csv");

  const auto restart = [](const std::string &file) {
    return "set Restart from = " + file + "\n";
  };
  const std::string three_d
    = "set Dimension = 3\n"
      + circle_flow(6,
                    "run",
                    restart("run/checkpoint.h5"),
                    "subsection Mesh\nset Elements = 16\nend\n"
                    "set Epsilon over h = 1\n")
      + "subsection Willmore flow\nset Center = 0,0,0\nend\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"checkpoint of the flow study",
     circle_flow(6, "run", restart("cavity/checkpoint.h5"))},
    {"other dimension", three_d},
    {"other degree",
     circle_flow(6, "run", restart("run/checkpoint.h5"), "set Degree = 2\n")},
    {"other mesh",
     circle_flow(6,
                 "run",
                 restart("run/checkpoint.h5"),
                 "subsection Mesh\nset Elements = 16\nend\n")},
    {"truncated file", circle_flow(6, "run", restart("truncated.h5"))},
    {"not HDF5", circle_flow(6, "run", restart("text.h5"))},
    {"missing file", circle_flow(6, "run", restart("missing.h5"))}};
  for (const auto &[name, prm] : cases)
    {
      const InProcessRun r = run_in_process(prm);
      out << name << ": exit code " << r.exit_code << "\n  "
          << error_line(r.output)
          << "\n  checkpoint and time series unchanged: "
          << (file_content("run/checkpoint.h5") == checkpoint
                  && file_content("run/time-series.csv") == series ?
                "yes" :
                "no")
          << '\n';
    }
  const InProcessRun fits
    = run_in_process(circle_flow(6, "run", restart("run/checkpoint.h5")));
  out << "a checkpoint that fits: exit code " << fits.exit_code << '\n';
}
