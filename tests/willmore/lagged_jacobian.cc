// Newton with a lagged Jacobian ('Newton/Jacobian interval = 3': the
// Jacobian and its multigrid are rebuilt every third correction) converges
// to the same steps as full Newton: the circle of circle_relaxation with a
// fixed dt = 1e-3 for 6 steps. Theory: both iterate to the same residual
// tolerance (relative 1e-8), so the states, hence E_B and the constraint
// errors, agree to that level (checked below 1e-6 relative); a lagged
// Jacobian converges linearly, so it needs at least as many corrections.
// The numbers of corrections are not printed (they are round-off
// sensitive); only the comparisons are.

#include <deal.II/base/mpi.h>

#include <cmath>
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
    = "set Study = willmore-flow\nset Print details = false\n"
      "subsection Willmore flow\nset Semi-axes = 1\nset Center = 0,0\n"
      "subsection Mesh\nset Lower corner = -3.2\nset Upper corner = 3.2\n"
      "set Elements = 32\nend\n"
      "subsection Time stepping\nset Step control = fixed\n"
      "set Initial dt = 1e-3\nset Max steps = 6\nset Checkpoint interval = 0\n"
      "end\n";
  const auto run = [&](const std::string &interval, const std::string &dir) {
    const int code = run_study_quietly(
      common + "subsection Newton\nset Jacobian interval = " + interval
      + "\nend\nend\nset Output directory = " + dir + "\n");
    return std::make_pair(code,
                          read_named_time_series(dir + "/time-series.csv"));
  };
  const auto full   = run("1", "full");
  const auto lagged = run("3", "lagged");
  out << "exit codes " << full.first << ' ' << lagged.first << '\n';
  const auto &a = full.second, &b = lagged.second;
  bool        same             = a.rows.size() == 6 && b.rows.size() == 6;
  double      corrections_full = 0, corrections_lagged = 0;
  for (unsigned int i = 0; same && i < a.rows.size(); ++i)
    {
      same
        = same
          && std::abs(
               a.value("bending_energy", i) / b.value("bending_energy", i) - 1)
               < 1e-6
          && std::abs(a.value("area_error", i) - b.value("area_error", i))
               < 1e-6;
      corrections_full += a.value("newton_iterations", i);
      corrections_lagged += b.value("newton_iterations", i);
    }
  out << "6 steps each, E_B and area errors agree within 1e-6: "
      << (same ? "yes" : "NO") << '\n'
      << "the lagged Jacobian needs at least as many corrections: "
      << (corrections_lagged >= corrections_full ? "yes" : "NO") << '\n';
}
