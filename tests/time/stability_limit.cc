// The step limit of a known linear instability (time/time_loop.h,
// TimeDependentProblem::largest_step) and the one of Part H's bulk phases
// (physics/bulk_stability.h).
//
// BulkStability: sigma(k) = eta s (-lambda_g - B s / eps), s = eps k^2 + 2 /
// eps, maximised over k in closed form; checked against a scan of 2e6 wave
// numbers (relative 1e-6) for lambda_g in each regime (stable above -2 B /
// eps^2; the k = 0 mode fastest between -4 B / eps^2 and -2 B / eps^2; an
// interior k below), and the singular step alpha_m / (alpha_f gamma
// sigma) against the values the failing first steps of the bench showed
// (doc/hydrodynamics.md, "What is missing": lambda_g(0) = -54 at eps =
// 0.125 gives 4.1e-3, where a step of 1e-3 passed; -396 gives 7.7e-5,
// where 1e-3 and 2.5e-4 failed and 6.25e-5 passed).
//
// TimeLoop: a problem y' = -y by backward Euler (exact per step: y_{n+1} =
// y_n / (1 + dt)) whose largest_step() is 0.01 before t = 0.045; with
// fixed steps of 0.02 the loop takes 0.01 there (steps 1-5) and 0.02 after,
// prints its note once and ends at T = 0.1 with y the product of the step
// factors (checked to 1e-15). The dt sequence is set by the rule alone
// (no tolerance is involved), so it is printed.
// It can fail: without the cap in TimeLoop::take_step the first step is
// 0.02 and the loop's verdict reads FAILED.

#include <deal.II/base/mpi.h>

#include <vesicle_iga/base/run_context.h>
#include <vesicle_iga/physics/bulk_stability.h>
#include <vesicle_iga/time/generalized_alpha.h>
#include <vesicle_iga/time/time_loop.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "../root_output.h"

using namespace vesicle_iga;

namespace
{
  /// y' = -y, backward Euler, with a stability limit before t = 0.045.
  class DecayWithLimit : public TimeDependentProblem
  {
  public:
    double
    time() const override
    {
      return t;
    }
    StepReport
    solve_step(const double dt) override
    {
      trial = y / (1 + dt);
      step  = dt;
      return {};
    }
    void
    accept_step() override
    {
      y = trial;
      t += step;
      steps.push_back(step);
    }
    double
    largest_step() const override
    {
      return t < 0.045 ? 0.01 : std::numeric_limits<double>::infinity();
    }

    double              t = 0, y = 1, trial = 1, step = 0;
    std::vector<double> steps;
  };
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                            out("output");

  MembraneCoefficients membrane; // Re 5e-3, Ca 1e4: B = 0.02
  membrane.epsilon = 0.125;
  const BulkStability bulk(membrane);
  const double        B = 0.02, eps = 0.125, eta = 0.1;
  bool                scan_ok = true;
  for (const double lambda : {1., -2., -3., -4., -5., -54., -396.})
    {
      double largest = -std::numeric_limits<double>::infinity();
      for (unsigned int j = 0; j <= 2000000; ++j)
        {
          const double k = 200. * j / 2000000;
          const double s = eps * k * k + 2 / eps;
          largest        = std::max(largest, eta * s * (-lambda - B * s / eps));
        }
      scan_ok = scan_ok
                && std::abs(bulk.growth_rate(lambda) - largest)
                     <= 1e-6 * std::abs(largest);
    }
  out << "growth rate against a scan over k (thresholds -2 B / eps^2 = "
      << -2 * B / (eps * eps) << ", -4 B / eps^2 = " << -4 * B / (eps * eps)
      << "): " << verdict(scan_ok) << '\n';
  const GeneralizedAlpha method(0.5);
  out << "stable above -2 B / eps^2 (singular step infinite): "
      << verdict(std::isinf(method.singular_step(bulk.growth_rate(-2.55)))
                 && bulk.growth_rate(-2.55) < 0)
      << '\n';
  out << std::setprecision(2) << "singular step, lambda_g = -54: "
      << method.singular_step(bulk.growth_rate(-54))
      << ", -396: " << method.singular_step(bulk.growth_rate(-396)) << ": "
      << verdict(method.singular_step(bulk.growth_rate(-54)) > 1e-3
                 && method.singular_step(bulk.growth_rate(-396)) < 2.5e-4
                 && method.singular_step(bulk.growth_rate(-396)) > 6.25e-5)
      << '\n';

  // The loop honours largest_step().
  std::ostringstream notes;
  RunContext         context{
    MPI_COMM_WORLD, 1, ".", false, dealii::ConditionalOStream(notes, true)};
  dealii::TimerOutput  timer(notes,
                            dealii::TimerOutput::never,
                            dealii::TimerOutput::wall_times);
  TimeLoop::Parameters parameters;
  parameters.end_time            = 0.1;
  parameters.step.mode           = "fixed";
  parameters.step.initial_dt     = 0.02;
  parameters.step.max_dt         = 0.02;
  parameters.step.min_dt         = 1e-6;
  parameters.checkpoint_interval = 0;
  TimeLoop loop(parameters, context, timer);
  loop.enable_checkpoints(false);
  loop.set_time_series_name("");
  DecayWithLimit problem;
  loop.run(problem);
  double product = 1;
  out << "steps:";
  for (const double dt : problem.steps)
    {
      out << ' ' << dt;
      product /= 1 + dt;
    }
  const std::string text  = notes.str();
  const auto        first = text.find("stability limit");
  out << "\nlimited to 0.01 before t = 0.045, 0.02 after, T reached: "
      << verdict(problem.steps.size() == 8 && problem.steps[0] == 0.01
                 && problem.steps[4] == 0.01 && problem.steps[5] == 0.02
                 && std::abs(problem.t - 0.1) < 1e-14
                 && std::abs(problem.y - product) < 1e-15)
      << "; note printed once: "
      << verdict(first != std::string::npos
                 && text.find("stability limit", first + 1)
                      == std::string::npos)
      << '\n';
}
