#pragma once

#include <deal.II/base/timer.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/solvers/linear_solver.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace vesicle_iga
{
  /**
   * The linear systems of Newton's method, K dx = b: the Jacobian matrix,
   * the Krylov method and preconditioner of LinearSolverParameters and the
   * policy for rebuilding a caller's preconditioner (spline multigrid,
   * velocity-pressure blocks):
   *  - every matrix: rebuilt for every new Jacobian (the flow blocks,
   *    which depend on the state through their Schur approximation);
   *  - while effective: rebuilt for the first Jacobian of a Newton solve
   *    and when a solve needs more than 2 n_1 + 5 iterations, n_1 the count
   *    right after the last rebuild (the multigrid of the phase field:
   *    the matrix changes little between Newton iterations and the set-up
   *    costs about two Krylov solves);
   *  - across steps: kept from one Newton solve (time step) to the next
   *    as long as the caller's step key (the rate factor of the time
   *    integrator, which changes with the step size) is the one it was
   *    built with, and rebuilt once the solves since the build have
   *    needed, in sum, LinearSolverParameters::rebuild_extra_iterations
   *    more iterations than n_1 (the coupled vesicle-flow tangent at a
   *    fixed step: its set-up costs as much as tens of iterations).
   * A Krylov failure with a preconditioner built for an earlier matrix is
   * retried once with one built for the current matrix; a failure then
   * throws SolverFailure.
   */
  class JacobianSolver
  {
  public:
    enum class Reuse
    {
      every_matrix,
      while_effective,
      across_steps
    };

    /// @p timer (optional): sections "preconditioner" and "linear solve".
    JacobianSolver(
      const LinearSolverParameters                    &parameters,
      const dealii::AffineConstraints<double>         &increment_constraints,
      const dealii::TrilinosWrappers::SparsityPattern &sparsity,
      dealii::TimerOutput                             *timer = nullptr);

    /// A preconditioner of the caller's (required by the gmres-mg, cg-mg and
    /// fgmres-block methods), its rebuild policy, what must happen
    /// before each rebuild (e.g. the lumped operators of the flow blocks)
    /// and, for Reuse::across_steps, the step key.
    void
    set_preconditioner(std::unique_ptr<MatrixPreconditioner> preconditioner,
                       const Reuse                           reuse,
                       std::function<void()>                 before_setup = {},
                       std::function<double()>               step_key     = {});

    dealii::TrilinosWrappers::SparseMatrix &
    matrix()
    {
      return jacobian;
    }
    /// A new Jacobian is in matrix(); @p first_of_solve: the first of a
    /// Newton solve; @p scale: NonlinearProblem::jacobian_scale() at its
    /// assembly.
    void
    matrix_changed(const bool first_of_solve, const double scale = 0);

    /// Newton corrections made with the Jacobian in matrix() since it was
    /// assembled; empty while matrix() holds none that a later Newton solve
    /// may keep (before the first, after forget_jacobian()).
    std::optional<unsigned int>
    corrections_with_jacobian() const
    {
      return jacobian_corrections;
    }
    /// The scale given with the last matrix_changed().
    double
    scale_of_jacobian() const
    {
      return jacobian_scale;
    }
    /// A Newton correction was made with matrix().
    void
    count_correction();
    /// matrix() is no Jacobian to keep (a failed solve, a new state layout).
    void
    forget_jacobian()
    {
      jacobian_corrections.reset();
    }

    /// Solve K x = b (x: initial guess in, solution out, constrained
    /// entries set); throws SolverFailure. @p tolerance > 0: the relative
    /// tolerance of this solve instead of the parameter's (a Newton
    /// correction that can end its solve, NewtonParameters).
    LinearSolveResult
    solve(dealii::TrilinosWrappers::MPI::Vector       &x,
          const dealii::TrilinosWrappers::MPI::Vector &b,
          const double                                 tolerance = 0);

    /// The relative tolerance of a Krylov solve ("Linear solver/Tolerance").
    double
    tolerance() const
    {
      return parameters.tolerance;
    }

    const dealii::AffineConstraints<double> &
    constraints() const
    {
      return increment_constraints;
    }
    /// One line for logs.
    std::string
    description() const;
    MatrixPreconditioner *
    preconditioner()
    {
      return caller_preconditioner.get();
    }

  private:
    /// One attempt: builds the preconditioner if it is stale (a failure
    /// marks it so), then solves.
    LinearSolveResult
    solve_once(dealii::TrilinosWrappers::MPI::Vector       &x,
               const dealii::TrilinosWrappers::MPI::Vector &b,
               const double                                 tolerance);

    const LinearSolverParameters             parameters;
    const dealii::AffineConstraints<double> &increment_constraints;
    dealii::TimerOutput                     *timer;
    dealii::TrilinosWrappers::SparseMatrix   jacobian;
    std::unique_ptr<MatrixPreconditioner>    caller_preconditioner;
    Reuse                                    reuse = Reuse::every_matrix;
    std::function<void()>                    before_setup;
    std::function<double()>                  step_key;
    double                                   key_at_setup = 0;
    bool                                     stale        = true;
    /// The count of the first solve after the last build, once made.
    std::optional<unsigned int> first_iterations;
    unsigned int                extra_iterations = 0;
    std::optional<unsigned int> jacobian_corrections;
    double                      jacobian_scale = 0;
  };
} // namespace vesicle_iga
