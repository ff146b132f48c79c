// The secant (Broyden) iteration for two unknowns of the implicit global
// multipliers (solvers/multiplier_secant.h), on maps whose root is known:
// - linear, G(x) = A x - b with A = [2 1; 0.5 3], started with the wrong
//   Jacobian with A's diagonal doubled (as the rate laws misjudge a step's
//   response): converges to the exact root A^-1 b to 1e-12 in at most 8
//   evaluations (Broyden's method is exact for linear maps after at most
//   2n = 4 updates);
// - nonlinear, G(x) = A x + 0.2 (x_0^2, x_1^2) - G_root with the root (1, -1)
//   put in by construction: converges to 1e-10 in at most 10 evaluations;
// - without_change(c) = x - J^-1 c, what the implicit multipliers keep
//   after a step: for the linear map with the exact Jacobian, G there is
//   G(x) - c to round-off (checked to 1e-14);
// - the starting Jacobian singular: a clear error.
// The iteration counts are printed: the arithmetic is a few dozen operations
// without any tolerance near a decision.

#include <deal.II/base/exceptions.h>

#include <vesicle_iga/solvers/multiplier_secant.h>

#include <cmath>
#include <fstream>
#include <functional>

#include "../root_output.h"

using namespace vesicle_iga;

namespace
{
  /// Evaluations until |G| <= tolerance (at most 50).
  unsigned int
  solve(const std::function<std::array<double, 2>(std::array<double, 2>)> &G,
        const std::array<double, 4>                                       &J,
        const double           tolerance,
        std::array<double, 2> &x)
  {
    SecantIteration2 secant(x, J);
    for (unsigned int k = 1; k <= 50; ++k)
      {
        const auto g = G(secant.x());
        if (std::hypot(g[0], g[1]) <= tolerance)
          {
            x = secant.x();
            return k;
          }
        secant.next(g);
      }
    x = secant.x();
    return 51;
  }
} // namespace

int
main()
{
  std::ofstream out("output");

  const std::array<double, 4> A{{2, 1, 0.5, 3}};
  const std::array<double, 2> b{{1, 2}};
  const auto                  linear = [&](const std::array<double, 2> x) {
    return std::array<double, 2>{
      {A[0] * x[0] + A[1] * x[1] - b[0], A[2] * x[0] + A[3] * x[1] - b[1]}};
  };
  // A^-1 b = (3 * 1 - 1 * 2, 2 * 2 - 0.5 * 1) / 5.5.
  const std::array<double, 2> root{{1 / 5.5, 3.5 / 5.5}};
  std::array<double, 2>       x{{0, 0}};
  const unsigned int k_linear = solve(linear, {{4, 1, 0.5, 6}}, 1e-13, x);
  out << "linear, diagonal of the Jacobian off by 2: " << k_linear
      << " evaluations, root to 1e-12: "
      << verdict(k_linear <= 8 && std::abs(x[0] - root[0]) < 1e-12
                 && std::abs(x[1] - root[1]) < 1e-12)
      << '\n';

  const auto nonlinear = [&](const std::array<double, 2> x) {
    const auto at = [&](const std::array<double, 2> y) {
      return std::array<double, 2>{
        {A[0] * y[0] + A[1] * y[1] + 0.2 * y[0] * y[0],
         A[2] * y[0] + A[3] * y[1] + 0.2 * y[1] * y[1]}};
    };
    const auto g = at(x), g_root = at({{1, -1}});
    return std::array<double, 2>{{g[0] - g_root[0], g[1] - g_root[1]}};
  };
  x                        = {{0.5, -0.5}};
  const unsigned int k_non = solve(nonlinear, A, 1e-12, x);
  out << "nonlinear, Jacobian at the wrong point: " << k_non
      << " evaluations, root (1, -1) to 1e-10: "
      << verdict(k_non <= 10 && std::abs(x[0] - 1) < 1e-10
                 && std::abs(x[1] + 1) < 1e-10)
      << '\n';

  {
    const std::array<double, 2> x0{{0.3, -0.2}}, change{{0.1, 0.05}};
    const SecantIteration2      secant(x0, A);
    const auto                  g0 = linear(x0);
    const auto                  g  = linear(secant.without_change(change));
    out << "without_change: G smaller by the change: "
        << verdict(std::abs(g[0] - (g0[0] - change[0])) < 1e-14
                   && std::abs(g[1] - (g0[1] - change[1])) < 1e-14)
        << '\n';
  }

  bool refused = false;
  try
    {
      SecantIteration2 singular({{0, 0}}, {{1, 2, 2, 4}});
    }
  catch (const std::exception &e)
    {
      refused = std::string(e.what()).find("singular") != std::string::npos;
    }
  out << "singular starting Jacobian refused: " << verdict(refused) << '\n';
}
