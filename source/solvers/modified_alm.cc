#include <vesicle_iga/solvers/modified_alm.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  ModifiedALM::ModifiedALM(const double       V0,
                           const double       A0,
                           const double       tolerance,
                           const unsigned int max_iterations,
                           const FirstUpdate  first_update)
    : V0(V0)
    , A0(A0)
    , tol(tolerance)
    , max_iterations(max_iterations)
    , first_update(first_update)
    , al(V0)
    , be(A0)
  {}


  bool
  ModifiedALM::converged(const double v, const double a) const
  {
    return std::max(std::abs(v - V0) / std::abs(V0),
                    std::abs(a - A0) / std::abs(A0))
           <= tol;
  }


  void
  ModifiedALM::update(const double v, const double a)
  {
    // (E21)
    const double dv = v - V0, da = a - A0;
    al -= Tinv[0] * dv + Tinv[1] * da;
    be -= Tinv[2] * dv + Tinv[3] * da;
  }


  void
  ModifiedALM::predicted_drift_update(const double v_n,
                                      const double a_n,
                                      const double dt)
  {
    const auto [dv, da, dt_last] = last_step;
    // (E19): Lambda_V = M1 (V(phi_n) - alpha) equals the last step's
    // M1 (V(phi_{n-1}) - alpha) when alpha moves with V, likewise beta.
    al += dv;
    be += da;
    // Under those multipliers V, A change at the last step's rate; (E21)
    // then removes the predicted end-of-step error.
    const double ratio = dt / dt_last;
    update(v_n + ratio * dv, a_n + ratio * da);
  }


  ModifiedALM::Result
  ModifiedALM::step(const StepSolver       &solve,
                    const double            v_n,
                    const double            a_n,
                    const double            dt,
                    const InverseRefresher &refresh)
  {
    const bool predict = first_update == FirstUpdate::predicted_drift;
    if (predict && inverse_dt > 0)
      {
        for (double &t : Tinv)
          t *= inverse_dt / dt;
        inverse_dt = dt;
      }
    // The last three iterates (oldest first).
    std::array<double, 3> als{}, bes{}, vs{}, as{};
    double                v = v_n, a = a_n;
    for (unsigned int it = 1; it <= max_iterations; ++it)
      {
        // Lines 5-10 of Algorithm 1 use the current inverse for the first
        // three updates; from the fourth on (lines 11-17) it is replaced
        // by the secant estimate (E22) from the last three iterates.
        if (it > 3)
          {
            const double m00 = vs[1] - vs[0], m01 = vs[2] - vs[0];
            const double m10 = as[1] - as[0], m11 = as[2] - as[0];
            const double det   = m00 * m11 - m01 * m10;
            const double scale = (std::abs(m00) + std::abs(m01))
                                 * (std::abs(m10) + std::abs(m11));
            if (std::abs(det) > 1e-12 * scale && scale > 0)
              {
                const double i00 = m11 / det, i01 = -m01 / det;
                const double i10 = -m10 / det, i11 = m00 / det;
                const double d00 = als[1] - als[0], d01 = als[2] - als[0];
                const double d10 = bes[1] - bes[0], d11 = bes[2] - bes[0];
                Tinv       = {{d00 * i00 + d01 * i10,
                               d00 * i01 + d01 * i11,
                               d10 * i00 + d11 * i10,
                               d10 * i01 + d11 * i11}};
                inverse_dt = dt;
              }
          }
        if (it == 1 && predict && last_step[2] > 0)
          predicted_drift_update(v_n, a_n, dt);
        else
          update(v, a);
        if (!solve(al, be, v, a))
          return {false, it, v, a};
        const bool done = converged(v, a);
        if (refresh
            && ((!done && it < 3) || (done && predict && inverse_dt == 0)))
          {
            std::array<double, 4> T = Tinv;
            if (refresh(T))
              {
                Tinv       = T;
                inverse_dt = dt;
              }
          }
        if (done)
          return {true, it, v, a};
        als = {{als[1], als[2], al}};
        bes = {{bes[1], bes[2], be}};
        vs  = {{vs[1], vs[2], v}};
        as  = {{as[1], as[2], a}};
      }
    return {false, max_iterations, v, a};
  }


  void
  ModifiedALM::save(Checkpoint &c, const std::string &prefix) const
  {
    c.scalars[prefix + ".volume_target"] = V0;
    c.scalars[prefix + ".area_target"]   = A0;
    c.scalars[prefix + ".alpha"]         = al;
    c.scalars[prefix + ".beta"]          = be;
    for (unsigned int k = 0; k < 4; ++k)
      c.scalars[prefix + ".inverse_jacobian_" + std::to_string(k)] = Tinv[k];
    c.scalars[prefix + ".last_step_volume_change"]    = last_step[0];
    c.scalars[prefix + ".last_step_area_change"]      = last_step[1];
    c.scalars[prefix + ".last_step_size"]             = last_step[2];
    c.scalars[prefix + ".inverse_jacobian_step_size"] = inverse_dt;
  }


  void
  ModifiedALM::load(const Checkpoint &c, const std::string &prefix)
  {
    V0 = c.scalar(prefix + ".volume_target");
    A0 = c.scalar(prefix + ".area_target");
    al = c.scalar(prefix + ".alpha");
    be = c.scalar(prefix + ".beta");
    for (unsigned int k = 0; k < 4; ++k)
      Tinv[k] = c.scalar(prefix + ".inverse_jacobian_" + std::to_string(k));
    // Checkpoints written before the drift was kept have none.
    last_step  = {{0, 0, 0}};
    inverse_dt = 0;
    if (c.scalars.count(prefix + ".last_step_size"))
      {
        last_step  = {{c.scalar(prefix + ".last_step_volume_change"),
                       c.scalar(prefix + ".last_step_area_change"),
                       c.scalar(prefix + ".last_step_size")}};
        inverse_dt = c.scalar(prefix + ".inverse_jacobian_step_size");
      }
  }
} // namespace vesicle_iga
