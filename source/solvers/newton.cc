#include <vesicle_iga/base/fault_injection.h>
#include <vesicle_iga/base/solver_failure.h>
#include <vesicle_iga/solvers/newton.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>

namespace vesicle_iga
{
  using namespace dealii;

  void
  NewtonParameters::declare(ParameterHandler  &prm,
                            const std::string &default_max_iterations,
                            const std::string &default_relative_tolerance,
                            const std::string &default_absolute_tolerance,
                            const std::string &default_jacobian_interval,
                            const std::string &default_keep_jacobian)
  {
    prm.enter_subsection("Newton");
    prm.declare_entry("Max iterations",
                      default_max_iterations,
                      Patterns::Integer(1),
                      "Newton corrections before the step counts as failed "
                      "(it is then repeated with dt / 4).");
    prm.declare_entry("Relative tolerance",
                      default_relative_tolerance,
                      Patterns::Double(0),
                      "Converged when |R| <= max(absolute tolerance, this "
                      "times |R| at the predictor) (l2 norms).");
    prm.declare_entry("Absolute tolerance",
                      default_absolute_tolerance,
                      Patterns::Double(0),
                      "Residual norm that counts as converged.");
    prm.declare_entry("Jacobian interval",
                      default_jacobian_interval,
                      Patterns::Integer(1),
                      "1: a new Jacobian every Newton iteration; k > 1: a "
                      "Jacobian (and its preconditioner) serves up to k "
                      "corrections (lagged Jacobian, a chord method), fewer "
                      "when one of them reduces the residual by less than "
                      "'Rebuild contraction'.");
    prm.declare_entry("Keep Jacobian",
                      default_keep_jacobian,
                      Patterns::Bool(),
                      "With 'Jacobian interval' > 1: a Newton solve (the "
                      "next ALM iteration, the next time step) starts with "
                      "the Jacobian the last solve left, while it has served "
                      "fewer than 'Jacobian interval' corrections and the "
                      "step size is within 20 % of the one it was assembled "
                      "at, instead of assembling one. Pays where the "
                      "Jacobian costs many residuals (the 3D phase field: "
                      "doc/performance.md). A checkpoint drops it, so a "
                      "restart continues exactly as the run would have.");
    prm.declare_entry("Print iterations",
                      "false",
                      Patterns::Bool(),
                      "Print every Newton iteration on rank 0: the residual "
                      "norm (also relative to the first), the Krylov "
                      "iterations of the correction and whether its Jacobian "
                      "was assembled for it. A diagnostic for hard steps.");
    prm.declare_entry(
      "Krylov tolerance of later corrections",
      "tightened",
      Patterns::Selection("linear|tightened|fitted"),
      "From the second Newton correction on, the Krylov solve can be asked "
      "for the reduction that can end the Newton solve, eta = 0.5 max("
      "absolute tolerance, relative tolerance |R_0|) / |R_k| (R_k the "
      "current residual). linear: every correction to 'Linear solver/"
      "Tolerance'. tightened: eta where it is tighter than that (by at most "
      "a factor 100, not where the solve is still far from its end), so "
      "that the Krylov residual alone does not leave the Newton solve above "
      "its tolerance: with FGMRES to 1e-4 and Newton to 1e-6 the doublet "
      "studies otherwise need a third correction once the vesicles touch, "
      "at 70 Krylov iterations. fitted: also looser, up to 0.1, where the "
      "residual is already close to its target: a third correction that "
      "only has to halve a residual costs 6-8 Krylov iterations instead of "
      "95-170 (doc/hydrodynamics.md, \"Cost per step\"); the solution is "
      "then as accurate as the Newton tolerance says and no more, which "
      "for an ill-conditioned system can be far less accurate than the "
      "linear tolerance would have made it.");
    prm.declare_entry("Rebuild contraction",
                      "0.1",
                      Patterns::Double(0, 1),
                      "A lagged Jacobian is rebuilt when the last correction "
                      "made with it left more than this fraction of the "
                      "residual.");
    prm.leave_subsection();
  }


  void
  NewtonParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    max_iterations      = prm.get_integer("Max iterations");
    relative_tolerance  = prm.get_double("Relative tolerance");
    absolute_tolerance  = prm.get_double("Absolute tolerance");
    jacobian_interval   = prm.get_integer("Jacobian interval");
    keep_jacobian       = prm.get_bool("Keep Jacobian");
    rebuild_contraction = prm.get_double("Rebuild contraction");
    print_iterations    = prm.get_bool("Print iterations");
    {
      const std::string later
        = prm.get("Krylov tolerance of later corrections");
      later_corrections = later == "linear"    ? LaterCorrections::linear :
                          later == "tightened" ? LaterCorrections::tightened :
                                                 LaterCorrections::fitted;
    }
    prm.leave_subsection();
  }


  namespace
  {
    std::string
    describe(const char *what, const NewtonReport &r)
    {
      std::ostringstream s;
      s << "Newton: " << what << " (residual " << r.residual
        << ", initial residual " << r.initial_residual << ", " << r.iterations
        << " corrections)";
      return s.str();
    }


    /// x += K^{-1} (-R); counts the correction. R is overwritten. With
    /// @p print, one line per correction on rank 0.
    void
    correct(JacobianSolver                &linear,
            TrilinosWrappers::MPI::Vector &residual,
            TrilinosWrappers::MPI::Vector &x,
            NewtonReport                  &report,
            const bool                     print,
            const bool                     new_jacobian,
            const double                   tolerance = 0)
    {
      TrilinosWrappers::MPI::Vector increment(x);
      residual *= -1.;
      increment                 = 0;
      const LinearSolveResult r = linear.solve(increment, residual, tolerance);
      report.krylov_iterations += r.iterations;
      report.linear_residual = r.residual;
      ++report.iterations;
      const double dx_norm = increment.l2_norm();
      // |x| only for the diagnostic line (a collective reduction: every
      // rank computes it, rank 0 prints).
      const double x_norm = print ? x.l2_norm() : 0;
      if (print
          && Utilities::MPI::this_mpi_process(x.get_mpi_communicator()) == 0)
        std::cout << "    Newton " << report.iterations << ": |R| "
                  << report.residual << " ("
                  << report.residual / report.initial_residual
                  << " of the first), " << r.iterations
                  << " Krylov iterations to " << r.residual << ", "
                  << (new_jacobian ? "new" : "kept") << " Jacobian, |dx| "
                  << dx_norm << " (" << dx_norm / x_norm << " of |x|)"
                  << std::endl;
      if (!std::isfinite(dx_norm))
        throw SolverFailure(
          describe("the Newton update is not finite", report));
      x += increment;
    }
  } // namespace


  NewtonReport
  NewtonSolver::solve(NonlinearProblem              &problem,
                      TrilinosWrappers::MPI::Vector &x) const
  {
    JacobianSolver &linear = problem.jacobian_solver();
    try
      {
        return iterate(problem, x);
      }
    catch (const SolverFailure &)
      {
        // The retry (a smaller step) starts from a Jacobian of its own.
        linear.forget_jacobian();
        throw;
      }
  }


  double
  NewtonSolver::correction_tolerance(const unsigned int  iteration,
                                     const NewtonReport &report,
                                     const double        linear_tolerance) const
  {
    if (parameters.later_corrections
          == NewtonParameters::LaterCorrections::linear
        || iteration == 0)
      return 0;
    // After this correction the residual is the Krylov residual eta |R_k|
    // plus the nonlinear remainder, which does not depend on eta. For the
    // Newton solve to end, eta |R_k| must be below its target: by 2, for
    // the remainder; tighter than the linear tolerance by no more than
    // 100, where the solve is still far from its end. Solving further buys
    // the Newton solve nothing (if the remainder is above the target
    // another correction follows either way), so "fitted" also loosens to
    // eta (at most 0.1, so that a correction still is one); "tightened"
    // keeps the accuracy of the linear tolerance for the solution.
    const double target
      = std::max(parameters.absolute_tolerance,
                 parameters.relative_tolerance * report.initial_residual);
    const double needed = 0.5 * target / report.residual;
    if (needed < 0.01 * linear_tolerance)
      return 0;
    if (needed < linear_tolerance)
      return needed;
    return parameters.later_corrections
               == NewtonParameters::LaterCorrections::fitted ?
             std::min(needed, 0.1) :
             0;
  }


  NewtonReport
  NewtonSolver::iterate(NonlinearProblem              &problem,
                        TrilinosWrappers::MPI::Vector &x) const
  {
    NewtonReport                  report;
    TrilinosWrappers::MPI::Vector residual(x);
    JacobianSolver               &linear = problem.jacobian_solver();
    const auto                    age    = linear.corrections_with_jacobian();
    // A Jacobian from an earlier solve serves if it has corrections left
    // and was assembled at about this scale (step size): with the rate as
    // unknown, a step 20 % longer changes the stiffness part of
    // alpha_m M + alpha_f gamma dt K by 20 %, and a chord iteration with
    // that error contracts by no better than about 0.2 per correction (a
    // step size that grows by 1.6 per step, as the controller's does early
    // on, made every kept Jacobian a wasted correction).
    const double scale      = problem.jacobian_scale(),
                 kept_scale = linear.scale_of_jacobian();
    const bool same_scale
      = scale == kept_scale
        || (kept_scale != 0 && std::abs(scale / kept_scale - 1) <= 0.2);
    // Whether matrix() is the Jacobian at x.
    bool current = !(parameters.keep_jacobian && age
                     && *age < parameters.jacobian_interval && same_scale);
    problem.assemble(x, &residual, current);
    if (current)
      linear.matrix_changed(true, scale);
    double previous_residual = 0;
    for (unsigned int it = 0;; ++it)
      {
        if (fault_requested("nan-residual"))
          {
            // Test fault: a NaN in the last rank's part only.
            const MPI_Comm comm = residual.get_mpi_communicator();
            if (Utilities::MPI::this_mpi_process(comm) + 1
                  == Utilities::MPI::n_mpi_processes(comm)
                && residual.locally_owned_size() > 0)
              residual[*residual.locally_owned_elements().begin()]
                = std::numeric_limits<double>::quiet_NaN();
            residual.compress(VectorOperation::insert);
          }
        report.residual = residual.l2_norm();
        if (it == 0)
          report.initial_residual = report.residual;
        if (!std::isfinite(report.residual))
          throw SolverFailure(describe("the residual is not finite", report));
        if (report.residual <= std::max(parameters.absolute_tolerance,
                                        parameters.relative_tolerance
                                          * report.initial_residual))
          return report;
        if (it == parameters.max_iterations)
          throw SolverFailure(describe("no convergence", report));
        // A lagged Jacobian is rebuilt when it has served its corrections
        // or when the chord iteration with it contracts too slowly.
        const bool served
          = *linear.corrections_with_jacobian() >= parameters.jacobian_interval;
        const bool slow = it > 0
                          && report.residual > parameters.rebuild_contraction
                                                 * previous_residual;
        const bool assembled = current || served || slow;
        if (!current && (served || slow))
          {
            problem.assemble(x, nullptr, true);
            linear.matrix_changed(it == 0, scale);
          }
        correct(linear,
                residual,
                x,
                report,
                parameters.print_iterations,
                assembled,
                correction_tolerance(it, report, linear.tolerance()));
        linear.count_correction();
        current           = false;
        previous_residual = report.residual;
        problem.assemble(x, &residual, false);
      }
  }


  NewtonReport
  NewtonSolver::solve_linear(NonlinearProblem              &problem,
                             TrilinosWrappers::MPI::Vector &x) const
  {
    NewtonReport                  report;
    TrilinosWrappers::MPI::Vector residual(x);
    JacobianSolver               &linear = problem.jacobian_solver();
    problem.assemble(x, &residual, true);
    linear.matrix_changed(true);
    report.initial_residual = report.residual = residual.l2_norm();
    correct(linear, residual, x, report, parameters.print_iterations, true);
    return report;
  }
} // namespace vesicle_iga
