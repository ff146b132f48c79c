// Restart of the vesicle-hydrodynamics study from a checkpoint continues
// the same trajectory: two vesicles (interaction on) in a shear flow
// between weakly imposed walls (spec HD4 in small form: [0, 3] x [0, 2],
// 36 x 24 cubic elements, eps = 2 h) run for 8 steps at once, and the same
// run stopped after 4 steps and restarted from its checkpoint.h5 to step 8,
// must give the same time series (to round-off: the checkpoint holds all
// fields with their generalized-alpha rates, t, dt, the step, A_i(0),
// V_i(0) and the global multipliers of (H13), which is the whole state).

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <fstream>

#include "../time_series_comparison.h"

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root
    = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::ofstream     out(root ? "output" : "/dev/null");
  const std::string common
    = "set Study = vesicle-hydrodynamics\n"
      "set Print details = false\n"
      "subsection Vesicle hydrodynamics\n"
      "set Epsilon = 0.17\n"
      "set Vesicles = 1.0, 1.02, 0.4, 0.84, 90; 2.0, 0.98, 0.4, 0.84, 90\n"
      "set Write VTU = false\n"
      "subsection Mesh\nset Lower corner = 0, 0\nset Upper corner = 3, 2\n"
      "set Elements = 36, 24\nend\n"
      "subsection Boundary 1\nset Type = weak\nset Where = y-max\n"
      "set Velocity = 1; 0\nend\n"
      "subsection Boundary 2\nset Type = weak\nset Where = y-min\n"
      "set Velocity = -1; 0\nend\n"
      "subsection Time stepping\nset Initial dt = 2e-3\nset Max dt = 2e-3\n"
      "set End time = 1\n";
  check_restart_equivalence(out, common, "end\nend\n");
}
