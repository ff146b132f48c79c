// Restart of the vesicle-hydrodynamics study from a checkpoint continues
// the same trajectory: two vesicles (interaction on) in a shear flow
// between weakly imposed walls (spec HD4 in small form: [0, 3] x [0, 2],
// 36 x 24 cubic elements, eps = 2 h) run for 8 steps at once, and the same
// run stopped after 4 steps and restarted from its checkpoint.h5 to step 8,
// must give the same time series (to round-off: the checkpoint holds all
// fields with their generalized-alpha rates, t, dt, the step, A_i(0),
// V_i(0) and the global multipliers of (H13), which is the whole state).
// The restart comparison builds the preconditioner for every Jacobian: a
// preconditioner kept across steps (the study's default) is rebuilt by a
// restart, which changes the Krylov iterates within the solver tolerance.
// The study's Jacobian, kept across corrections and steps ('Jacobian
// interval = 2', 'Keep Jacobian = true'), is dropped by every checkpoint,
// so both runs write one at step 4: the straight run continues from there
// with a fresh Jacobian as the restarted one does (without the checkpoint
// at step 4 the straight run's step 5 starts with step 4's Jacobian and
// the two differ within the Newton tolerance: the Krylov counts of steps
// 5-8 by 1-2, the multipliers lambda_g, lambda_v by 6e-6 relative).
//
// Second part: the study's default 'Preconditioner reuse = across-steps'
// gives the trajectory of 'every-matrix' to the solver tolerance (Newton
// and FGMRES to 1e-8 relative): every column but the iteration counts
// agrees to 1e-6 relative (measured 2.9e-8, in lambda_g_2). Measured on
// this set-up with 'Print details' (one rank): the preconditioner is built
// 2 times instead of 18 in 8 steps (FGMRES 404 iterations in all against
// 359), and the run takes 10.0 s instead of 18.6 s.
//
// Third part: a checkpoint records which volume its V_i(0) are (int phi_i,
// or int chi(phi_i) of 'Volume multiplier = indicator'); a restart with the
// other kind would hold V_i(0) of the wrong functional, so it must stop
// with exit code 1 and a message naming 'Restart from' and the kind.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

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
      "set End time = 1\nset Checkpoint interval = 4\n";
  const std::string every_matrix
    = "subsection Linear solver\nset Preconditioner reuse = every-matrix\n"
      "end\n";
  check_restart_equivalence(out, common, "end\n" + every_matrix + "end\n");

  const auto run = [&](const std::string &reuse, const std::string &dir) {
    return run_study_quietly(common + "set Max steps = 8\nend\n"
                             + "subsection Linear solver\n"
                               "set Preconditioner reuse = "
                             + reuse + "\nend\nend\nset Output directory = "
                             + dir + "\n");
  };
  out << "across-steps: exit code " << run("across-steps", "reused") << '\n';
  const auto reused    = read_named_time_series("reused/time-series.csv");
  const auto reference = read_named_time_series("straight/time-series.csv");
  double     diff      = 0;
  for (unsigned int i = 0; i < reused.rows.size(); ++i)
    for (unsigned int j = 0; j < reused.columns.size(); ++j)
      if (reused.columns[j].find("iterations") == std::string::npos)
        diff = std::max(diff,
                        std::abs(reused.rows[i][j] - reference.rows[i][j])
                          / (1e-3 + std::abs(reference.rows[i][j])));
  out << "rows: " << reused.rows.size()
      << "; every column but the iteration counts equals every-matrix to "
      << (diff < 1e-6 ? "1e-6" : std::to_string(diff)) << '\n';

  std::ostringstream errors;
  auto              *old_cerr = std::cerr.rdbuf(errors.rdbuf());
  const int          code     = run_study_quietly(
    common
    + "set Max steps = 8\nset Restart from = restarted/checkpoint.h5\nend\n"
                   "set Volume multiplier = membrane\nend\n"
                   "set Output directory = membrane\n");
  std::cerr.rdbuf(old_cerr);
  std::string first_line;
  std::getline(std::istringstream(errors.str()) >> std::ws, first_line);
  out << "restart with 'Volume multiplier = membrane' from a checkpoint of "
         "'indicator' (the default): exit code "
      << code << "\n  " << first_line << '\n';
}
