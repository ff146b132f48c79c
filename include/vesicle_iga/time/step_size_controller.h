#pragma once

#include <deal.II/base/parameter_handler.h>

namespace vesicle_iga
{
  using namespace dealii;

  /**
   * Adaptive time steps (spec section 2.5): after an accepted Newton solve
   * a local error estimate (N5) of order k = 2 drives a PI42 digital filter
   * (the default of PETSc's DSP adaptor that the source used), with the
   * limiter rho <- 1 + atan(rho - 1), acceptance for rho >= 0.81, step
   * factor clipped to [0.1, 10] and dt to [dt_min, dt_max]. A Newton (or
   * ALM) failure rejects the step and multiplies dt by 0.25; after such a
   * cut dt may not grow until 3 consecutive steps have converged.
   */
  class StepSizeController
  {
  public:
    struct Parameters
    {
      bool         adaptive;
      double       initial_dt, min_dt, max_dt;
      double       atol, rtol;
      unsigned int increase_delay;

      static void
      declare(ParameterHandler  &prm,
              const std::string &default_dt,
              const std::string &default_max_dt);
      void
      parse(ParameterHandler &prm);
    };

    explicit StepSizeController(const Parameters &parameters);

    double
    dt() const
    {
      return current_dt;
    }
    /// Whether the error norm e (weighted RMS of (N5), < 0: no estimate)
    /// accepts the step; sets the next dt either way.
    bool
    accept(const double error);
    /// Newton/ALM failure: reject and cut dt. Returns false when dt would
    /// fall below the minimum (the run cannot continue).
    bool
    reject_failure();

    /// State for checkpoints: dt, previous filter value, steps since a cut.
    void
    set_state(const double dt, const double c_previous, const int since_cut)
    {
      current_dt      = dt;
      c_prev          = c_previous;
      steps_since_cut = since_cut;
    }
    double
    previous_filter_value() const
    {
      return c_prev;
    }
    int
    steps_since_failure() const
    {
      return steps_since_cut;
    }

  private:
    Parameters prm;
    double     current_dt;
    double     c_prev          = 1;
    int        steps_since_cut = 1000;
  };
} // namespace vesicle_iga
