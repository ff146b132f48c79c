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
    std::function<void()>                 hook,
    std::function<double()>               key)
  {
    AssertThrow(reuse_policy != Reuse::across_steps || key,
                ExcMessage("Reuse::across_steps needs a step key"));
    caller_preconditioner = std::move(preconditioner);
    reuse                 = reuse_policy;
    before_setup          = hook;
    step_key              = key;
    stale                 = true;
  }


  void
  JacobianSolver::count_correction()
  {
    if (jacobian_corrections)
      ++*jacobian_corrections;
  }


  void
  JacobianSolver::matrix_changed(const bool first_of_solve, const double scale)
  {
    jacobian_corrections = 0;
    jacobian_scale       = scale;
    switch (reuse)
      {
        case Reuse::every_matrix:
          stale = true;
          break;
        case Reuse::while_effective:
          stale = stale || first_of_solve;
          break;
        case Reuse::across_steps:
          stale = stale || step_key() != key_at_setup;
          break;
      }
  }


  LinearSolveResult
  JacobianSolver::solve(TrilinosWrappers::MPI::Vector       &x,
                        const TrilinosWrappers::MPI::Vector &b,
                        const double                         tolerance)
  {
    check_input(!parameters.uses_caller_preconditioner()
                  || caller_preconditioner,
                "Linear solver/Method",
                parameters.method,
                "a method this study offers (gmres-mg and cg-mg serve the "
                "phase-field solvers, fgmres-block the flow solver)");
    // A preconditioner kept from an earlier matrix that fails is built for
    // this matrix and the solve is tried once more before the failure
    // counts (which would cost the time step a smaller step size).
    const bool kept = caller_preconditioner && !stale;
    if (!kept)
      return solve_once(x, b, tolerance);
    const TrilinosWrappers::MPI::Vector guess(x);
    try
      {
        return solve_once(x, b, tolerance);
      }
    catch (const SolverFailure &)
      {
        x = guess;
        return solve_once(x, b, tolerance);
      }
  }


  LinearSolveResult
  JacobianSolver::solve_once(TrilinosWrappers::MPI::Vector       &x,
                             const TrilinosWrappers::MPI::Vector &b,
                             const double                         tolerance)
  {
    std::optional<TimerOutput::Scope> scope;
    if (caller_preconditioner && stale)
      {
        if (timer)
          scope.emplace(*timer, "preconditioner");
        if (before_setup)
          before_setup();
        caller_preconditioner->initialize(jacobian);
        stale = false;
        first_iterations.reset();
        extra_iterations = 0;
        key_at_setup     = step_key ? step_key() : 0.;
      }
    scope.reset();
    if (timer)
      scope.emplace(*timer, "linear solve");
    LinearSolveResult result;
    try
      {
        LinearSolverParameters this_solve = parameters;
        if (tolerance > 0)
          this_solve.tolerance = tolerance;
        result = solve_linear_system(this_solve,
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
        stale = true;
        throw SolverFailure(e.what());
      }
    // A rebuild pays when it saves more than its own cost. The phase-field
    // multigrid costs about two solves to build: rebuilt when a solve
    // needs more than 2 n_1 + 5 iterations. The coupled flow blocks kept
    // across steps: rebuilt once the iterations spent beyond n_1 since the
    // build add up to about a build's cost (35-45 FGMRES iterations on the
    // vesicle studies; a growth rule fired on counts as small as 3 -> 9
    // and rebuilt at every step, doc/hydrodynamics.md).
    if (!first_iterations)
      first_iterations = result.iterations;
    else if (reuse == Reuse::across_steps)
      {
        extra_iterations += result.iterations > *first_iterations ?
                              result.iterations - *first_iterations :
                              0;
        if (extra_iterations > parameters.rebuild_extra_iterations)
          stale = true;
      }
    else if (reuse == Reuse::while_effective
             && result.iterations > 2 * *first_iterations + 5)
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
