#pragma once

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/solvers/jacobian_solver.h>

#include <string>

namespace vesicle_iga
{
  /**
   * A nonlinear system R(x) = 0 as Newton's method sees it: the residual
   * and the Jacobian K = dR/dx (into the matrix of its JacobianSolver), in
   * one assembly pass when both are wanted.
   */
  class NonlinearProblem
  {
  public:
    virtual ~NonlinearProblem() = default;
    /// R(x) into @p residual (if not null) and, if @p jacobian, K(x) into
    /// jacobian_solver().matrix().
    virtual void
    assemble(const dealii::TrilinosWrappers::MPI::Vector &x,
             dealii::TrilinosWrappers::MPI::Vector       *residual,
             const bool                                   jacobian)
      = 0;
    virtual JacobianSolver &
    jacobian_solver()
      = 0;
  };


  struct NewtonParameters
  {
    unsigned int max_iterations     = 12;
    double       relative_tolerance = 1e-8;
    double       absolute_tolerance = 1e-10;
    /// 1: a new Jacobian every iteration; k > 1: the Jacobian is rebuilt
    /// every k iterations (lagged Jacobian, modified Newton).
    unsigned int jacobian_interval = 1;

    /// Subsection "Newton" with the given defaults.
    static void
    declare(dealii::ParameterHandler &prm,
            const std::string        &default_max_iterations,
            const std::string        &default_relative_tolerance,
            const std::string        &default_absolute_tolerance);
    void
    parse(dealii::ParameterHandler &prm);
  };


  /// What a Newton solve took.
  struct NewtonReport
  {
    unsigned int iterations        = 0; // corrections
    unsigned int krylov_iterations = 0;
    double       initial_residual = 0, residual = 0;
    /// Relative residual of the last Krylov solve.
    double linear_residual = 0;
  };


  /**
   * Newton's method for a NonlinearProblem: converged when |R| <=
   * max(atol, rtol |R_0|) (l2 norms, R_0 at the initial guess). The first
   * residual comes with the Jacobian in one pass (an initial guess is rarely
   * converged); later residuals come alone, and the Jacobian only when a
   * correction is needed, so that no Jacobian is assembled on the
   * converged iteration. Failure (no convergence in max_iterations, a
   * residual that is not finite, a Krylov failure) throws SolverFailure;
   * @p x is then meaningless.
   */
  class NewtonSolver
  {
  public:
    explicit NewtonSolver(const NewtonParameters &parameters)
      : parameters(parameters)
    {}

    NewtonReport
    solve(NonlinearProblem                      &problem,
          dealii::TrilinosWrappers::MPI::Vector &x) const;

    /// A linear problem: one residual and Jacobian pass, one correction.
    NewtonReport
    solve_linear(NonlinearProblem                      &problem,
                 dealii::TrilinosWrappers::MPI::Vector &x) const;

    const NewtonParameters &
    get_parameters() const
    {
      return parameters;
    }

  private:
    const NewtonParameters parameters;
  };
} // namespace vesicle_iga
