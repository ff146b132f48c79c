#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/base/solver_failure.h>
#include <vesicle_iga/solvers/jacobian_solver.h>

#include <optional>

namespace vesicle_iga
{
  using namespace dealii;

  JacobianSolver::JacobianSolver(
    const LinearSolverParameters            &parameters,
    const AffineConstraints<double>         &increment_constraints,
    const TrilinosWrappers::SparsityPattern &sparsity,
    TimerOutput                             *timer)
    : parameters(parameters)
    , increment_constraints(increment_constraints)
    , timer(timer)
  {
    jacobian.reinit(sparsity);
  }


  void
  JacobianSolver::set_preconditioner(
    std::unique_ptr<MatrixPreconditioner> preconditioner,
    const Reuse                           reuse_policy,
    std::function<void()>                 hook)
  {
    caller_preconditioner = std::move(preconditioner);
    reuse                 = reuse_policy;
    before_setup          = hook;
    stale                 = true;
  }


  void
  JacobianSolver::matrix_changed(const bool first_of_solve)
  {
    if (reuse == Reuse::every_matrix || first_of_solve)
      stale = true;
  }


  LinearSolveResult
  JacobianSolver::solve(TrilinosWrappers::MPI::Vector       &x,
                        const TrilinosWrappers::MPI::Vector &b)
  {
    check_input(!parameters.uses_caller_preconditioner()
                  || caller_preconditioner,
                "Linear solver/Method",
                parameters.method,
                "a method this study offers (gmres-mg and cg-mg serve the "
                "phase-field solvers, fgmres-block the flow solver)");
    std::optional<TimerOutput::Scope> scope;
    if (caller_preconditioner && stale)
      {
        if (timer)
          scope.emplace(*timer, "preconditioner");
        if (before_setup)
          before_setup();
        caller_preconditioner->initialize(jacobian);
        stale            = false;
        first_iterations = 0;
      }
    scope.reset();
    if (timer)
      scope.emplace(*timer, "linear solve");
    LinearSolveResult result;
    try
      {
        result = solve_linear_system(parameters,
                                     jacobian,
                                     x,
                                     b,
                                     increment_constraints,
                                     caller_preconditioner.get());
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &e)
      {
        throw SolverFailure(e.what());
      }
    if (first_iterations == 0)
      first_iterations = result.iterations;
    else if (reuse == Reuse::while_effective
             && result.iterations > 2 * first_iterations + 5)
      stale = true;
    return result;
  }


  std::string
  JacobianSolver::description() const
  {
    return parameters.method
           + (caller_preconditioner ?
                " with " + caller_preconditioner->description() :
                std::string());
  }
} // namespace vesicle_iga
