// Quasi-Newton iteration for two unknowns (implicit global multipliers of
// Part H).
#include <deal.II/base/exceptions.h>

#include <vesicle_iga/solvers/multiplier_secant.h>

#include <cmath>
#include <string>

namespace vesicle_iga
{
  namespace
  {
    double
    determinant(const std::array<double, 4> &J)
    {
      return J[0] * J[3] - J[1] * J[2];
    }
  } // namespace


  SecantIteration2::SecantIteration2(const std::array<double, 2> &x,
                                     const std::array<double, 4> &jacobian)
    : current(x)
    , J(jacobian)
  {
    AssertThrow(std::isfinite(determinant(J)) && determinant(J) != 0,
                dealii::ExcMessage(
                  "The starting Jacobian of the secant iteration is "
                  "singular (determinant "
                  + std::to_string(determinant(J)) + ")."));
  }


  const std::array<double, 2> &
  SecantIteration2::next(const std::array<double, 2> &G)
  {
    if (has_previous)
      {
        const double dx[2]
          = {current[0] - previous_x[0], current[1] - previous_x[1]};
        const double dG[2] = {G[0] - previous_G[0], G[1] - previous_G[1]};
        const double norm2 = dx[0] * dx[0] + dx[1] * dx[1];
        if (norm2 > 0)
          {
            std::array<double, 4> updated = J;
            for (unsigned int r = 0; r < 2; ++r)
              {
                const double defect
                  = dG[r] - (J[2 * r] * dx[0] + J[2 * r + 1] * dx[1]);
                updated[2 * r] += defect * dx[0] / norm2;
                updated[2 * r + 1] += defect * dx[1] / norm2;
              }
            // Keep J if the update would make it nearly singular (a secant
            // along a direction G hardly changes in).
            const double scale = std::abs(updated[0] * updated[3])
                                 + std::abs(updated[1] * updated[2]);
            if (std::abs(determinant(updated)) > 1e-8 * scale)
              J = updated;
          }
      }
    previous_x   = current;
    previous_G   = G;
    has_previous = true;
    current      = without_change(G);
    return current;
  }


  std::array<double, 2>
  SecantIteration2::without_change(const std::array<double, 2> &change) const
  {
    // J is never singular: checked at the start, and updates that would
    // make it nearly so are skipped.
    const double det = determinant(J);
    return {{current[0] - (J[3] * change[0] - J[1] * change[1]) / det,
             current[1] - (J[0] * change[1] - J[2] * change[0]) / det}};
  }
} // namespace vesicle_iga
