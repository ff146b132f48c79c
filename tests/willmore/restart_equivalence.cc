// Restart from a checkpoint continues the same trajectory: a circle flow of
// 8 steps run at once, and the same flow stopped after 4 steps and
// restarted from its checkpoint.h5 to step 8, must give the same time
// series (to round-off: the checkpoint stores every piece of state, the
// three phase-field levels, dt and the controller's filter, the ALM
// targets and secant matrix). The test prints both final rows and the
// largest difference over all rows of the two time-series.csv files.

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "../root_output.h"
#include "../time_series_comparison.h"

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                            out = root_output();
  const std::string                        common
    = "set Study = willmore-flow\n"
      "set Print details = false\n"
      "subsection Willmore flow\n"
      "set Semi-axes = 1\nset Center = 0,0\n"
      "subsection Linear solver\nset Method = direct\nend\n"
      "subsection Mesh\nset Lower corner = -3.2\n"
      "set Upper corner = 3.2\nset Elements = 32\nend\n"
      "subsection Time stepping\nset End time = 10\n"
      "set Initial dt = 1e-3\nset Max dt = 0.05\n";
  check_restart_equivalence(out, common, "end\nend\n");
}
