#pragma once

#include <vesicle_iga/io/checkpoint.h>

#include <array>
#include <functional>
#include <string>

namespace vesicle_iga
{
  /**
   * The modified augmented-Lagrangian method of spec section 3.8
   * (Algorithm 1): the shifted targets (alpha, beta) of (E11)/(E19) are
   * updated by (E21) with the secant estimate (E22) of the inverse 2x2
   * Jacobian of (V(phi_{n+1}), A(phi_{n+1})) with respect to (alpha, beta),
   * until both constraints hold to a relative tolerance. The inverse
   * Jacobian is kept across time steps (spec section 7). Safeguards
   * (spec [R]): a near-singular secant matrix keeps the previous inverse;
   * after a maximum number of iterations the step counts as failed.
   */
  class ModifiedALM : public Checkpointable
  {
  public:
    /// Solves the time step with shifted targets alpha, beta; returns
    /// false on Newton failure, else sets v = V(phi_{n+1}),
    /// a = A(phi_{n+1}).
    using StepSolver
      = std::function<bool(double alpha, double beta, double &v, double &a)>;

    ModifiedALM(const double       V0,
                const double       A0,
                const double       tolerance,
                const unsigned int max_iterations);

    struct Result
    {
      bool         converged;
      unsigned int iterations;
      double       volume, area;
    };

    /// One time step: @p v_n, @p a_n are V(phi_n), A(phi_n).
    /// Optionally replaces the inverse Jacobian after an unconverged
    /// iteration among the first three (which use the current inverse,
    /// Algorithm 1 lines 5-10) by a better estimate; returns false to keep
    /// it.
    using InverseRefresher = std::function<bool(std::array<double, 4> &)>;

    Result
    step(const StepSolver       &solve,
         const double            v_n,
         const double            a_n,
         const InverseRefresher &refresh = InverseRefresher());

    /// New targets V0, A0 (alpha = V0, beta = A0; the inverse Jacobian
    /// is kept).
    void
    reset_targets(const double volume, const double area)
    {
      V0 = volume;
      A0 = area;
      al = volume;
      be = area;
    }
    double
    volume_target() const
    {
      return V0;
    }
    double
    area_target() const
    {
      return A0;
    }
    /// Targets, shifted targets and the inverse Jacobian.
    void
    save(Checkpoint &c, const std::string &prefix) const override;
    void
    load(const Checkpoint &c, const std::string &prefix) override;

    double
    alpha() const
    {
      return al;
    }
    double
    beta() const
    {
      return be;
    }
    void
    set_state(const double                 alpha,
              const double                 beta,
              const std::array<double, 4> &T_inverse)
    {
      al   = alpha;
      be   = beta;
      Tinv = T_inverse;
    }
    const std::array<double, 4> &
    inverse_jacobian() const
    {
      return Tinv;
    }

  private:
    bool
    converged(const double v, const double a) const;
    void
    update(const double v, const double a);

    double                V0, A0, tol;
    unsigned int          max_iterations;
    double                al, be;
    std::array<double, 4> Tinv{{1, 0, 0, 1}}; // row-major 2x2
  };
} // namespace vesicle_iga
