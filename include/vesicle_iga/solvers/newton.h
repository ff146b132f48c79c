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
    /// A number the Jacobian scales with that changes between solves (the
    /// step size of a time integrator), 0 if none: a Jacobian kept from an
    /// earlier solve (NewtonParameters::keep_jacobian) serves only while
    /// this has changed by at most 20 % since it was assembled.
    virtual double
    jacobian_scale() const
    {
      return 0;
    }
  };


  struct NewtonParameters
  {
    unsigned int max_iterations     = 12;
    double       relative_tolerance = 1e-8;
    double       absolute_tolerance = 1e-10;
    /// 1: a new Jacobian every iteration; k > 1: a Jacobian serves up to k
    /// corrections (lagged Jacobian, modified Newton), fewer if a
    /// correction with it reduces the residual by less than
    /// rebuild_contraction.
    unsigned int jacobian_interval = 1;
    /// With jacobian_interval > 1: a Newton solve starts with the Jacobian
    /// the last one left (it counts its corrections on) instead of
    /// assembling one at its initial guess.
    bool keep_jacobian = false;
    /// A kept Jacobian is rebuilt when the last correction made with it
    /// left more than this fraction of the residual.
    double rebuild_contraction = 0.1;
    /// One line per correction on rank 0 (a diagnostic).
    bool print_iterations = false;
    /// The Krylov tolerance from the second correction on: the linear
    /// solver's; the reduction that can end the Newton solve where that is
    /// tighter (by at most 100), so that the correction that can end the
    /// solve is solved accurately enough to end it; or that reduction also
    /// where it is looser (up to 0.1), so that it is solved no further
    /// (doc/hydrodynamics.md, "Cost per step").
    enum class LaterCorrections
    {
      linear,
      tightened,
      fitted
    };
    LaterCorrections later_corrections = LaterCorrections::tightened;

    /// Subsection "Newton" with the given defaults.
    static void
    declare(dealii::ParameterHandler &prm,
            const std::string        &default_max_iterations,
            const std::string        &default_relative_tolerance,
            const std::string        &default_absolute_tolerance,
            const std::string        &default_jacobian_interval = "1",
            const std::string        &default_keep_jacobian     = "false");
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
   * converged iteration. A lagged Jacobian (jacobian_interval > 1) makes
   * the iteration a chord method: each correction costs a residual and a
   * Krylov solve with a matrix (and preconditioner) already built, and
   * converges linearly; the Jacobian is rebuilt once it has served
   * jacobian_interval corrections or converges too slowly. A correction
   * after the first can ask its Krylov solve for eta = 0.5 max(atol, rtol
   * |R_0|) / |R_k| (later_corrections: where that is tighter than the
   * linear tolerance by at most 100, and with "fitted" also where it is
   * looser, up to 0.1: the Krylov residual eta |R_k| then leaves room for
   * the Newton tolerance, and no more). Failure (no
   * convergence in max_iterations, a residual that is not finite, a Krylov
   * failure) throws SolverFailure and forgets a kept Jacobian; @p x is then
   * meaningless.
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
    /// The relative Krylov tolerance of correction @p iteration (0: the
    /// linear solver's own), NewtonParameters::later_corrections.
    double
    correction_tolerance(const unsigned int  iteration,
                         const NewtonReport &report,
                         const double        linear_tolerance) const;

    /// solve() without the clean-up after a failure.
    NewtonReport
    iterate(NonlinearProblem                      &problem,
            dealii::TrilinosWrappers::MPI::Vector &x) const;

    const NewtonParameters parameters;
  };
} // namespace vesicle_iga
