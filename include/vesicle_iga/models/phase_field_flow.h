#pragma once

#include <deal.II/base/timer.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/io/checkpoint.h>
#include <vesicle_iga/kernel/system_assembler.h>
#include <vesicle_iga/models/electric_potential.h>
#include <vesicle_iga/physics/electromechanics_material.h>
#include <vesicle_iga/solvers/modified_alm.h>
#include <vesicle_iga/solvers/newton.h>
#include <vesicle_iga/terms/bending_energy.h>
#include <vesicle_iga/terms/constraint_functionals.h>
#include <vesicle_iga/terms/rate.h>
#include <vesicle_iga/time/generalized_alpha.h>
#include <vesicle_iga/time/time_loop.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vesicle_iga
{
  /// Settings of the constrained phase-field flow (spec 3.5-3.9).
  struct PhaseFieldFlowParameters
  {
    double kappa = 1, epsilon = 0.1, spontaneous_curvature = 0;
    /// alm (spec 3.8), penalty or none.
    std::string constraint_method = "alm", alm_jacobian = "linearised";
    /// carried error (Algorithm 1) or predicted drift (ModifiedALM).
    std::string  alm_first_update = "predicted drift";
    double       M1 = 1, M2 = 1, constraint_tolerance = 1e-4;
    unsigned int max_alm_iterations = 20;
    /// staggered (spec 3.9) or fixed-point.
    std::string                coupling                   = "staggered";
    double                     fixed_point_tolerance      = 1e-6;
    unsigned int               max_fixed_point_iterations = 10;
    unsigned int               quadrature_points          = 6;
    GeneralizedAlphaParameters time_integration;
    NewtonParameters           newton;
    LinearSolverParameters     solver, potential_solver;
    ElectromechanicsMaterial   material;
  };


  /**
   * The vesicle of spec Part E as a time-dependent problem: the gradient
   * flow (E12) of the phase field in the primal weak form (E18), i.e. the
   * rate term, the bending energy and (with a field) the flexoelectric and
   * dielectric energies with the potential psi^n frozen, plus the area and
   * volume constraint terms whose multipliers the modified ALM (E19)-(E22)
   * (or a penalty) sets per Newton solve; generalized-alpha steps
   * (GeneralizedAlphaStepper) solved by Newton with the spline multigrid;
   * the potential (E16)-(E17) staggered once per accepted step (spec 3.9)
   * or iterated to a fixed point. The terms live in terms/, the ALM in
   * solvers/modified_alm, the potential in models/electric_potential.
   */
  template <int dim>
  class PhaseFieldFlow : public TimeDependentProblem, public Checkpointable
  {
  public:
    PhaseFieldFlow(
      const SplineDofHandler<dim>             &dofs,
      const dealii::AffineConstraints<double> &increment_constraints,
      const PhaseFieldFlowParameters          &parameters,
      dealii::TimerOutput                     &timer);

    /// phi(0) (owned layout): the targets V0 = V(phi_0), A0 = A(phi_0).
    void
    set_initial_state(const dealii::TrilinosWrappers::MPI::Vector &phi0);

    /// The functionals at a phase field (owned layout) with the current
    /// potential: every energy, their sum, A, V and the Lagrangian
    /// E + Lambda_A (A - A0) + Lambda_V (V - V0), which is insensitive to
    /// first order to the constraint errors the ALM tolerance allows.
    struct Functionals
    {
      std::vector<double> energies;
      double              energy = 0, area = 0, volume = 0, lagrangian = 0;
    };
    Functionals
    functionals(const dealii::TrilinosWrappers::MPI::Vector &phi);
    /// Names of the energies (CSV columns).
    std::vector<std::string>
    energy_names() const;

    const dealii::TrilinosWrappers::MPI::Vector &
    solution() const
    {
      return stepper->solution();
    }
    const dealii::TrilinosWrappers::MPI::Vector &
    previous_solution() const
    {
      return stepper->previous_solution();
    }
    const SplineDofHandler<dim> &
    get_dofs() const
    {
      return dofs;
    }
    double
    area_target() const
    {
      return A0;
    }
    /// New targets of the diffuse constraints (E9) in the middle of a run
    /// (ZeroSetTargetControl); the ALM keeps its shifts.
    void
    set_constraint_targets(const double volume_target,
                           const double area_target);
    double
    volume_target() const
    {
      return V0;
    }
    double
    area_multiplier() const
    {
      return area.multiplier();
    }
    double
    volume_multiplier() const
    {
      return volume.multiplier();
    }
    /// The potential (null without a field).
    const ElectricPotential<dim> *
    potential() const
    {
      return electric.get();
    }
    /// Krylov iterations of the potential solves since the last call.
    unsigned int
    take_potential_iterations();
    /// The energy and Lagrangian at the accepted state with the potential
    /// of the step (the one the step minimised, spec 3.9), measured before
    /// the potential was updated.
    const Functionals &
    frozen_functionals() const
    {
      return frozen;
    }
    /// The functionals at the accepted state (with the new potential).
    const Functionals &
    current_functionals() const
    {
      return current;
    }
    /// How the interface moved over the last accepted step: the rigid
    /// drift velocity U that best explains phi_n - phi_{n-1}, and the RMS
    /// normal speed of what is left (the shape change),
    /// ||phi_n - phi_{n-1} + dt U . grad phi_n|| / (dt ||grad phi_n||): a
    /// front moving at normal speed v changes phi by v dt |grad phi|.
    struct InterfaceMotion
    {
      dealii::Tensor<1, dim> drift;
      double                 speed = 0;
    };
    InterfaceMotion
    interface_motion(const double dt);

    std::string
    solver_description() const
    {
      return linear->description();
    }
    /// Compare the tangent with central differences of the residual at the
    /// initial state, every term (kernel/jacobian_check).
    void
    check_jacobian(std::ostream &out);

    // TimeDependentProblem
    double
    time() const override
    {
      return stepper->time();
    }
    std::vector<std::pair<std::string, std::string>>
    step_columns() const override
    {
      return {{"alm_iterations", "alm"}};
    }
    StepReport
    solve_step(const double dt) override;
    double
    local_error(const double atol, const double rtol) const override
    {
      return stepper->local_error(atol, rtol);
    }
    void
    accept_step() override;
    void
    reject_step() override;

    // Checkpointable: the stepper, the ALM and the multipliers.
    void
    save(Checkpoint &c, const std::string &prefix) const override;
    void
    load(const Checkpoint &c, const std::string &prefix) override;
    /// Forgets a Jacobian kept for the next Newton solve.
    void
    drop_unsaved_state() override;

  private:
    /// One step with the constraint method: Newton solves with the
    /// multipliers of (E19) (ALM, penalty or none).
    StepReport
    constrained_step(const double dt);
    /// The inverse 2x2 Jacobian of (E21) from the linearised step.
    std::array<double, 4>
    linearised_alm_inverse(const double                 dt,
                           const std::array<double, 4> &fallback);
    void
    solve_potential(const dealii::TrilinosWrappers::MPI::Vector &phi_owned);
    dealii::TrilinosWrappers::MPI::Vector &
    ghost(const dealii::TrilinosWrappers::MPI::Vector &owned);

    const SplineDofHandler<dim>             &dofs;
    const dealii::AffineConstraints<double> &increment_constraints;
    const PhaseFieldFlowParameters           parameters;
    dealii::TimerOutput                     &timer;
    std::unique_ptr<ElectricPotential<dim>>  electric;
    BendingEnergy<dim>                       bending;
    std::vector<std::unique_ptr<Term<dim>>>  electric_terms;
    AreaConstraint<dim>                      area;
    VolumeConstraint<dim>                    volume;
    RateTerm<dim>                            rate;
    /// The energies (bending first), each also an Integrand.
    std::vector<Integrand<dim> *>                 energies;
    std::vector<std::string>                      names;
    SystemAssembler<dim>                          assembler;
    std::unique_ptr<JacobianSolver>               linear;
    std::unique_ptr<GeneralizedAlphaStepper<dim>> stepper;
    NewtonSolver                                  newton;
    ModifiedALM                                   alm;
    dealii::TrilinosWrappers::MPI::Vector         ghosted;
    double                                        V0 = 0, A0 = 0;
    Functionals                                   current, frozen;
    unsigned int                                  potential_iterations = 0;
    /// The ALM as the step found it (a rejected step or a fixed-point
    /// repetition starts from it again).
    std::optional<ModifiedALM> alm_at_step_start;
    /// Size of the step being solved (ModifiedALM::record_accepted_step).
    double step_size = 0;
  };
} // namespace vesicle_iga
