#pragma once

#include <vesicle_iga/models/incompressible_flow.h>
#include <vesicle_iga/physics/bulk_stability.h>
#include <vesicle_iga/physics/hydrodynamic_membrane.h>
#include <vesicle_iga/solvers/vesicle_block_preconditioner.h>
#include <vesicle_iga/terms/global_constraint_forcing.h>
#include <vesicle_iga/terms/hydrodynamic_bending.h>
#include <vesicle_iga/terms/local_inextensibility.h>
#include <vesicle_iga/terms/phase_field_advection.h>
#include <vesicle_iga/terms/phase_field_inflow.h>
#include <vesicle_iga/terms/tension_lumped_schur.h>
#include <vesicle_iga/terms/vesicle_interaction.h>
#include <vesicle_iga/terms/viscosity_contrast.h>

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace vesicle_iga
{
  template <int dim>
  class GramSolver;
  class SecantIteration2;

  /// What is measured of one vesicle (spec 4.5, 4.12).
  struct VesicleMeasures
  {
    /// A_i and V_i of (H12c).
    double area = 0, volume = 0;
    /// Centroid (z = 0 in 2D) and inclination angle theta_i (radians) of
    /// the indicator (1 + phi_i) / 2 (spec 4.12); in 3D the angle of the
    /// major principal axis of the x-y second moments (the shear plane).
    dealii::Point<3> centroid;
    double           angle = 0;
    /// (1 / (2 eps Re Ca)) int f_i^2.
    double bending_energy = 0;
  };


  /// The periodic directions of the box, for the vesicle measures: period
  /// > 0 in a periodic direction (0 otherwise) and the lower end.
  struct PeriodicBox
  {
    double period[3] = {0, 0, 0};
    double lower[3]  = {0, 0, 0};
  };


  /**
   * N vesicles in an incompressible flow, spec Part H in the mixed-free
   * form of 4.13: the unknowns u, p (the flow model) and phi_i, lambda_i
   * (i = 1..N) in one Newton system on one spline space (cubic C^2 by
   * default: (H25) needs third derivatives of phi_i; the velocity is
   * equal-order, which RBVMS allows), one generalized-alpha stepper.
   * Terms per vesicle: advection (H16), bending (H24)-(H25), global
   * multipliers (H1), local inextensibility and tension force (H17, H14);
   * per pair: interaction (H10)-(H11); viscosity contrast (H12a) if
   * beta_mu != 1. The RBVMS residual r_M of (H18b) carries the flow terms
   * only (the vesicle forces are left out of it, spec 4.13), tau_M the outer
   * viscosity. lambda_i = 0 strongly on the boundary (spec 4.10). After each
   * accepted step the global multipliers lambda_{g,i}, lambda_{v,i} follow
   * from the 2x2 systems (H13), which use the step just taken.
   */
  template <int dim>
  class VesicleHydrodynamics : public FlowCoupling<dim>,
                               public TimeDependentProblem,
                               public Checkpointable
  {
  public:
    VesicleHydrodynamics(const MPI_Comm                             comm,
                         const SplineSpace<dim>                    &space,
                         const MembraneCoefficients                &membrane,
                         const FlowCoefficients<dim>               &flow,
                         const std::vector<VelocityCondition<dim>> &conditions,
                         const IncompressibleFlowParameters        &parameters,
                         const unsigned int                         n_vesicles,
                         dealii::TimerOutput                       &timer,
                         const PhaseFieldBlockParameters &phase_field_blocks
                         = PhaseFieldBlockParameters());
    ~VesicleHydrodynamics();

    unsigned int
    n_vesicles() const
    {
      return n;
    }
    /// Flat components of u_1, p, phi_i, lambda_i.
    static constexpr unsigned int velocity = 0, pressure = dim;
    unsigned int
    phase(const unsigned int i) const
    {
      return dim + 1 + i;
    }
    unsigned int
    tension(const unsigned int i) const
    {
      return dim + 1 + n + i;
    }

    /// u(x, 0) from @p velocity (dim components), phi_i(x, 0) from
    /// @p phases, p = lambda_i = 0; A_i(0), V_i(0) and the multipliers of
    /// (H13) from these fields.
    void
    set_initial_state(
      const dealii::Function<dim> &velocity,
      const std::vector<std::function<double(const dealii::Point<dim> &)>>
        &phases);

    IncompressibleFlow<dim> &
    get_flow()
    {
      return *flow_model;
    }
    const IncompressibleFlow<dim> &
    get_flow() const
    {
      return *flow_model;
    }
    /// The measures of every vesicle at time().
    std::vector<VesicleMeasures>
    measure() const;
    /// A_i(0), V_i(0).
    const std::vector<double> &
    initial_areas() const
    {
      return area_0;
    }
    const std::vector<double> &
    initial_volumes() const
    {
      return volume_0;
    }
    /// lambda_{g,i}, lambda_{v,i} used in the next step.
    const std::vector<double> &
    area_multipliers() const
    {
      return lambda_g;
    }
    const std::vector<double> &
    volume_multipliers() const
    {
      return lambda_v;
    }
    /// E_int of (H10), summed over pairs.
    double
    interaction_energy() const;
    /// The advection power of the bending pairing, b(f_i; u . grad phi_i)
    /// summed over i, and the power of its momentum forcing with w = u:
    /// equal up to round-off by construction of (H24)-(H25) (spec 4.13).
    std::pair<double, double>
    bending_powers() const;

    // FlowCoupling
    void
    add_fields(FieldLayout<dim> &layout) const override;
    std::vector<Term<dim> *>
    terms() override;
    void
    boundary_values(const SplineDofHandler<dim>       &dofs,
                    const double                       t,
                    dealii::AffineConstraints<double> &c) const override;
    /// VesicleBlockPreconditioner around the flow blocks (Method =
    /// fgmres-block), the phase-field blocks by spline multigrid or AMG.
    std::unique_ptr<LumpedOperatorPreconditioner>
    block_preconditioner(
      std::unique_ptr<FlowBlockPreconditioner> flow,
      const SplineDofHandler<dim>             &dofs,
      const dealii::AffineConstraints<double> &increments,
      const FlowBlockPreconditionerParameters &parameters) override;
    std::vector<Term<dim> *>
    lumped_operator_terms() override;
    void
    prepare_lumped_operators(const AssemblyState &state) override;

    // TimeDependentProblem
    double
    time() const override
    {
      return flow_model->time();
    }
    /// With implicit multipliers: the number of multiplier iterations of
    /// the step.
    std::vector<std::pair<std::string, std::string>>
    step_columns() const override;
    StepReport
    solve_step(const double dt) override;
    /// The estimate (N5) on the phase fields only: the velocity, pressure
    /// and tensions follow the membrane quasi-statically (viscous time
    /// Re h^2, far below any step), so their change in the first steps
    /// after a start or a contact is no truncation error of the scheme.
    double
    local_error(const double atol, const double rtol) const override;
    void
    accept_step() override;
    /// Half the step at which the step matrix of the fastest growing bulk
    /// mode turns singular (BulkStability), for the most negative lambda_g
    /// the next step may use (its value, or extrapolated over a step like
    /// the last); infinity while every bulk is stable.
    double
    largest_step() const override;

    // Checkpointable
    void
    save(Checkpoint &c, const std::string &prefix) const override;
    void
    load(const Checkpoint &c, const std::string &prefix) override;
    /// Forgets a Jacobian kept for the next Newton solve.
    void
    drop_unsaved_state() override;

  private:
    /// Whether V_i is int chi(phi_i) ('Volume multiplier = indicator')
    /// rather than int phi_i.
    bool
    indicator_volume() const
    {
      return membrane.volume_multiplier
             == MembraneCoefficients::VolumeMultiplier::indicator;
    }
    /// Solve (H13) for every vesicle with the current fields; @p dt: the
    /// step just taken (0: no relaxation terms, the initial state).
    void
    update_multipliers(const double dt);
    /// (H13) of every vesicle as [F_v(1) F_g(1); F_v(Y) F_g(Y)] (lambda_v,
    /// lambda_g) = b (row-major matrix, then b) from the current fields
    /// (with 'indicator' the first row is -(c / eta_phi) [F_v(Z) F_g(Z)],
    /// Z = M^-1 F_v);
    /// @p dt: the step just taken (0: no relaxation terms).
    std::vector<std::array<double, 6>>
    rate_laws(const double dt) const;
    /// The step solved again with the global multipliers iterated until it
    /// ends on V_i(0), A_i(0) (implicit multipliers).
    StepReport
    implicit_step(const double dt);
    /// Per vesicle the secant iteration of implicit_step() for
    /// (lambda_v, lambda_g), started from the step's multipliers with the
    /// last step's response scaled to @p dt, or before a first step the
    /// rate laws' dt d(dV/dt, dA/dt)/d(lambda_v, lambda_g).
    std::vector<SecantIteration2>
    multiplier_secants(const double dt) const;
    /// Per vesicle (V_i - V_i(0), A_i - A_i(0)) of @p fields (nullptr: the
    /// current fields).
    std::vector<std::array<double, 2>>
    constraint_errors(
      const dealii::TrilinosWrappers::MPI::Vector *fields) const;
    /// Through the increments' constraints: the residual of every term
    /// with phase-field rows but the multipliers' at zero rate (R_0), and
    /// that of the multipliers' term with (lambda_g, lambda_v) = (1, 0)
    /// and (0, 1) (F_g, F_v); the multipliers' term is left as it was.
    std::array<dealii::TrilinosWrappers::MPI::Vector, 3>
    phase_row_residuals() const;
    /// Per vesicle the 12 sums of the geometry integrand about
    /// @p references (A_i and V_i first), then, if asked for, per vesicle
    /// its bending energy (the costly part: Hessians).
    std::vector<double>
    integrate_geometry(const std::vector<dealii::Point<dim>> &references,
                       const bool with_bending_energy,
                       const dealii::TrilinosWrappers::MPI::Vector *fields
                       = nullptr) const;

    const MembraneCoefficients                             membrane;
    const FlowCoefficients<dim>                            flow_coefficients;
    dealii::TimerOutput                                   &timer;
    const PhaseFieldBlockParameters                        phase_field_blocks;
    const unsigned int                                     n;
    std::vector<std::unique_ptr<PhaseFieldAdvection<dim>>> advection;
    std::vector<std::unique_ptr<HydrodynamicBending<dim>>> bending;
    std::vector<std::unique_ptr<GlobalConstraintForcing<dim>>> constraint;
    std::vector<std::unique_ptr<LocalInextensibility<dim>>>    inextensibility;
    std::vector<std::unique_ptr<VesicleInteraction<dim>>>      interaction;
    std::vector<std::pair<unsigned int, unsigned int>>         pairs;
    std::unique_ptr<ViscosityContrast<dim>>                    viscosity;
    std::vector<std::unique_ptr<TensionLumpedSchur<dim>>>      tension_schur;
    std::vector<std::unique_ptr<PhaseFieldInflow<dim>>>        inflow;
    std::unique_ptr<IncompressibleFlow<dim>>                   flow_model;
    /// The projection onto one phase field's space, for (H13).
    std::unique_ptr<GramSolver<dim>> phase_gram;
    std::vector<double>              area_0, volume_0, lambda_g, lambda_v;
    /// d lambda / dt over the last accepted step and over the one before
    /// it (zero before the first).
    std::vector<double> lambda_g_rate, lambda_v_rate;
    std::vector<double> lambda_g_previous_rate, lambda_v_previous_rate;
    /// The rate by which extrapolated multipliers move over the next step:
    /// that of the last step, or none where it changed sign (see the
    /// definition).
    static double
    extrapolation_rate(const double rate, const double previous_rate);
    /// The multipliers the last solved step used.
    std::vector<double> step_lambda_g, step_lambda_v;
    /// Implicit multipliers: per vesicle the secant estimate of d(V, A) /
    /// d(lambda_v, lambda_g) per unit step of the last accepted step (the
    /// next step's first estimate, times its dt; empty: none yet, the rate
    /// laws give it), and that of the step last solved.
    std::vector<std::array<double, 4>> step_response, solved_step_response;
    /// Implicit multipliers: per vesicle (lambda_v, lambda_g) of the step
    /// last solved without the part that removed the constraint errors of
    /// its start (the values kept and extrapolated after it).
    std::vector<std::array<double, 2>> solved_drift_free;
    double                             last_dt = 0;
    /// rho_inf of the generalized-alpha steps, for largest_step().
    const double        rho_inf;
    const BulkStability bulk_stability;
    PeriodicBox         periodic_box;
    /// Per locally owned unknown: whether it is a phase field.
    std::vector<bool> phase_entries;
  };
} // namespace vesicle_iga
