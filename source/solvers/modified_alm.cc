#include <vesicle_iga/solvers/modified_alm.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  ModifiedALM::ModifiedALM(const double       V0,
                           const double       A0,
                           const double       tolerance,
                           const unsigned int max_iterations)
    : V0(V0)
    , A0(A0)
    , tol(tolerance)
    , max_iterations(max_iterations)
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


  ModifiedALM::Result
  ModifiedALM::step(const StepSolver       &solve,
                    const double            v_n,
                    const double            a_n,
                    const InverseRefresher &refresh)
  {
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
                Tinv = {{d00 * i00 + d01 * i10,
                         d00 * i01 + d01 * i11,
                         d10 * i00 + d11 * i10,
                         d10 * i01 + d11 * i11}};
              }
          }
        update(v, a);
        if (!solve(al, be, v, a))
          return {false, it, v, a};
        if (converged(v, a))
          return {true, it, v, a};
        if (it < 3 && refresh)
          {
            std::array<double, 4> T = Tinv;
            if (refresh(T))
              Tinv = T;
          }
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
  }
} // namespace vesicle_iga
