// Restart of the flow study from a checkpoint continues the same
// trajectory: the lid-driven cavity (Re = 100, 16^2, p = 2, pseudo-time
// steps growing by 4) run for 8 steps at once, and the same run stopped
// after 4 steps and restarted from its checkpoint.h5 to step 8, must give
// the same time series (to round-off: the checkpoint stores the velocity,
// the pressure, their generalized-alpha rates, t, the next dt and the step,
// which is the whole state of the step). The test prints both final rows
// and the largest relative difference over all rows of the two
// time-series.csv files (the Krylov counts included).

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
    = "set Study = navier-stokes\n"
      "set Print details = false\n"
      "subsection Navier-Stokes\n"
      "set Reynolds number = 100\n"
      "subsection Mesh\nset Elements = 16\nend\n"
      "subsection Boundary 1\nset Type = strong\n"
      "set Where = x-min; x-max; y-min\nset Velocity = 0; 0\nend\n"
      "subsection Boundary 2\nset Type = weak\nset Where = y-max\n"
      "set Velocity = 1; 0\nend\n"
      "subsection Time stepping\nset Initial dt = 0.1\n"
      "set Max dt = 1e6\nset Step control = growing\nset Growth factor = 4\n"
      "set End time = 1e9\nset Steady tolerance = 0\nset rho_inf = 0.5\n";
  check_restart_equivalence(out, common, "end\nend\n");
}
