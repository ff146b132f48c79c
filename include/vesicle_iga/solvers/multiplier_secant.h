#pragma once

#include <array>

namespace vesicle_iga
{
  /**
   * A quasi-Newton iteration for two unknowns x and two residuals G(x) = 0
   * whose evaluations are expensive (each is a time step solved with x):
   * started from an estimate J of dG/dx, every further evaluation improves
   * J by Broyden's secant update J += ((dG - J dx) dx^T) / (dx . dx), and
   * the next x solves J (x_new - x) = -G.
   *
   * The implicit global multipliers of Part H use one per vesicle: x =
   * (lambda_v, lambda_g) of the step, G = (V_i, A_i) at its end minus
   * V_i(0), A_i(0) (H7), J from the rate laws of (H13) times dt
   * (VesicleHydrodynamics::solve_step).
   */
  class SecantIteration2
  {
  public:
    /// Starts at @p x with the estimate @p jacobian of dG/dx (row-major).
    SecantIteration2(const std::array<double, 2> &x,
                     const std::array<double, 4> &jacobian);

    /// G at x(): moves x() to the next iterate and returns it. A secant
    /// update that would leave J (nearly) singular is skipped.
    const std::array<double, 2> &
    next(const std::array<double, 2> &G);

    const std::array<double, 2> &
    x() const
    {
      return current;
    }
    /// The current estimate of dG/dx (row-major).
    const std::array<double, 4> &
    jacobian() const
    {
      return J;
    }

    /// x() - J^-1 @p change: by the current estimate J, the x at which G
    /// would be smaller by @p change than at x(). The implicit multipliers
    /// keep the x of a step without its change of the constraint errors
    /// (change = G at the end minus G at the start of the step), so that
    /// the next step starts from multipliers that hold the errors where
    /// they are.
    std::array<double, 2>
    without_change(const std::array<double, 2> &change) const;

  private:
    std::array<double, 2> current, previous_x, previous_G;
    std::array<double, 4> J;
    bool                  has_previous = false;
  };
} // namespace vesicle_iga
