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
   *
   * The first update of a step (Algorithm 1, line 7) removes the error
   * carried in, V(phi_n) - alpha0, but not the drift of the step itself:
   * with the multipliers of (E19) held, (V, A) moves over the step by
   * about dt times the rate of the last step, so one-iteration steps leave
   * an error proportional to dt; with an exact T^{-1} and equal steps the
   * errors of successive one-iteration steps follow e_{n+1} = (I - C)
   * (e_n - e_{n-1}), C = dt K diag(M1, M2) the small response of the step
   * to the multipliers: an oscillation of period about six steps that only
   * C damps (doc/validation.md section 5, tests/solvers/modified_alm).
   * FirstUpdate::predicted_drift (not in the source) aims the first
   * update at the predicted end-of-step values instead: the multipliers
   * (E19) of the last accepted step are kept (alpha, beta shifted by that
   * step's change of V, A, since (E19) takes V, A at phi_n) and the
   * change (V, A) made under them, scaled by the ratio of the step sizes,
   * is added to the error the update removes. The inverse Jacobian it
   * uses must belong to the step size at hand: T is proportional to dt for
   * steps short against the relaxation of the shape (the rate term
   * dominates the Newton matrix), so T^{-1} kept from a step of size dt'
   * is scaled by dt'/dt, and a step that finds no estimate yet (the
   * identity of the start) asks the refresher for one even when it
   * converged.
   */
  class ModifiedALM : public Checkpointable
  {
  public:
    /// Solves the time step with shifted targets alpha, beta; returns
    /// false on Newton failure, else sets v = V(phi_{n+1}),
    /// a = A(phi_{n+1}).
    using StepSolver
      = std::function<bool(double alpha, double beta, double &v, double &a)>;

    /// What the first update of a step removes (see the class comment).
    enum class FirstUpdate
    {
      carried_error,
      predicted_drift
    };

    ModifiedALM(const double       V0,
                const double       A0,
                const double       tolerance,
                const unsigned int max_iterations,
                const FirstUpdate  first_update = FirstUpdate::carried_error);

    struct Result
    {
      bool         converged;
      unsigned int iterations;
      double       volume, area;
    };

    /// One time step of size @p dt: @p v_n, @p a_n are V(phi_n), A(phi_n).
    /// Optionally replaces the inverse Jacobian after an unconverged
    /// iteration among the first three (which use the current inverse,
    /// Algorithm 1 lines 5-10) by a better estimate; returns false to keep
    /// it.
    using InverseRefresher = std::function<bool(std::array<double, 4> &)>;

    Result
    step(const StepSolver       &solve,
         const double            v_n,
         const double            a_n,
         const double            dt,
         const InverseRefresher &refresh = InverseRefresher());

    /// The step of size @p dt from phi_{n-1} to phi_n was accepted and
    /// changed V, A by @p dv, @p da (the drift that
    /// FirstUpdate::predicted_drift extrapolates).
    void
    record_accepted_step(const double dv, const double da, const double dt)
    {
      last_step = {{dv, da, dt}};
    }

    /// New targets V0, A0 (alpha = V0, beta = A0; the inverse Jacobian
    /// is kept).
    void
    reset_targets(const double volume, const double area)
    {
      V0        = volume;
      A0        = area;
      al        = volume;
      be        = area;
      last_step = {{0, 0, 0}};
    }
    /// Moves the targets to V0 + dv, A0 + da, and the shifted targets
    /// alpha, beta with them, so that what the iterations have learnt about
    /// the step (the shifts alpha - V0, beta - A0, the inverse Jacobian, the
    /// last accepted step) is kept (ZeroSetTargetControl).
    void
    shift_targets(const double dv, const double da)
    {
      V0 += dv;
      A0 += da;
      al += dv;
      be += da;
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
    /// Targets, shifted targets, the inverse Jacobian and the last
    /// accepted step's change of V, A.
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

    /// The first update with the drift predicted from the last step.
    void
    predicted_drift_update(const double v_n, const double a_n, const double dt);

    double                V0, A0, tol;
    unsigned int          max_iterations;
    FirstUpdate           first_update;
    double                al, be;
    std::array<double, 4> Tinv{{1, 0, 0, 1}}; // row-major 2x2
    /// Change of V and A over the last accepted step and its size
    /// (dt = 0: none since the start or the last new targets).
    std::array<double, 3> last_step{{0, 0, 0}};
    /// The step size Tinv was estimated at (0: the identity of the start;
    /// used only by FirstUpdate::predicted_drift).
    double inverse_dt = 0;
  };
} // namespace vesicle_iga
