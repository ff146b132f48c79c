#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <vesicle_iga/base/fault_injection.h>
#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/base/interrupt.h>
#include <vesicle_iga/base/solver_failure.h>
#include <vesicle_iga/time/time_loop.h>

#include <sstream>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    /// Version of the checkpoint layout (names and meaning of the entries);
    /// raised whenever a Checkpointable changes what it writes.
    /// 3: vectors carry the record of their discretisation (format 2
    /// files, without it, are still read; their sizes are checked).
    /// 4: the fields are stored apart from the small vectors (index
    /// "field_names"), so that only rank 0 holds them (format 2 and 3 files
    /// are still read).
    const double checkpoint_format_version = 4;
  } // namespace

  void
  TimeLoop::Parameters::declare(ParameterHandler &prm, const Defaults &d)
  {
    prm.declare_entry("End time",
                      d.end_time,
                      Patterns::Double(0),
                      "The run ends at this time (or earlier: Max steps, a "
                      "stationary state).");
    prm.declare_entry("Max steps",
                      "100000",
                      Patterns::Integer(1),
                      "Upper bound on the number of the last accepted "
                      "step, counted from the start of the run (a restart "
                      "continues the count of its checkpoint).");
    StepSizeController::Parameters::declare(prm,
                                            d.step_control,
                                            d.initial_dt,
                                            d.max_dt);
    prm.declare_entry("Checkpoint interval",
                      d.checkpoint_interval,
                      Patterns::Integer(0),
                      "Write <Output directory>/checkpoint.h5 every N "
                      "accepted steps (0: only at the end and when the run "
                      "fails); it holds everything a restart needs.");
    prm.declare_entry("VTU interval",
                      "0",
                      Patterns::Integer(0),
                      "Write the fields every N accepted steps (0: the "
                      "final state only).");
    prm.declare_entry("Restart from",
                      "",
                      Patterns::Anything(),
                      "A checkpoint.h5 of a run of this study with the same "
                      "mesh, degree and fields (any number of ranks) to "
                      "continue from; time-series.csv keeps its rows up to "
                      "the checkpoint's step. Empty: start from the initial "
                      "state.");
  }


  void
  TimeLoop::Parameters::parse(ParameterHandler &prm, const std::string &section)
  {
    end_time            = prm.get_double("End time");
    max_steps           = prm.get_integer("Max steps");
    checkpoint_interval = prm.get_integer("Checkpoint interval");
    vtu_interval        = prm.get_integer("VTU interval");
    restart_file        = prm.get("Restart from");
    step.parse(prm, section);
    check_input(end_time >= step.min_dt,
                section + "/End time",
                value_text(end_time),
                "at least Min dt = " + value_text(step.min_dt)
                  + " (no step may be shorter than Min dt)");
  }


  TimeLoop::TimeLoop(const Parameters &parameters,
                     const RunContext &context,
                     TimerOutput      &timer)
    : parameters(parameters)
    , context(context)
    , timer(timer)
    , controller(parameters.step)
  {}


  void
  TimeLoop::add_checkpointable(const std::string &prefix,
                               Checkpointable    &object)
  {
    objects.emplace_back(prefix, &object);
  }


  void
  TimeLoop::add_monitor(Monitor &monitor)
  {
    monitors.push_back(&monitor);
  }


  void
  TimeLoop::add_stationarity_criterion(StationarityCriterion &criterion)
  {
    criteria.push_back(&criterion);
  }


  void
  TimeLoop::set_output(const std::function<void(unsigned int)> &writer)
  {
    output = writer;
  }


  bool
  TimeLoop::restore()
  {
    if (parameters.restart_file.empty())
      return false;
    const Checkpoint c
      = Checkpoint::read(parameters.restart_file, context.communicator);
    const double version = c.scalar("time_loop.format_version");
    check_input(version >= 2 && version <= checkpoint_format_version,
                "Restart from",
                parameters.restart_file,
                "a checkpoint of format 2 to "
                  + value_text(checkpoint_format_version) + " (this one has "
                  + value_text(version) + ")");
    step_number = static_cast<unsigned int>(c.scalar("time_loop.step"));
    controller.load(c, "time_loop.controller");
    for (auto &[prefix, object] : objects)
      object->load(c, prefix);
    restarted = true;
    return true;
  }


  void
  TimeLoop::write_checkpoint() const
  {
    TimerOutput::Scope t(timer, "output");
    Checkpoint         c;
    c.scalars["time_loop.format_version"] = checkpoint_format_version;
    c.scalars["time_loop.step"]           = step_number;
    controller.save(c, "time_loop.controller");
    for (const auto &[prefix, object] : objects)
      object->save(c, prefix);
    c.write(context.output_directory + "/checkpoint.h5", context.communicator);
    for (const auto &[prefix, object] : objects)
      object->drop_unsaved_state();
  }


  std::vector<std::string>
  TimeLoop::series_columns(const TimeDependentProblem &problem) const
  {
    std::vector<std::string> columns
      = {"step", "t", "dt", "newton_iterations", "krylov_iterations"};
    for (const auto &c : problem.step_columns())
      columns.push_back(c.first);
    columns.emplace_back("rejected_steps");
    for (const auto *m : monitors)
      for (const auto &c : m->columns())
        columns.push_back(c);
    return columns;
  }


  double
  final_step_size(const double dt, const double remaining)
  {
    // Up to round-off of the accumulated time (fixed steps that divide
    // the interval), the step ends the run.
    if (remaining <= dt * (1 + 1e-8))
      return remaining;
    // Two equal steps rather than a full one and a sliver: a step far
    // below its predecessor divides the relaxation terms of the global
    // multipliers of (H13) by it (a vesicle's lambda_g jumped from -0.2 to
    // -2.6 in a last step of 5e-4 after steps of 0.05).
    if (remaining < 2 * dt)
      return remaining / 2;
    return dt;
  }


  StepInfo
  TimeLoop::take_step(TimeDependentProblem &problem)
  {
    rejected = 0;
    // What a checkpoint written after a failed step stores: the controller
    // as the last accepted step left it, so that a restart repeats this
    // step as the uninterrupted run took it (not with the cut dt).
    const StepSizeController at_start = controller;
    for (;;)
      {
        const double t = problem.time();
        // A step past the problem's stability limit meets a singular step
        // matrix (a NaN from the preconditioner, a diverging Newton) and
        // would be cut only after failing.
        if (controller.limit(problem.largest_step()) && !limit_noted)
          {
            limit_noted = true;
            context.pcout << "  Note: dt cut to " << controller.dt()
                          << " at t = " << t
                          << " by the problem's stability limit (printed "
                             "once)."
                          << std::endl;
          }
        const double dt
          = final_step_size(controller.dt(), parameters.end_time - t);
        StepReport report;
        try
          {
            report = problem.solve_step(dt);
          }
        catch (const SolverFailure &failure)
          {
            ++rejected;
            problem.reject_step();
            if (context.print_details)
              context.pcout << "  step from t=" << t << " with dt=" << dt
                            << " failed: " << failure.what() << std::endl;
            if (controller.reject_failure())
              continue;
            controller = at_start;
            if (checkpoints)
              write_checkpoint();
            std::ostringstream s;
            s << "The step from t = " << t << " failed with dt = " << dt
              << " and dt cannot be cut below Min dt = "
              << parameters.step.min_dt << ": " << failure.what()
              << ". The run stops at step " << step_number
              << "; the time series up to it is in " << context.output_directory
              << "/" << series_name;
            if (checkpoints)
              s << " and the last accepted state in "
                << context.output_directory
                << "/checkpoint.h5 ('Restart from' continues from it)";
            throw SolverFailure(s.str());
          }
        const double error
          = controller.adaptive() ?
              problem.local_error(parameters.step.atol, parameters.step.rtol) :
              -1;
        if (!controller.accept(error))
          {
            ++rejected;
            problem.reject_step();
            continue;
          }
        problem.accept_step();
        ++step_number;
        return {
          step_number, problem.time(), dt, controller.at_maximum(), report};
      }
  }


  void
  TimeLoop::record(const StepInfo &info, TimeDependentProblem &problem)
  {
    std::vector<double> row = {double(info.step),
                               info.time,
                               info.dt,
                               double(info.report.newton_iterations),
                               double(info.report.krylov_iterations)};
    std::ostringstream  progress;
    // Iteration counts only with 'Print details': they move with round-off
    // (a residual on either side of a tolerance), the rest does not.
    progress << "step " << info.step << " t=" << info.time << " dt=" << info.dt;
    if (context.print_details)
      progress << " newton=" << info.report.newton_iterations
               << " krylov=" << info.report.krylov_iterations;
    const auto counters = problem.step_columns();
    for (unsigned int k = 0; k < counters.size(); ++k)
      {
        row.push_back(info.report.counters[k]);
        if (context.print_details)
          progress << " " << counters[k].second << "="
                   << info.report.counters[k];
      }
    row.push_back(rejected);
    for (auto *m : monitors)
      m->measure(info, row, progress);
    if (series)
      series->add_row(row);
    context.pcout << progress.str() << std::endl;
    if (output && parameters.vtu_interval > 0
        && info.step % parameters.vtu_interval == 0)
      {
        TimerOutput::Scope t(timer, "output");
        output(info.step);
      }
    if (checkpoints && parameters.checkpoint_interval > 0
        && info.step % parameters.checkpoint_interval == 0)
      write_checkpoint();
  }


  void
  TimeLoop::stop_if_interrupted(const StepInfo &info) const
  {
    // Every rank stops after the same step, whichever ranks the signal
    // reached.
    const int signal = Utilities::MPI::max(InterruptHandler::signal_received(),
                                           context.communicator);
    if (signal == 0)
      return;
    if (checkpoints)
      write_checkpoint();
    std::ostringstream s;
    s << "interrupted by " << InterruptHandler::name(signal) << " after step "
      << info.step << " (t = " << info.time
      << "): the time series up to it is in " << context.output_directory << "/"
      << series_name;
    if (checkpoints)
      s << " and the state in " << context.output_directory
        << "/checkpoint.h5; continue with 'Restart from = "
        << context.output_directory << "/checkpoint.h5'";
    throw RunInterrupted(s.str());
  }


  void
  TimeLoop::run(TimeDependentProblem &problem)
  {
    if (!series_name.empty())
      series = std::make_unique<TimeSeriesWriter>(
        context.output_directory + "/" + series_name,
        series_columns(problem),
        context.communicator,
        restarted ? long(step_number) : -1);
    if (output && parameters.vtu_interval > 0 && !restarted)
      {
        TimerOutput::Scope t(timer, "output");
        output(0);
      }
    const InterruptHandler interrupt;
    StepInfo               last{step_number, problem.time(), 0., false, {}};
    while (problem.time() < parameters.end_time * (1 - 1e-12)
           && step_number < parameters.max_steps && !stationary)
      {
        last = take_step(problem);
        record(last, problem);
        if (Utilities::MPI::this_mpi_process(context.communicator) == 1
            && fault_requested("rank-1-throws"))
          throw std::runtime_error("test fault: rank 1 fails after step "
                                   + std::to_string(step_number));
        stop_if_interrupted(last);
        for (auto *c : criteria)
          if (c->stationary(last))
            {
              context.pcout << c->message(last) << std::endl;
              stationary = true;
              break;
            }
      }
    if (output
        && (parameters.vtu_interval == 0
            || step_number % parameters.vtu_interval != 0))
      {
        TimerOutput::Scope t(timer, "output");
        output(step_number);
      }
    if (checkpoints)
      write_checkpoint();
    if (step_number >= parameters.max_steps
        && problem.time() < parameters.end_time * (1 - 1e-12))
      context.pcout << "stopped at step " << step_number
                    << " by 'Max steps' = " << parameters.max_steps
                    << " (counted from the start of the run), at t = "
                    << problem.time()
                    << " before 'End time' = " << parameters.end_time
                    << std::endl;
    if (!stationary)
      for (const auto *c : criteria)
        {
          const std::string m = c->not_reached_message(last);
          if (!m.empty())
            context.pcout << m << std::endl;
        }
  }
} // namespace vesicle_iga
