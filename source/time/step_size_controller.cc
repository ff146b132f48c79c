#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/time/step_size_controller.h>

#include <algorithm>
#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  void
  StepSizeController::Parameters::declare(ParameterHandler  &p,
                                          const std::string &default_mode,
                                          const std::string &default_dt,
                                          const std::string &default_max_dt)
  {
    p.declare_entry("Step control",
                    default_mode,
                    Patterns::Selection("fixed|growing|adaptive"),
                    "fixed: dt = Initial dt; growing: dt multiplied by "
                    "'Growth factor' after every step up to Max dt "
                    "(pseudo-time stepping to a steady state); adaptive: dt "
                    "from a local error estimate (spec section 2.5, PI42 "
                    "filter). In every mode a failed step is repeated with "
                    "dt / 4; a fixed step returns to Initial dt (x4 per "
                    "step) once 'Increase delay' steps have converged.");
    p.declare_entry("Initial dt", default_dt, Patterns::Double(0), "First dt.");
    p.declare_entry("Min dt",
                    "1e-14",
                    Patterns::Double(0),
                    "Smallest dt; a failure below it ends the run with an "
                    "error (the last checkpoint and time series are kept).");
    p.declare_entry("Max dt",
                    default_max_dt,
                    Patterns::Double(0),
                    "Cap on dt.");
    p.declare_entry("Growth factor",
                    "1",
                    Patterns::Double(1),
                    "Step control = growing: dt is multiplied by this after "
                    "every accepted step.");
    p.declare_entry("Absolute tolerance",
                    "1e-4",
                    Patterns::Double(0),
                    "Step control = adaptive: atol of the weighted RMS error "
                    "norm.");
    p.declare_entry("Relative tolerance",
                    "1e-4",
                    Patterns::Double(0),
                    "Step control = adaptive: rtol of the weighted RMS error "
                    "norm.");
    p.declare_entry("Increase delay",
                    "3",
                    Patterns::Integer(0),
                    "Consecutive converged steps required after a failure "
                    "before dt may grow again (or, Step control = fixed, "
                    "return towards Initial dt).");
  }


  void
  StepSizeController::Parameters::parse(ParameterHandler  &p,
                                        const std::string &section)
  {
    mode           = p.get("Step control");
    initial_dt     = p.get_double("Initial dt");
    min_dt         = p.get_double("Min dt");
    max_dt         = p.get_double("Max dt");
    growth         = p.get_double("Growth factor");
    atol           = p.get_double("Absolute tolerance");
    rtol           = p.get_double("Relative tolerance");
    increase_delay = p.get_integer("Increase delay");
    check_input(initial_dt > 0 && initial_dt <= max_dt && min_dt <= initial_dt,
                section + "/Initial dt",
                value_text(initial_dt),
                "Min dt <= Initial dt <= Max dt and > 0");
  }


  StepSizeController::StepSizeController(const Parameters &p)
    : prm(p)
    , current_dt(p.initial_dt)
  {}


  bool
  StepSizeController::accept(const double error)
  {
    ++steps_since_cut;
    if (prm.mode == "growing")
      {
        if (steps_since_cut >= int(prm.increase_delay))
          current_dt = std::min(current_dt * prm.growth, prm.max_dt);
        return true;
      }
    if (prm.mode == "fixed")
      {
        // A cut is a response to one hard step (a Krylov or Newton
        // failure), not a new step size: return to the prescribed one.
        if (steps_since_cut >= int(prm.increase_delay))
          current_dt = std::min(4 * current_dt, prm.initial_dt);
        return true;
      }
    if (error < 0)
      return true;
    const double c0   = std::pow(1. / std::max(error, 1e-12), 0.5);
    double       rho  = std::pow(c0, 0.6) * std::pow(c_prev, -0.2);
    rho               = 1 + std::atan(rho - 1);
    const bool ok     = rho >= 0.81;
    double     factor = std::clamp(rho, 0.1, 10.);
    if (steps_since_cut < int(prm.increase_delay))
      factor = std::min(factor, 1.);
    current_dt = std::clamp(current_dt * factor, prm.min_dt, prm.max_dt);
    if (ok)
      c_prev = c0;
    else
      steps_since_cut = std::min(steps_since_cut, 0);
    return ok;
  }


  bool
  StepSizeController::limit(const double largest)
  {
    if (!(largest < current_dt))
      return false;
    current_dt = std::max(largest, prm.min_dt);
    return true;
  }


  bool
  StepSizeController::reject_failure()
  {
    steps_since_cut = 0;
    if (current_dt * 0.25 < prm.min_dt)
      return false;
    current_dt *= 0.25;
    return true;
  }


  void
  StepSizeController::save(Checkpoint &c, const std::string &prefix) const
  {
    c.scalars[prefix + ".dt"]              = current_dt;
    c.scalars[prefix + ".filter_value"]    = c_prev;
    c.scalars[prefix + ".steps_since_cut"] = steps_since_cut;
  }


  void
  StepSizeController::load(const Checkpoint &c, const std::string &prefix)
  {
    current_dt      = c.scalar(prefix + ".dt");
    c_prev          = c.scalar(prefix + ".filter_value");
    steps_since_cut = c.scalar(prefix + ".steps_since_cut");
  }
} // namespace vesicle_iga
