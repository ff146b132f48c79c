#include <vesicle_iga/base/fault_injection.h>
#include <vesicle_iga/base/solver_failure.h>
#include <vesicle_iga/solvers/newton.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace vesicle_iga
{
  using namespace dealii;

  void
  NewtonParameters::declare(ParameterHandler  &prm,
                            const std::string &default_max_iterations,
                            const std::string &default_relative_tolerance,
                            const std::string &default_absolute_tolerance)
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
                      "1",
                      Patterns::Integer(1),
                      "1: a new Jacobian every Newton iteration; k > 1: the "
                      "Jacobian (and its preconditioner) is kept for k "
                      "iterations (lagged Jacobian).");
    prm.leave_subsection();
  }


  void
  NewtonParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    max_iterations     = prm.get_integer("Max iterations");
    relative_tolerance = prm.get_double("Relative tolerance");
    absolute_tolerance = prm.get_double("Absolute tolerance");
    jacobian_interval  = prm.get_integer("Jacobian interval");
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


    /// x += K^{-1} (-R); counts the correction. R is overwritten.
    void
    correct(JacobianSolver                &linear,
            TrilinosWrappers::MPI::Vector &residual,
            TrilinosWrappers::MPI::Vector &x,
            NewtonReport                  &report)
    {
      TrilinosWrappers::MPI::Vector increment(x);
      residual *= -1.;
      increment                 = 0;
      const LinearSolveResult r = linear.solve(increment, residual);
      report.krylov_iterations += r.iterations;
      report.linear_residual = r.residual;
      ++report.iterations;
      if (!std::isfinite(increment.l2_norm()))
        throw SolverFailure(
          describe("the Newton update is not finite", report));
      x += increment;
    }
  } // namespace


  NewtonReport
  NewtonSolver::solve(NonlinearProblem              &problem,
                      TrilinosWrappers::MPI::Vector &x) const
  {
    NewtonReport                  report;
    TrilinosWrappers::MPI::Vector residual(x);
    JacobianSolver               &linear = problem.jacobian_solver();
    problem.assemble(x, &residual, true);
    linear.matrix_changed(true);
    unsigned int jacobian_age = 0;
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
        if (it > 0 && ++jacobian_age >= parameters.jacobian_interval)
          {
            problem.assemble(x, nullptr, true);
            linear.matrix_changed(false);
            jacobian_age = 0;
          }
        correct(linear, residual, x, report);
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
    report.initial_residual = residual.l2_norm();
    correct(linear, residual, x, report);
    return report;
  }
} // namespace vesicle_iga
