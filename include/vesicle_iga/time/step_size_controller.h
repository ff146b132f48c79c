#pragma once

#include <deal.II/base/parameter_handler.h>

#include <vesicle_iga/io/checkpoint.h>

#include <string>

namespace vesicle_iga
{
  /**
   * The time step of the time loop, in one of three modes:
   *  - fixed: dt = Initial dt;
   *  - growing: dt multiplied by 'Growth factor' after every accepted step
   *    up to Max dt (pseudo-time stepping to a steady state);
   *  - adaptive (spec section 2.5): after an accepted Newton solve a local
   *    error estimate (N5) of order k = 2 drives a PI42 digital filter (the
   *    default of PETSc's DSP adaptor that the source used), with the
   *    limiter rho <- 1 + atan(rho - 1), acceptance for rho >= 0.81, step
   *    factor clipped to [0.1, 10] and dt to [Min dt, Max dt].
   * In every mode a failed step (Newton, Krylov or the constraint method)
   * is rejected and dt multiplied by 0.25; dt may then not grow until
   * 'Increase delay' consecutive steps have converged. A fixed step then
   * returns to Initial dt, by a factor 4 per accepted step.
   */
  class StepSizeController : public Checkpointable
  {
  public:
    struct Parameters
    {
      std::string  mode       = "adaptive";
      double       initial_dt = 1, min_dt = 1e-14, max_dt = 1, growth = 1;
      double       atol = 1e-4, rtol = 1e-4;
      unsigned int increase_delay = 3;

      /// Entries of the current subsection ("Time stepping").
      static void
      declare(dealii::ParameterHandler &prm,
              const std::string        &default_mode,
              const std::string        &default_dt,
              const std::string        &default_max_dt);
      void
      parse(dealii::ParameterHandler &prm, const std::string &section);
    };

    explicit StepSizeController(const Parameters &parameters);

    double
    dt() const
    {
      return current_dt;
    }
    bool
    adaptive() const
    {
      return prm.mode == "adaptive";
    }
    /// Whether dt has reached Max dt (a fixed dt counts as reached).
    bool
    at_maximum() const
    {
      return prm.mode == "fixed" || current_dt >= prm.max_dt * 0.999;
    }
    /// After a solved step: whether the error norm e (weighted RMS of (N5),
    /// < 0: no estimate) accepts it; sets the next dt either way.
    bool
    accept(const double error);
    /// Caps the next dt at @p largest (not below Min dt); returns whether
    /// the cap cut it.
    bool
    limit(const double largest);
    /// Failure: reject and cut dt. Returns false when dt would fall below
    /// the minimum (the run cannot continue).
    bool
    reject_failure();

    void
    save(Checkpoint &c, const std::string &prefix) const override;
    void
    load(const Checkpoint &c, const std::string &prefix) override;

  private:
    Parameters prm;
    double     current_dt;
    double     c_prev          = 1;
    int        steps_since_cut = 1000;
  };
} // namespace vesicle_iga
