#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <vesicle_iga/base/run_context.h>
#include <vesicle_iga/io/checkpoint.h>
#include <vesicle_iga/io/time_series.h>
#include <vesicle_iga/time/step_size_controller.h>

#include <functional>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace vesicle_iga
{
  /// What solving one step took.
  struct StepReport
  {
    unsigned int newton_iterations = 0, krylov_iterations = 0;
    /// Values of the problem's step_columns().
    std::vector<double> counters;
  };

  /// What the time loop knows of an accepted step, passed to monitors and
  /// stationarity criteria.
  struct StepInfo
  {
    unsigned int step = 0;
    double       time = 0, dt = 0;
    /// dt has reached Max dt (or is fixed): the step no longer limits how
    /// fast the solution may change.
    bool       dt_at_maximum = false;
    StepReport report;
  };


  /**
   * What the time loop advances: a model whose step is solved (possibly by
   * several Newton solves, e.g. inside the modified ALM), checked, and then
   * accepted or rejected.
   */
  class TimeDependentProblem
  {
  public:
    virtual ~TimeDependentProblem() = default;
    virtual double
    time() const = 0;
    /// Extra per-step counters: (time-series column, progress label).
    virtual std::vector<std::pair<std::string, std::string>>
    step_columns() const
    {
      return {};
    }
    /// Solve the step from time() to time() + dt without accepting it;
    /// throws SolverFailure.
    virtual StepReport
    solve_step(const double dt)
      = 0;
    /// Weighted RMS norm of the local error estimate (N5) of the solved
    /// step; < 0: none.
    virtual double
    local_error(const double /*atol*/, const double /*rtol*/) const
    {
      return -1;
    }
    virtual void
    accept_step()
      = 0;
    /// The longest step the problem can take from time() before its step
    /// matrix turns singular by a linear instability it knows of (infinity:
    /// none); the loop takes no longer step.
    virtual double
    largest_step() const
    {
      return std::numeric_limits<double>::infinity();
    }
    /// The solved step was rejected (the state is still that of time()).
    virtual void
    reject_step()
    {}
  };


  /**
   * A quantity recorded after every accepted step: its time-series columns
   * and, optionally, items of the progress line.
   */
  class Monitor
  {
  public:
    virtual ~Monitor() = default;
    virtual std::vector<std::string>
    columns() const = 0;
    /// Append one value per column to @p row and any " name=value" items
    /// to @p progress.
    virtual void
    measure(const StepInfo      &info,
            std::vector<double> &row,
            std::ostream        &progress)
      = 0;
  };


  /// When a time-dependent run has reached a stationary state.
  class StationarityCriterion
  {
  public:
    virtual ~StationarityCriterion() = default;
    /// Checked after the monitors of every accepted step.
    virtual bool
    stationary(const StepInfo &info)
      = 0;
    /// Printed when it fires.
    virtual std::string
    message(const StepInfo &info) const = 0;
    /// Printed at the end of a run in which it never fired (empty: nothing).
    virtual std::string
    not_reached_message(const StepInfo & /*info*/) const
    {
      return "";
    }
  };


  /// The step the loop takes with the controller's @p dt and @p remaining
  /// time to End time: @p remaining if it is at most dt (to round-off), half
  /// of it if it is below 2 dt (no sliver of a last step), else dt.
  double
  final_step_size(const double dt, const double remaining);


  /**
   * The one time loop of every time-dependent study (doc/engine.md): step
   * size control (fixed, growing or adaptive, StepSizeController), solve,
   * accept or reject, monitors into time-series.csv and the progress line
   * on rank 0, VTU and checkpoints at their intervals, stationarity
   * criteria, restart from a checkpoint (every registered object loads
   * itself), and on a failure that dt can no longer avoid a final
   * checkpoint of the last accepted state and one SolverFailure that says
   * where the run stopped and what it kept.
   *
   * Parameters (subsection "Time stepping" of a study): End time, Max steps,
   * the step control of StepSizeController, Checkpoint interval, VTU
   * interval, Restart from.
   */
  class TimeLoop
  {
  public:
    struct Parameters
    {
      double                         end_time  = 1;
      unsigned int                   max_steps = 100000;
      StepSizeController::Parameters step;
      unsigned int                   checkpoint_interval = 10;
      unsigned int                   vtu_interval        = 0;
      std::string                    restart_file;

      struct Defaults
      {
        std::string step_control, initial_dt, max_dt, end_time;
        std::string checkpoint_interval = "10";
      };
      /// Entries of the current subsection.
      static void
      declare(dealii::ParameterHandler &prm, const Defaults &defaults);
      void
      parse(dealii::ParameterHandler &prm, const std::string &section);
    };

    TimeLoop(const Parameters    &parameters,
             const RunContext    &context,
             dealii::TimerOutput &timer);

    /// An object saved in checkpoints under @p prefix (and loaded on
    /// restart).
    void
    add_checkpointable(const std::string &prefix, Checkpointable &object);
    void
    add_monitor(Monitor &monitor);
    void
    add_stationarity_criterion(StationarityCriterion &criterion);
    /// Writes the fields of step n (VTU and friends); without it, nothing.
    void
    set_output(const std::function<void(unsigned int)> &writer);
    /// The time-series file (default time-series.csv); none for "".
    void
    set_time_series_name(const std::string &name)
    {
      series_name = name;
    }
    /// Whether checkpoints are written (default true).
    void
    enable_checkpoints(const bool on)
    {
      checkpoints = on;
    }

    /// Load every registered object and the loop's own state from
    /// 'Restart from' if it is set; returns whether it did.
    bool
    restore();
    /// Run until End time, Max steps or a stationarity criterion.
    void
    run(TimeDependentProblem &problem);

    unsigned int
    step() const
    {
      return step_number;
    }
    double
    next_dt() const
    {
      return controller.dt();
    }
    /// Whether a stationarity criterion fired.
    bool
    stopped_stationary() const
    {
      return stationary;
    }

  private:
    std::vector<std::string>
    series_columns(const TimeDependentProblem &problem) const;
    /// Solves until a step is accepted; throws when dt reaches its minimum.
    StepInfo
    take_step(TimeDependentProblem &problem);
    void
    record(const StepInfo &info, TimeDependentProblem &problem);
    void
    write_checkpoint() const;
    /// After a signal (InterruptHandler): checkpoint and RunInterrupted.
    void
    stop_if_interrupted(const StepInfo &info) const;

    const Parameters                                      parameters;
    const RunContext                                     &context;
    dealii::TimerOutput                                  &timer;
    StepSizeController                                    controller;
    std::vector<std::pair<std::string, Checkpointable *>> objects;
    std::vector<Monitor *>                                monitors;
    std::vector<StationarityCriterion *>                  criteria;
    std::function<void(unsigned int)>                     output;
    std::string series_name = "time-series.csv";
    bool        checkpoints = true, restarted = false, stationary = false;
    /// Whether the note on a step cut by TimeDependentProblem::largest_step
    /// has been printed (once per run).
    bool                              limit_noted = false;
    unsigned int                      step_number = 0, rejected = 0;
    std::unique_ptr<TimeSeriesWriter> series;
  };
} // namespace vesicle_iga
