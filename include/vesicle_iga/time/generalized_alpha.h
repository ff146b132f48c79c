#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/io/checkpoint.h>
#include <vesicle_iga/kernel/system_assembler.h>
#include <vesicle_iga/solvers/newton.h>

#include <functional>
#include <limits>
#include <vector>

namespace vesicle_iga
{
  /**
   * Parameters of the first-order generalized-alpha method
   * (Jansen-Whiting-Hulbert), spec (N2)-(N3): second order for any
   * rho_inf in [0,1], unconditionally stable for linear problems.
   */
  struct GeneralizedAlpha
  {
    explicit GeneralizedAlpha(const double rho_inf)
      : rho_inf(rho_inf)
      , alpha_m(0.5 * (3 - rho_inf) / (1 + rho_inf))
      , alpha_f(1 / (1 + rho_inf))
      , gamma(0.5 + alpha_m - alpha_f)
    {}
    /// The step size at which the step matrix alpha_m M + alpha_f gamma dt
    /// K of a mode growing at @p growth_rate (K = -sigma M) turns singular:
    /// alpha_m / (alpha_f gamma sigma); infinity for a mode that does not
    /// grow (the method is unconditionally stable for those).
    double
    singular_step(const double growth_rate) const
    {
      return growth_rate > 0 ? alpha_m / (alpha_f * gamma * growth_rate) :
                               std::numeric_limits<double>::infinity();
    }
    double rho_inf, alpha_m, alpha_f, gamma;
  };


  /// Settings of GeneralizedAlphaStepper.
  struct GeneralizedAlphaParameters
  {
    double rho_inf          = 0.5;
    bool   algebraic_at_end = true;

    /// Entries "rho_inf" and "Algebraic fields at" of the current
    /// subsection.
    static void
    declare(dealii::ParameterHandler &prm, const std::string &default_rho);
    void
    parse(dealii::ParameterHandler &prm);
  };


  /**
   * One generalized-alpha step of a system of fields (spec 2.4, 4.9) as a
   * NonlinearProblem for Newton: it holds U_n, its rate and U_{n-1}; the
   * Newton unknown is the rate at t_{n+1}; from it follow (N2)
   *   U_{n+1}          = U_n + dt rate_n + gamma dt (rate_{n+1} - rate_n),
   *   rate_{n+alpha_m} = rate_n + alpha_m (rate_{n+1} - rate_n),
   *   U_{n+alpha_f}    = U_n + alpha_f (U_{n+1} - U_n),
   * the stage values each component is evaluated at (a differential field
   * at t_{n+alpha_f}, an algebraic one at t_{n+1} or t_{n+alpha_f}, a
   * parameter, spec 4.9) and the Jacobian factors of (N4) (alpha_m for the
   * rate, alpha_f gamma dt or gamma dt for the values). The predictor is
   * U_{n+1} = U_n with the strong boundary values at t_{n+1} and the rate
   * that (N2) needs for it (spec 2.4 step 1; (gamma - 1)/gamma rate_n where
   * nothing is prescribed).
   */
  template <int dim>
  class GeneralizedAlphaStepper : public NonlinearProblem, public Checkpointable
  {
  public:
    using Parameters = GeneralizedAlphaParameters;

    /// Strong boundary values of the fields at time t (inhomogeneous
    /// constraints with the lines of the increment constraints).
    using BoundaryValues
      = std::function<void(const double, dealii::AffineConstraints<double> &)>;

    /// @p timer (optional): sections "residual" and "assembly" (a
    /// Jacobian, with or without the residual).
    GeneralizedAlphaStepper(const SystemAssembler<dim> &assembler,
                            JacobianSolver             &jacobian_solver,
                            const Parameters           &parameters,
                            const BoundaryValues       &boundary_values = {},
                            dealii::TimerOutput        *timer = nullptr);

    /// U(t0) = @p U0 (owned layout), zero rate.
    void
    set_initial_state(const dealii::TrilinosWrappers::MPI::Vector &U0,
                      const double                                 t0);
    /// U_n, its rate and the time (U_{n-1} = U_n, no previous step).
    void
    set_state(const dealii::TrilinosWrappers::MPI::Vector &U_n,
              const dealii::TrilinosWrappers::MPI::Vector &rate_n,
              const double                                 t_n);
    /// Auxiliary fields of the assembler (ghosted), in its order.
    void
    set_auxiliary_fields(
      const std::vector<const dealii::TrilinosWrappers::MPI::Vector *> &fields)
    {
      auxiliary = fields;
    }

    /// Solve the step t_n -> t_n + dt (Newton on the rate); the result is
    /// next_solution() until accept_step(). Throws SolverFailure.
    NewtonReport
    solve_step(const NewtonSolver &newton, const double dt);
    /// Accept the last solved step: U_{n-1} <- U_n <- U_{n+1}, t += dt.
    void
    accept_step();
    /// The Jacobian at the step just solved (its converged rate) into the
    /// Jacobian solver's matrix: for solves with the tangent at the solution
    /// (the linearised ALM inverse) when Newton keeps an older Jacobian.
    void
    assemble_jacobian_at_solution();

    double
    time() const
    {
      return t;
    }
    /// dt of the last accepted step (0 before the first).
    double
    previous_step() const
    {
      return dt_previous;
    }
    const dealii::TrilinosWrappers::MPI::Vector &
    solution() const
    {
      return U;
    }
    const dealii::TrilinosWrappers::MPI::Vector &
    rate() const
    {
      return U_rate;
    }
    const dealii::TrilinosWrappers::MPI::Vector &
    previous_solution() const
    {
      return U_previous;
    }
    const dealii::TrilinosWrappers::MPI::Vector &
    next_solution() const
    {
      return U_next;
    }
    /// The stage of a step of size @p step at the trial rate @p rate_n1
    /// (what assemble() evaluates at; for tests and checks).
    const AssemblyState &
    stage_at(const dealii::TrilinosWrappers::MPI::Vector &rate_n1,
             const double                                 step)
    {
      dt = step;
      set_stage(rate_n1);
      return state;
    }
    /// The state at the stage of the last assembly (for the step just
    /// solved: the converged stage).
    const AssemblyState &
    stage() const
    {
      return state;
    }
    const GeneralizedAlpha &
    method() const
    {
      return alpha;
    }
    /// Weighted RMS norm of the local error estimate (N5) of the solved
    /// step; < 0 before two accepted steps.
    double
    local_error(const double             atol,
                const double             rtol,
                const std::vector<bool> *selected = nullptr) const;

    // NonlinearProblem: x is the rate at t_{n+1}.
    void
    assemble(const dealii::TrilinosWrappers::MPI::Vector &rate_n1,
             dealii::TrilinosWrappers::MPI::Vector       *residual,
             const bool                                   jacobian) override;
    JacobianSolver &
    jacobian_solver() override
    {
      return linear;
    }
    /// The step size: the Jacobian is alpha_m M + alpha_f gamma dt K (N3).
    double
    jacobian_scale() const override
    {
      return dt;
    }

    // Checkpointable: U_n, its rate, U_{n-1}, t, the last dt.
    void
    save(Checkpoint &c, const std::string &prefix) const override;
    void
    load(const Checkpoint &c, const std::string &prefix) override;

  private:
    void
    set_stage(const dealii::TrilinosWrappers::MPI::Vector &rate_n1);

    const SystemAssembler<dim>  &assembler;
    const SplineDofHandler<dim> &dofs;
    JacobianSolver              &linear;
    const GeneralizedAlpha       alpha;
    const bool                   algebraic_at_end;
    const BoundaryValues         boundary_values;
    dealii::TimerOutput         *timer;
    /// Owned entries of the algebraic components.
    std::vector<dealii::types::global_dof_index> algebraic_dofs;

    dealii::TrilinosWrappers::MPI::Vector U, U_rate, U_previous;
    dealii::TrilinosWrappers::MPI::Vector U_next, rate_next;
    dealii::TrilinosWrappers::MPI::Vector stage_value, stage_rate; // ghosted
    std::vector<const dealii::TrilinosWrappers::MPI::Vector *> auxiliary;
    AssemblyState                                              state;
    double t = 0, dt = 0, dt_previous = 0;
  };
} // namespace vesicle_iga
