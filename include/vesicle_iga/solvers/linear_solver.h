#pragma once

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/solvers/spline_multigrid.h>

#include <string>

namespace vesicle_iga
{
  /// Defaults of a flow study's "Linear solver" subsection. The velocity
  /// smoother differs by study: Chebyshev for the flow alone
  /// (doc/flow.md), the Schwarz ILU for vesicles in the flow
  /// (doc/hydrodynamics.md).
  struct FlowSolverDefaults
  {
    std::string method            = "fgmres-block";
    std::string tolerance         = "1e-8";
    std::string reuse             = "every-matrix";
    std::string velocity_smoother = "chebyshev";
    std::string velocity_sweeps   = "3";
    /// Pressure Schur approximation: the lumped viscous mass for the flow
    /// alone, the consistent one with C for vesicles in the flow
    /// (doc/hydrodynamics.md, "The stabilized Cahouet-Chabard
    /// approximation").
    std::string schur_approximation = "cahouet-chabard";
  };

  /// Settings of the velocity-pressure block preconditioner
  /// (FlowBlockPreconditioner; subsection "Linear solver/Block
  /// preconditioner" of the flow study).
  struct FlowBlockPreconditionerParameters
  {
    /// AMG smoother sweeps on the velocity block and on the Schur block.
    unsigned int velocity_sweeps = 3;
    unsigned int schur_sweeps    = 2;
    /// Smoother of the velocity spline multigrid: ssor, chebyshev or ilu.
    std::string velocity_smoother = "chebyshev";
    /// Largest level of the velocity spline multigrid solved by LU (0:
    /// the SplineMultigrid default).
    unsigned int velocity_coarse_size = 0;
    /// Symmetric smoothed aggregation with Chebyshev smoothing on the
    /// velocity block, or non-symmetric smoothed aggregation.
    bool velocity_elliptic = true;
    /// "spline-multigrid" or "amg" on the velocity block.
    std::string velocity_preconditioner = "spline-multigrid";
    /// "cahouet-chabard", "stabilized-cahouet-chabard", "simple" or
    /// "direct" (see FlowBlockPreconditioner).
    std::string schur_approximation = "cahouet-chabard";
    /// Relative tolerance of the CG solve of the viscous part M_nu + C of
    /// stabilized-cahouet-chabard (0: one AMG V-cycle).
    double viscous_schur_tolerance = 1e-2;
    /// Relative tolerance of an inner GMRES solve of the velocity block,
    /// preconditioned by the velocity V-cycle (0: one V-cycle).
    double velocity_tolerance = 0.;

    /// The entries, with the velocity smoother's defaults of @p defaults.
    static void
    declare(dealii::ParameterHandler &prm,
            const FlowSolverDefaults &defaults = {});
    void
    parse(dealii::ParameterHandler &prm);
  };

  /**
   * Krylov method and preconditioner of a spline system (subsection
   * "Linear solver" of a study):
   *  - cg-amg: CG preconditioned by one V-cycle of Trilinos ML AMG
   *    (higher-order smoothing, as the spline couplings are wide);
   *  - direct: MUMPS sparse LU through Amesos (small problems, fourth
   *    order operators on which AMG is not robust, the coupled vesicle
   *    system);
   *  - gmres-mg, cg-mg: one V-cycle of the geometric spline multigrid
   *    (SplineMultigrid), robust for the fourth-order operators of Part E;
   *  - fgmres-block: flexible GMRES with the velocity-pressure block
   *    preconditioner of the flow solver (FlowBlockPreconditioner).
   */
  struct LinearSolverParameters
  {
    std::string                       method         = "cg-amg";
    double                            tolerance      = 1e-12;
    unsigned int                      max_iterations = 5000;
    SplineMultigridParameters         multigrid;
    FlowBlockPreconditionerParameters block;
    /// When the caller's preconditioner of a time-dependent problem is
    /// rebuilt (flow studies): "every-matrix" or "across-steps" (see
    /// JacobianSolver::Reuse).
    std::string preconditioner_reuse = "every-matrix";
    /// Reuse across steps: the preconditioner is rebuilt once the solves
    /// since its build have needed, in sum, this many Krylov iterations
    /// more than the first of them.
    unsigned int rebuild_extra_iterations = 40;

    /// Whether the method needs a SplineMultigrid from the caller.
    bool
    uses_multigrid() const
    {
      return method == "gmres-mg" || method == "cg-mg";
    }
    /// Whether the caller builds the preconditioner (multigrid, block).
    bool
    uses_caller_preconditioner() const
    {
      return uses_multigrid() || method == "fgmres-block";
    }

    static void
    declare(dealii::ParameterHandler &prm,
            const std::string        &default_method,
            const std::string        &default_tolerance = "1e-12",
            const std::string        &default_smoother  = "ssor",
            const std::string        &default_sweeps    = "2");
    void
    parse(dealii::ParameterHandler &prm);

    /// The flow solver's choice: gmres-ilu, gmres-amg, direct or
    /// fgmres-block, with the Block preconditioner subsection instead of
    /// the Multigrid one.
    static void
    declare_flow(dealii::ParameterHandler &prm,
                 const FlowSolverDefaults &defaults);
    void
    parse_flow(dealii::ParameterHandler &prm);
  };

  struct LinearSolveResult
  {
    unsigned int iterations;
    double       residual;
  };

  /// Solve A x = b (relative tolerance), then set the constrained entries.
  /// The multigrid and block methods need @p caller_preconditioner,
  /// initialized by the caller (with A, or with an earlier matrix when the
  /// caller reuses it).
  LinearSolveResult
  solve_linear_system(const LinearSolverParameters                 &parameters,
                      const dealii::TrilinosWrappers::SparseMatrix &A,
                      dealii::TrilinosWrappers::MPI::Vector        &x,
                      const dealii::TrilinosWrappers::MPI::Vector  &b,
                      const dealii::AffineConstraints<double>      &constraints,
                      MatrixPreconditioner *caller_preconditioner = nullptr);
} // namespace vesicle_iga
