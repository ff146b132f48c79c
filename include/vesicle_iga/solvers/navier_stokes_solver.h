#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/assembly/assembly_term.h>
#include <vesicle_iga/assembly/boundary_selection.h>
#include <vesicle_iga/parallel/patch_mesh.h>
#include <vesicle_iga/parallel/spline_dof_handler.h>
#include <vesicle_iga/physics/navier_stokes_rbvms.h>
#include <vesicle_iga/solvers/flow_block_preconditioner.h>
#include <vesicle_iga/solvers/linear_solver.h>
#include <vesicle_iga/time/generalized_alpha.h>

#include <memory>
#include <vector>

namespace vesicle_iga
{
  /// A velocity condition on a part of the boundary (spec 4.10).
  template <int dim>
  struct VelocityCondition
  {
    BoundarySelection<dim> where;
    /// dim + 1 components (the last, pressure, unused); may depend on t.
    std::shared_ptr<Function<dim>> velocity;
    bool                           weak = false;
  };

  /// Newton settings of one time step.
  struct FlowNewtonParameters
  {
    double       relative_tolerance = 1e-8;
    double       absolute_tolerance = 1e-10;
    unsigned int max_iterations     = 20;
  };

  /// What one time step took.
  struct FlowStepResult
  {
    bool         converged;
    unsigned int newton_iterations;
    unsigned int krylov_iterations;
    double       residual; // final |R|_2
  };

  /**
   * The incompressible flow on one spline patch: equal-order spline
   * velocity and pressure (one SplineDofHandler with dim + 1 components),
   * the RBVMS residual of NavierStokesRBVMS plus weak velocity conditions,
   * strong velocity conditions as constraints, the pressure level fixed
   * when no boundary does it, and generalized-alpha steps solved by Newton
   * (spec (N2)-(N4)) with the pressure at t_{n+1} or t_{n+alpha_f}
   * (spec 4.9). Further terms (the vesicle forces of Part H) join through
   * add_term().
   */
  template <int dim>
  class NavierStokesSolver
  {
  public:
    NavierStokesSolver(const MPI_Comm                             comm,
                       const SplineSpace<dim>                    &space,
                       const FlowCoefficients<dim>               &coefficients,
                       const std::vector<VelocityCondition<dim>> &conditions,
                       const double                  weak_penalty_constant,
                       const bool                    weak_inflow_term,
                       const bool                    fix_pressure_mean,
                       const Quadrature<1>          &quadrature,
                       const LinearSolverParameters &linear_solver,
                       const FlowNewtonParameters   &newton,
                       const double                  rho_inf,
                       const bool                    pressure_at_end,
                       TimerOutput                  &timer);

    const SplineDofHandler<dim> &
    dofs() const
    {
      return dof_handler;
    }
    const PatchMesh<dim> &
    mesh() const
    {
      return patch_mesh;
    }

    /// Set u(t0) by Greville interpolation of @p velocity (dim + 1
    /// components), the pressure and all rates to zero, and the boundary
    /// values at t0.
    void
    set_initial_state(const Function<dim> &velocity, const double t0);

    /// One step from time() to time() + dt.
    FlowStepResult
    advance(const double dt);

    double
    time() const
    {
      return t;
    }
    /// U_n (ghosted), pressure shifted to zero mean if the level is free.
    const TrilinosWrappers::MPI::Vector &
    solution() const
    {
      return ghosted_solution;
    }
    /// The owned U_n and its rate (for checkpoints) and a restart from them.
    const TrilinosWrappers::MPI::Vector &
    owned_solution() const
    {
      return U;
    }
    const TrilinosWrappers::MPI::Vector &
    owned_rate() const
    {
      return U_rate;
    }
    void
    set_state(const TrilinosWrappers::MPI::Vector &solution,
              const TrilinosWrappers::MPI::Vector &rate,
              const double                         time);

    /// The residual R (not -R) and the tangent K of the step from time() to
    /// time() + dt at the trial rate @p rate_n1 (for the Jacobian check;
    /// constrained rows are condensed as in the Newton solve).
    void
    assemble(const TrilinosWrappers::MPI::Vector &rate_n1,
             const double                         dt,
             const bool                           with_matrix,
             TrilinosWrappers::MPI::Vector       &residual);
    const TrilinosWrappers::SparseMatrix &
    matrix() const
    {
      return system_matrix;
    }
    /// The homogeneous constraints of the Newton increments (strong
    /// velocity conditions, pinned pressure) of the last assembly.
    const AffineConstraints<double> &
    constraints_of_increments() const
    {
      return increment_constraints;
    }

    /// Kinetic energy (1/2) |u|^2 and the L2 norm of div u at time().
    std::pair<double, double>
    kinetic_energy_and_divergence() const;

    /// Further terms of the momentum and continuity residual.
    void
    add_term(AssemblyTerm<dim> *term)
    {
      extra_terms.push_back(term);
    }

  private:
    void
    make_constraints(const double time);
    void
    assemble_system(const TrilinosWrappers::MPI::Vector &rate_n1,
                    const double                         dt,
                    const bool                           with_matrix,
                    TrilinosWrappers::MPI::Vector       &residual);
    void
    set_levels(const TrilinosWrappers::MPI::Vector &rate_n1,
               const double                         dt,
               const bool                           with_matrix);
    void
    update_ghosted_solution();

    const MPI_Comm                            comm;
    const SplineSpace<dim>                    space;
    PatchMesh<dim>                            patch_mesh;
    SplineDofHandler<dim>                     dof_handler;
    const FlowCoefficients<dim>              &coefficients;
    const std::vector<VelocityCondition<dim>> conditions;
    const bool                                fix_pressure_mean;
    const Quadrature<1>                       quadrature;
    const LinearSolverParameters              linear_solver;
    const FlowNewtonParameters                newton;
    const GeneralizedAlpha                    alpha;
    const bool                                pressure_at_end;
    TimerOutput                              &timer;

    NavierStokesRBVMS<dim>                                   rbvms;
    RBVMSLumpedSchurOperators<dim>                           lumped_schur;
    std::vector<std::unique_ptr<WeakVelocityDirichlet<dim>>> weak_terms;
    std::vector<AssemblyTerm<dim> *>                         extra_terms;

    AffineConstraints<double>      constraints, increment_constraints;
    types::global_dof_index        pinned_pressure;
    TrilinosWrappers::SparseMatrix system_matrix;
    /// Method fgmres-block only.
    std::unique_ptr<FlowBlockPreconditioner> block_preconditioner;
    bool                                     velocity_multigrid_set = false;
    TrilinosWrappers::MPI::Vector            U, U_rate;       // at t_n
    TrilinosWrappers::MPI::Vector U_alpha, rate_alpha, U_end; // ghosted
    TrilinosWrappers::MPI::Vector ghosted_solution;
    double                        t = 0;
  };
} // namespace vesicle_iga
