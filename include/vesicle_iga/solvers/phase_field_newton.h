#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/physics/phase_field_operator.h>
#include <vesicle_iga/solvers/linear_solver.h>
#include <vesicle_iga/time/generalized_alpha.h>

#include <memory>

namespace vesicle_iga
{
  struct NewtonParameters
  {
    unsigned int max_iterations     = 12;
    double       relative_tolerance = 1e-8;
    double       absolute_tolerance = 1e-10;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /**
   * One time step t_n -> t_{n+1} of the phase-field gradient flow with the
   * first-order generalized-alpha method: the predictor-multicorrector
   * Newton iteration of spec section 2.4 on the residual of a
   * PhaseFieldOperator (E18), with the tangent (N4) and the Krylov solver
   * of LinearSolverParameters (the spline multigrid by default). The
   * unknown of Newton is the rate phidot_{n+1}; phi_{n+1} follows from (N2)
   * (with the increment, spec section 7 item 8).
   */
  template <int dim>
  class PhaseFieldNewton
  {
  public:
    PhaseFieldNewton(const SplineDofHandler<dim>     &dofs,
                     PhaseFieldOperator<dim>         &op,
                     const AffineConstraints<double> &increment_constraints,
                     const Quadrature<1>             &quadrature_1d,
                     const LinearSolverParameters    &solver,
                     const NewtonParameters          &newton,
                     TimerOutput                     &timer);

    struct Result
    {
      bool         converged         = false;
      unsigned int newton_iterations = 0;
      unsigned int krylov_iterations = 0;
    };

    /// From (phi_n, phidot_n) to (phi, phidot) at t_n + dt; on failure
    /// (no convergence, a non-finite residual, a linear solver failure)
    /// converged is false and phi, phidot are meaningless.
    Result
    solve(const GeneralizedAlpha              &ga,
          const double                         dt,
          const TrilinosWrappers::MPI::Vector &phi_n,
          const TrilinosWrappers::MPI::Vector &phidot_n,
          TrilinosWrappers::MPI::Vector       &phi,
          TrilinosWrappers::MPI::Vector       &phidot);

    /// The linearised response of the step just solved to source terms:
    /// x_k with K x_k = b_k for the last Newton matrix K (N4) and the
    /// preconditioner in use (no assembly). Used for the 2x2 Jacobian of
    /// the modified ALM.
    void
    linear_response(const std::vector<TrilinosWrappers::MPI::Vector> &b,
                    std::vector<TrilinosWrappers::MPI::Vector>       &x);

    /// Compare K d with central differences of the residual at the state
    /// (phi_n, phidot_n) for dt = 1 and print the relative differences for
    /// h_fd = 1e-2, 1e-3, 1e-4 (they fall as h_fd^2 for a consistent
    /// tangent).
    void
    check_jacobian(const GeneralizedAlpha              &ga,
                   const TrilinosWrappers::MPI::Vector &phi_n,
                   const TrilinosWrappers::MPI::Vector &phidot_n,
                   const ConditionalOStream            &out);

    /// Solve K x = K x* for the Newton matrix of the first step at this dt
    /// and print iterations, times and the error (tools/bench).
    void
    benchmark_linear_solver(const GeneralizedAlpha              &ga,
                            const double                         dt,
                            const TrilinosWrappers::MPI::Vector &phi_n,
                            const TrilinosWrappers::MPI::Vector &phidot_n,
                            const ConditionalOStream            &out);

    /// One line describing the linear solver.
    std::string
    solver_description() const;

  private:
    /// Assemble -R (and K if @p matrix_too) at phi_{n+alpha_f},
    /// phidot_{n+alpha_m} given in the ghost vectors.
    void
    assemble(const double                   mass_factor,
             const double                   stiffness_factor,
             TrilinosWrappers::MPI::Vector &rhs,
             const bool                     matrix_too);
    /// A direction defined in the natural numbering (the same on any
    /// number of ranks), zero on constrained unknowns.
    TrilinosWrappers::MPI::Vector
    test_vector() const;

    const SplineDofHandler<dim>          &dofs;
    PhaseFieldOperator<dim>              &op;
    const AffineConstraints<double>      &constraints;
    const Quadrature<1>                   quadrature;
    const LinearSolverParameters          solver;
    const NewtonParameters                newton;
    TimerOutput                          &timer;
    TrilinosWrappers::SparseMatrix        matrix;
    std::unique_ptr<SplineMultigrid<dim>> multigrid;
    TrilinosWrappers::MPI::Vector         ghost_phi, ghost_rate;
  };
} // namespace vesicle_iga
