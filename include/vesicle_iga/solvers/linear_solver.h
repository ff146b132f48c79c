#pragma once

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/solvers/spline_multigrid.h>

#include <string>

namespace vesicle_iga
{
  using namespace dealii;

  /**
   * Krylov method and preconditioner for a symmetric positive definite
   * spline system (subsection "Linear solver" of a study):
   *  - cg-amg: CG preconditioned by one V-cycle of Trilinos ML AMG
   *    (higher-order smoothing, as the spline couplings are wide);
   *  - direct: Amesos KLU (gathers the matrix: small problems and fourth
   *    order operators, on which AMG is not robust);
   *  - gmres-mg, cg-mg: one V-cycle of the geometric spline multigrid
   *    (SplineMultigrid), robust for the fourth-order operators of Part E.
   */
  struct LinearSolverParameters
  {
    std::string               method         = "cg-amg";
    double                    tolerance      = 1e-12;
    unsigned int              max_iterations = 5000;
    SplineMultigridParameters multigrid;

    /// Whether the method needs a SplineMultigrid from the caller.
    bool
    uses_multigrid() const
    {
      return method == "gmres-mg" || method == "cg-mg";
    }

    static void
    declare(ParameterHandler  &prm,
            const std::string &default_method,
            const std::string &default_tolerance = "1e-12",
            const std::string &default_smoother  = "ssor",
            const std::string &default_sweeps    = "2");
    void
    parse(ParameterHandler &prm);
  };

  struct LinearSolveResult
  {
    unsigned int iterations;
    double       residual;
  };

  /// Solve A x = b (relative tolerance), then set the constrained entries.
  /// The multigrid methods need @p multigrid, initialized by the caller
  /// (with A, or with an earlier matrix when the caller reuses it).
  LinearSolveResult
  solve_linear_system(const LinearSolverParameters         &parameters,
                      const TrilinosWrappers::SparseMatrix &A,
                      TrilinosWrappers::MPI::Vector        &x,
                      const TrilinosWrappers::MPI::Vector  &b,
                      const AffineConstraints<double>      &constraints,
                      MatrixPreconditioner *multigrid = nullptr);
} // namespace vesicle_iga
