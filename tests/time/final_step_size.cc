// The last steps before End time (time/time_loop.h, final_step_size): the
// loop never takes a sliver of a step. Checked from the rule itself:
// - a remainder at most dt ends the run in one step, also when the
//   accumulated time leaves it a round-off above dt (fixed steps that
//   divide the interval: 2000 steps of 1e-3 summed to t, then T - t);
// - a remainder between dt and 2 dt is split into two equal steps, so no
//   step is below half its predecessor (a remainder of 1.01 dt: two of
//   0.505 dt, where min(dt, remainder) gave dt and then 0.01 dt);
// - a remainder of 2 dt or more takes dt unchanged.
// Why it matters: (H13) divides its relaxation terms by the step, and a
// last step of 5e-4 after steps of 0.05 made a vesicle's lambda_g jump
// from -0.2 to -2.6 (doc/hydrodynamics.md, "HD1 to its stationary shape").

#include <vesicle_iga/time/time_loop.h>

#include <cmath>
#include <fstream>

#include "../root_output.h"

int
main()
{
  std::ofstream out("output");
  using vesicle_iga::final_step_size;
  const auto near
    = [](const double a, const double b) { return std::abs(a - b) < 1e-14; };

  double t = 0;
  for (unsigned int k = 0; k < 1999; ++k)
    t += 1e-3;
  // 1999 steps of 1e-3 in floating point: the remainder is 1e-3 up to
  // round-off, on either side.
  const double last = final_step_size(1e-3, 2. - t);
  out << "fixed steps: the 2000th step ends the run: "
      << verdict(std::abs(last - (2. - t)) == 0
                 && std::abs(last - 1e-3) < 1e-12)
      << '\n';
  out << "remainder 0.3 dt: one step of it: "
      << verdict(near(final_step_size(1., 0.3), 0.3)) << '\n';
  out << "remainder 1.01 dt: two steps of 0.505 dt: "
      << verdict(near(final_step_size(1., 1.01), 0.505)
                 && near(final_step_size(1., 1.01 - 0.505), 0.505))
      << '\n';
  out << "remainder 1.999 dt: half of it: "
      << verdict(near(final_step_size(1., 1.999), 0.9995)) << '\n';
  out << "remainder 2 dt and more: dt: "
      << verdict(final_step_size(1., 2.) == 1.
                 && final_step_size(1., 7.5) == 1.)
      << '\n';
}
