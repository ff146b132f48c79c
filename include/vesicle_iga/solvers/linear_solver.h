#pragma once

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

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
   *    order operators, on which AMG is not robust).
   */
  struct LinearSolverParameters
  {
    std::string  method         = "cg-amg";
    double       tolerance      = 1e-12;
    unsigned int max_iterations = 5000;

    static void
    declare(ParameterHandler &prm, const std::string &default_method);
    void
    parse(ParameterHandler &prm);
  };

  struct LinearSolveResult
  {
    unsigned int iterations;
    double       residual;
  };

  /// Solve A x = b (relative tolerance), then set the constrained entries.
  LinearSolveResult
  solve_linear_system(const LinearSolverParameters         &parameters,
                      const TrilinosWrappers::SparseMatrix &A,
                      TrilinosWrappers::MPI::Vector        &x,
                      const TrilinosWrappers::MPI::Vector  &b,
                      const AffineConstraints<double>      &constraints);
} // namespace vesicle_iga
