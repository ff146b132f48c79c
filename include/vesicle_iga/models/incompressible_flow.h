#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/boundary_selection.h>
#include <vesicle_iga/fields/spline_dof_handler.h>
#include <vesicle_iga/io/checkpoint.h>
#include <vesicle_iga/kernel/system_assembler.h>
#include <vesicle_iga/parallel/patch_mesh.h>
#include <vesicle_iga/physics/flow_coefficients.h>
#include <vesicle_iga/solvers/flow_block_preconditioner.h>
#include <vesicle_iga/solvers/newton.h>
#include <vesicle_iga/terms/navier_stokes_rbvms.h>
#include <vesicle_iga/terms/rbvms_lumped_schur.h>
#include <vesicle_iga/terms/weak_velocity_dirichlet.h>
#include <vesicle_iga/time/generalized_alpha.h>
#include <vesicle_iga/time/time_loop.h>

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
    std::shared_ptr<dealii::Function<dim>> velocity;
    bool                                   weak = false;
  };

  /**
   * What a model adds to the flow (e.g. the vesicles of spec Part H): more
   * fields after velocity and pressure (on the flow's space), their terms
   * (which may also act on the momentum and continuity rows), and their
   * strong conditions. The flow model does everything else: one Newton
   * system, one time stepper, one checkpoint.
   */
  template <int dim>
  class FlowCoupling
  {
  public:
    virtual ~FlowCoupling() = default;
    /// Add fields to @p layout (velocity and pressure are fields 0, 1 on
    /// space 0).
    virtual void
    add_fields(FieldLayout<dim> &layout) const = 0;
    /// The terms of the added fields.
    virtual std::vector<Term<dim> *>
    terms() = 0;
    /// Strong conditions of the added fields at time t.
    virtual void
    boundary_values(const SplineDofHandler<dim> & /*dofs*/,
                    const double /*t*/,
                    dealii::AffineConstraints<double> & /*constraints*/) const
    {}
    /// Linear solver/Method = fgmres-block: the preconditioner of the whole
    /// coupled tangent around the flow's velocity-pressure blocks @p flow
    /// (which expect the flow's own layout, basis (dim + 1) + component);
    /// @p increments: the strong conditions. Null: the coupling has none
    /// and the method is refused.
    virtual std::unique_ptr<LumpedOperatorPreconditioner>
    block_preconditioner(
      std::unique_ptr<FlowBlockPreconditioner> /*flow*/,
      const SplineDofHandler<dim> & /*dofs*/,
      const dealii::AffineConstraints<double> & /*increments*/,
      const FlowBlockPreconditionerParameters & /*parameters*/)
    {
      return nullptr;
    }
    /// Terms that add the coupled fields' lumped operators of that
    /// preconditioner (assembled as a residual with the flow's), set up
    /// for @p state by prepare_lumped_operators().
    virtual std::vector<Term<dim> *>
    lumped_operator_terms()
    {
      return {};
    }
    virtual void
    prepare_lumped_operators(const AssemblyState & /*state*/)
    {}
  };


  /// Settings of the flow model besides its coefficients and conditions.
  struct IncompressibleFlowParameters
  {
    /// C_B of (H21); <= 0: 5 (p + 1).
    double weak_penalty_constant = -1;
    bool   weak_inflow_term      = true;
    /// Fix the pressure level (zero mean) when no boundary does.
    bool                       fix_pressure_mean = true;
    unsigned int               quadrature_points = 4;
    LinearSolverParameters     solver;
    NewtonParameters           newton;
    GeneralizedAlphaParameters time_integration;
  };


  /**
   * The incompressible flow of spec Part H without vesicles as a
   * time-dependent problem of the engine: the fields velocity (dim
   * components, differential) and pressure (algebraic) on one spline space
   * (equal order, interleaved per basis function), the terms RBVMS
   * (terms/navier_stokes_rbvms) and weak velocity conditions
   * (terms/weak_velocity_dirichlet), strong conditions as constraints at
   * t_{n+1}, the pressure level pinned and reported with zero mean where no
   * boundary fixes it, generalized-alpha steps solved by Newton with FGMRES
   * and the velocity-pressure block preconditioner (or any other linear
   * solver).
   */
  template <int dim>
  class IncompressibleFlow : public TimeDependentProblem, public Checkpointable
  {
  public:
    IncompressibleFlow(const MPI_Comm                             comm,
                       const SplineSpace<dim>                    &space,
                       const FlowCoefficients<dim>               &coefficients,
                       const std::vector<VelocityCondition<dim>> &conditions,
                       const IncompressibleFlowParameters        &parameters,
                       dealii::TimerOutput                       &timer,
                       FlowCoupling<dim> *coupling = nullptr);
    ~IncompressibleFlow();

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
    SystemAssembler<dim> &
    get_assembler()
    {
      return assembler;
    }
    const SystemAssembler<dim> &
    get_assembler() const
    {
      return assembler;
    }
    GeneralizedAlphaStepper<dim> &
    get_stepper()
    {
      return *stepper;
    }
    const dealii::AffineConstraints<double> &
    increment_constraints() const
    {
      return increments;
    }

    /// U(t0) by Greville interpolation of @p initial (one component per
    /// component of the layout: velocity, pressure, then the coupling's
    /// fields), zero rates, the boundary values at t0.
    void
    set_initial_state(const dealii::Function<dim> &initial, const double t0);
    /// U_n, its rate and the time (e.g. a test's state).
    void
    set_state(const dealii::TrilinosWrappers::MPI::Vector &solution,
              const dealii::TrilinosWrappers::MPI::Vector &rate,
              const double                                 time);
    /// One step: solve and accept (throws SolverFailure).
    NewtonReport
    advance(const double dt);

    /// U_n (ghosted), the pressure shifted to zero mean if its level is free.
    const dealii::TrilinosWrappers::MPI::Vector &
    solution() const
    {
      return ghosted_solution;
    }
    const dealii::TrilinosWrappers::MPI::Vector &
    owned_solution() const
    {
      return stepper->solution();
    }
    const dealii::TrilinosWrappers::MPI::Vector &
    previous_solution() const
    {
      return stepper->previous_solution();
    }
    /// Kinetic energy (1/2) |u|^2 and the L2 norm of div u at time().
    std::pair<double, double>
    kinetic_energy_and_divergence() const;
    std::string
    solver_description() const
    {
      return linear->description();
    }

    // TimeDependentProblem
    double
    time() const override
    {
      return stepper->time();
    }
    StepReport
    solve_step(const double dt) override;
    void
    accept_step() override;

    // Checkpointable
    void
    save(Checkpoint &c, const std::string &prefix) const override;
    void
    load(const Checkpoint &c, const std::string &prefix) override;
    /// Forgets a Jacobian kept for the next Newton solve.
    void
    drop_unsaved_state() override;

  private:
    void
    boundary_values(const double t, dealii::AffineConstraints<double> &c) const;
    void
    setup_block_preconditioner();
    /// The pressure space's mass matrix, for the viscous part of the
    /// stabilized Cahouet-Chabard Schur approximation.
    std::shared_ptr<const dealii::TrilinosWrappers::SparseMatrix>
    pressure_mass_matrix() const;
    void
    update_ghosted_solution();

    const MPI_Comm                                           comm;
    const SplineSpace<dim>                                   space;
    PatchMesh<dim>                                           patch_mesh;
    SplineDofHandler<dim>                                    dof_handler;
    const FlowCoefficients<dim>                             &coefficients;
    const std::vector<VelocityCondition<dim>>                conditions;
    const IncompressibleFlowParameters                       parameters;
    dealii::TimerOutput                                     &timer;
    dealii::types::global_dof_index                          pinned_pressure;
    dealii::AffineConstraints<double>                        increments;
    NavierStokesRBVMS<dim>                                   rbvms;
    RBVMSLumpedSchurOperators<dim>                           lumped_schur;
    std::vector<std::unique_ptr<WeakVelocityDirichlet<dim>>> weak_terms;
    SystemAssembler<dim>                                     assembler;
    std::unique_ptr<SystemAssembler<dim>>                    schur_assembler;
    std::unique_ptr<JacobianSolver>                          linear;
    std::unique_ptr<GeneralizedAlphaStepper<dim>>            stepper;
    NewtonSolver                                             newton;
    dealii::TrilinosWrappers::MPI::Vector                    ghosted_solution;
    FlowCoupling<dim>                                       *coupling;
  };
} // namespace vesicle_iga
