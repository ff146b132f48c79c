// Adaptive steps of the coupled vesicle-flow system (issue 15, item 6), run
// through the program as a user runs it: one vesicle (R_0 = 0.45,
// chi = 0.84) in [0, 2]^2 of fluid at rest, 32^2 cubic C^2 elements,
// eps = 0.125, Step control = adaptive from dt = 1e-3 (Max dt = 0.02,
// tolerances 1e-4) to T = 0.04. tau_M uses the fixed RBVMS time scale
// (the Initial dt) and the estimate (N5) runs over the phase fields only
// (doc/hydrodynamics.md, "Time steps"). Checks, from time-series.csv:
// - the run reaches T and the controller lets dt grow: the largest dt is
//   at least 4 times the first (6.8 times measured), with at most 3 rejected
//   steps (1 measured). With the estimate over all fields the second step
//   was rejected 8 times and dt fell to 1.5e-6, which fails both;
// - the physics holds at the larger steps: the total energy never rises
//   (no power enters through walls at rest, spec 4.3), |dV/V| < 1e-4
//   (1.3e-5 measured) and |dA/A| < 5e-3 (2.1e-3 measured, the bound
//   (drift rate) 2 dt / eta_phi of the explicit multipliers, see
//   quiescent_vesicle).
// Step counts and last digits are not printed: they move with round-off.

#include <deal.II/base/mpi.h>

#include <vesicle_iga/app/program.h>

#include <algorithm>
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
  const bool                               root = root_rank();
  std::ofstream                            out  = root_output();
  if (root)
    {
      std::ofstream prm("adaptive.prm");
      prm << R"(set Study = vesicle-hydrodynamics
set Dimension = 2
set Output directory = adaptive-results
subsection Vesicle hydrodynamics
  set Vesicles = 1, 1, 0.45, 0.84, 90
  set Epsilon = 0.125
  set Write VTU = false
  set Write membrane samples = false
  subsection Mesh
    set Lower corner = 0, 0
    set Upper corner = 2, 2
    set Elements = 32, 32
  end
  subsection Boundary 1
    set Type = strong
    set Where = all
    set Velocity = 0; 0
  end
  subsection Time stepping
    set Step control = adaptive
    set Initial dt = 1e-3
    set Max dt = 0.02
    set End time = 0.04
    set Checkpoint interval = 0
  end
end
)";
    }
  MPI_Barrier(MPI_COMM_WORLD);
  std::ostringstream captured;
  auto              *old  = std::cout.rdbuf(captured.rdbuf());
  const int          code = vesicle_iga::run_program({"adaptive.prm"});
  std::cout.rdbuf(old);
  out << "exit code " << code << '\n';
  if (!root)
    return 0;

  // The time series by column name.
  const NamedTimeSeries series
    = read_named_time_series("adaptive-results/time-series.csv");
  const auto &rows = series.rows;
  const auto  at   = [&](const std::size_t r, const std::string &name) {
    return series.value(name, r);
  };
  double rejected = 0, worst_area = 0, worst_volume = 0, worst_rise = -1;
  double largest_dt = 0;
  for (std::size_t r = 0; r < rows.size(); ++r)
    {
      rejected += at(r, "rejected_steps");
      largest_dt   = std::max(largest_dt, at(r, "dt"));
      worst_area   = std::max(worst_area, std::abs(at(r, "area_error_1")));
      worst_volume = std::max(worst_volume, std::abs(at(r, "volume_error_1")));
      if (r > 0)
        worst_rise
          = std::max(worst_rise,
                     at(r, "total_energy") - at(r - 1, "total_energy"));
    }
  const std::size_t last = rows.size() - 1;
  const auto verdict     = [](const bool ok) { return ok ? "ok" : "FAILED"; };
  out << "reaches T = 0.04: " << verdict(at(last, "t") > 0.04 - 1e-12) << '\n'
      << "dt grows at least 4-fold: " << verdict(largest_dt >= 4 * at(0, "dt"))
      << '\n'
      << "at most 3 rejected steps: " << verdict(rejected <= 3) << '\n'
      << "total energy never rises: " << verdict(worst_rise <= 0) << '\n'
      << "volume error < 1e-4: " << verdict(worst_volume < 1e-4) << '\n'
      << "area error < 5e-3: " << verdict(worst_area < 5e-3) << '\n';
  std::cout << rows.size() << " steps, largest dt " << largest_dt << ", "
            << rejected << " rejected, dA " << worst_area << " dV "
            << worst_volume << " rise " << worst_rise << std::endl;
}
