// ModifiedALM (spec 3.8, Algorithm 1) on a linear model of the constrained
// step whose answers are known in closed form: the state s = (V, A) moves
// over a step of size dt under the multipliers of (E19),
//   Lambda = diag(M) (s_n - (alpha, beta)),
//   s_{n+1} = s_n + dt (r(t_n + dt/2) - K Lambda),
// with an unconstrained drift r and a coupling matrix K (SPD). The exact
// Jacobian of s_{n+1} with respect to (alpha, beta) is T = dt K diag(M);
// the ALM is given its exact inverse before each step, so what is tested
// is the first update of a step, not the secant estimate (E22). Every step
// is accepted after one ALM iteration (tolerance 1e-3 against errors of
// 1e-5 and less); e_n = s_n - (V0, A0).
//
// Theory the output is checked against (derived in the class comment of
// ModifiedALM and doc/validation.md section 5):
// 1. carried error (Algorithm 1): with constant r and dt the one-iteration
//    errors follow e_{n+1} = (I - C)(e_n - e_{n-1}), C = dt K diag(M): an
//    oscillation of period about six steps, damped only by C (the printed
//    recursion defect is relative to max |e|); the error is O(dt): halving
//    dt halves it.
// 2. predicted drift: with constant r the error after the second step is
//    zero to round-off, for constant and for growing steps (which checks
//    the step-size ratio of the extrapolation); with r linear in time it
//    is exactly dt^2 dr/dt per step (the rate moves between steps), O(dt^2).
//    The same holds when the ALM gets the inverse once, from its
//    refresher at the first step, and scales it by the step-size ratio
//    (T is proportional to dt here).
// 3. a checkpoint of the ALM taken after step 10 and loaded into a new
//    object continues bit for bit like the uninterrupted one (the drift of
//    the last step is part of the state).
// Checked to fail with the extrapolation ratio inverted (dt_last / dt),
// without the shift of (alpha, beta) by the last step's change, and
// without the scaling of T^-1 or the refresh at a converged first step.

#include <deal.II/base/mpi.h>

#include <vesicle_iga/solvers/modified_alm.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <vector>

using namespace vesicle_iga;
using Vec2 = std::array<double, 2>;

namespace
{
  const double V0 = 300, A0 = 60;
  const Vec2   M{{1, 2}};
  // K, row-major, SPD.
  const std::array<double, 4> K{{2, 0.5, 0.5, 1}};

  /// The linear model: a drift rate as a function of time.
  struct Model
  {
    std::function<Vec2(double)> rate;
    Vec2                        s{{V0, A0}};
    double                      t = 0;

    /// T^{-1} = (dt K diag(M))^{-1}, row-major.
    static std::array<double, 4>
    exact_inverse(const double dt)
    {
      const double T00 = dt * K[0] * M[0], T01 = dt * K[1] * M[1];
      const double T10 = dt * K[2] * M[0], T11 = dt * K[3] * M[1];
      const double det = T00 * T11 - T01 * T10;
      return {{T11 / det, -T01 / det, -T10 / det, T00 / det}};
    }

    /// Whether the test hands the ALM the exact inverse before each step;
    /// else only through the refresher (the linearised Jacobian of the
    /// model), which the ALM calls when it has no estimate yet.
    bool given_inverse = true;

    /// One accepted step with the ALM; returns the ALM iterations.
    unsigned int
    step(ModifiedALM &alm, const double dt)
    {
      if (given_inverse)
        alm.set_state(alm.alpha(), alm.beta(), exact_inverse(dt));
      const auto refresh = [dt](std::array<double, 4> &T) {
        T = exact_inverse(dt);
        return true;
      };
      const Vec2 r     = rate(t + dt / 2);
      Vec2       next  = s;
      const auto solve = [&](double al, double be, double &v, double &a) {
        const Vec2 L{{M[0] * (s[0] - al), M[1] * (s[1] - be)}};
        next = {{s[0] + dt * (r[0] - K[0] * L[0] - K[1] * L[1]),
                 s[1] + dt * (r[1] - K[2] * L[0] - K[3] * L[1])}};
        v    = next[0];
        a    = next[1];
        return true;
      };
      const auto result = given_inverse ?
                            alm.step(solve, s[0], s[1], dt) :
                            alm.step(solve, s[0], s[1], dt, refresh);
      if (!result.converged)
        throw std::runtime_error("ALM did not converge");
      alm.record_accepted_step(next[0] - s[0], next[1] - s[1], dt);
      s = next;
      t += dt;
      return result.iterations;
    }

    Vec2
    error() const
    {
      return {{s[0] - V0, s[1] - A0}};
    }
  };

  double
  norm(const Vec2 &e)
  {
    return std::max(std::abs(e[0]), std::abs(e[1]));
  }

  ModifiedALM
  make_alm(const ModifiedALM::FirstUpdate first)
  {
    return ModifiedALM(V0, A0, 1e-3, 20, first);
  }

  const Vec2 constant_rate{{-0.5, 0.3}};

  /// Errors of @p n steps of size dt (constant rate); max |e| and the
  /// largest defect of e_{n+1} = (I - C)(e_n - e_{n-1}) from step 3 on.
  void
  carried_error(std::ostream &out, const double dt, const unsigned int n)
  {
    Model             model{[](double) { return constant_rate; }};
    ModifiedALM       alm = make_alm(ModifiedALM::FirstUpdate::carried_error);
    std::vector<Vec2> e;
    for (unsigned int k = 0; k < n; ++k)
      {
        model.step(alm, dt);
        e.push_back(model.error());
      }
    double max_e = 0, defect = 0;
    for (const auto &x : e)
      max_e = std::max(max_e, norm(x));
    const double C00 = dt * K[0] * M[0], C01 = dt * K[1] * M[1];
    const double C10 = dt * K[2] * M[0], C11 = dt * K[3] * M[1];
    for (unsigned int k = 2; k < n; ++k)
      {
        const Vec2 d{{e[k - 1][0] - e[k - 2][0], e[k - 1][1] - e[k - 2][1]}};
        const Vec2 predicted{
          {d[0] - C00 * d[0] - C01 * d[1], d[1] - C10 * d[0] - C11 * d[1]}};
        defect
          = std::max(defect,
                     norm({{e[k][0] - predicted[0], e[k][1] - predicted[1]}}));
      }
    // Sign changes of the volume error: an oscillation of period ~6 gives
    // one every ~3 steps.
    unsigned int sign_changes = 0;
    for (unsigned int k = 1; k < n; ++k)
      sign_changes += (e[k][0] * e[k - 1][0] < 0);
    out << "carried error, dt = " << dt << ", " << n
        << " steps: max |e| = " << std::setprecision(3) << max_e
        << ", recursion defect / max |e| "
        << (defect <= 1e-10 * max_e ? "< 1e-10" : "TOO LARGE")
        << ", sign changes of e_V: " << sign_changes << std::endl;
  }

  /// Predicted drift: max |e| from step 3 on, for steps dt * growth^k.
  void
  predicted_drift(std::ostream                     &out,
                  const std::string                &label,
                  const std::function<Vec2(double)> rate,
                  const double                      dt0,
                  const double                      growth,
                  const unsigned int                n,
                  const double                      expected,
                  const bool                        given_inverse = true)
  {
    Model model{rate};
    model.given_inverse = given_inverse;
    ModifiedALM alm     = make_alm(ModifiedALM::FirstUpdate::predicted_drift);
    double      dt = dt0, max_e = 0, first = 0;
    for (unsigned int k = 0; k < n; ++k, dt *= growth)
      {
        model.step(alm, dt);
        if (k == 0)
          first = norm(model.error());
        if (k >= 2)
          max_e = std::max(max_e, norm(model.error()));
      }
    out << "predicted drift, " << label
        << ": |e| after step 1 = " << std::setprecision(3) << first
        << ", max |e| from step 3 on ";
    if (expected == 0)
      out << "/ V0 " << (max_e <= 1e-13 * V0 ? "< 1e-13" : "TOO LARGE")
          << " (round-off of V)";
    else
      out << "/ (dt^2 |dr/dt|) = " << std::setprecision(6) << max_e / expected;
    out << std::endl;
  }

  /// Steps 11-20 after a checkpoint of step 10 against the uninterrupted
  /// run.
  void
  restart(std::ostream &out)
  {
    const auto rate = [](double t) {
      return Vec2{{-0.5 + 0.2 * t, 0.3 - 0.1 * t}};
    };
    Model       model{rate};
    ModifiedALM alm = make_alm(ModifiedALM::FirstUpdate::predicted_drift);
    for (unsigned int k = 0; k < 10; ++k)
      model.step(alm, 0.01 * (1 + 0.1 * k));
    Checkpoint c;
    alm.save(c, "alm");
    Model       resumed = model;
    ModifiedALM loaded  = make_alm(ModifiedALM::FirstUpdate::predicted_drift);
    loaded.load(c, "alm");
    bool equal = true;
    for (unsigned int k = 10; k < 20; ++k)
      {
        model.step(alm, 0.01 * (1 + 0.1 * k));
        resumed.step(loaded, 0.01 * (1 + 0.1 * k));
        equal = equal && model.s == resumed.s && alm.alpha() == loaded.alpha()
                && alm.beta() == loaded.beta();
      }
    out << "restart after step 10 equals the uninterrupted run: "
        << (equal ? "yes" : "NO") << std::endl;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                            out("output");
  carried_error(out, 0.01, 60);
  carried_error(out, 0.005, 120);
  const auto constant = [](double) { return constant_rate; };
  predicted_drift(out, "constant rate, dt = 0.01", constant, 0.01, 1, 60, 0);
  predicted_drift(
    out, "constant rate, dt growing 1.2x per step", constant, 1e-3, 1.2, 30, 0);
  // The inverse from the refresher once, at the first step (which
  // converges at once): T = dt K diag(M) is proportional to dt, so the
  // scaling by the step-size ratio keeps it exact.
  predicted_drift(out,
                  "constant rate, dt growing 1.2x per step, T^-1 estimated "
                  "once and scaled",
                  constant,
                  1e-3,
                  1.2,
                  30,
                  0,
                  false);
  // r = r0 + r1 t with |r1| = 0.2 (max norm): e_{n+1} = dt^2 r1 exactly.
  const auto linear = [](double t) {
    return Vec2{{-0.5 + 0.2 * t, 0.3 - 0.1 * t}};
  };
  predicted_drift(out, "linear rate, dt = 0.01", linear, 0.01, 1, 60, 0.2e-4);
  predicted_drift(
    out, "linear rate, dt = 0.005", linear, 0.005, 1, 120, 0.2 * 0.25e-4);
  restart(out);
}
