#include <vesicle_iga/io/field_checkpoint.h>
#include <vesicle_iga/time/generalized_alpha.h>
#include <vesicle_iga/time/local_error_estimate.h>

#include <optional>

namespace vesicle_iga
{
  using namespace dealii;

  void
  GeneralizedAlphaParameters::declare(ParameterHandler  &prm,
                                      const std::string &default_rho)
  {
    prm.declare_entry("rho_inf",
                      default_rho,
                      Patterns::Double(0, 1),
                      "Spectral radius at infinity of generalized-alpha (N3): "
                      "alpha_m = (3 - rho)/(2 (1 + rho)), alpha_f = 1/(1 + "
                      "rho), gamma = 1/2 + alpha_m - alpha_f.");
    prm.declare_entry("Algebraic fields at",
                      "t_n+1",
                      Patterns::Selection("t_n+1|t_n+alpha_f"),
                      "Where fields without a time derivative (pressure, "
                      "tension) are evaluated (spec 4.9: t_n+1 as written in "
                      "the source; t_n+alpha_f as PETSc's TSALPHA does).");
  }


  void
  GeneralizedAlphaParameters::parse(ParameterHandler &prm)
  {
    rho_inf          = prm.get_double("rho_inf");
    algebraic_at_end = prm.get("Algebraic fields at") == "t_n+1";
  }


  template <int dim>
  GeneralizedAlphaStepper<dim>::GeneralizedAlphaStepper(
    const SystemAssembler<dim> &assembler,
    JacobianSolver             &jacobian_solver,
    const Parameters           &parameters,
    const BoundaryValues       &boundary_values,
    TimerOutput                *timer)
    : assembler(assembler)
    , dofs(assembler.get_dofs())
    , linear(jacobian_solver)
    , alpha(parameters.rho_inf)
    , algebraic_at_end(parameters.algebraic_at_end)
    , boundary_values(boundary_values)
    , timer(timer)
  {
    const MPI_Comm comm   = dofs.get_mesh().get_communicator();
    const auto    &owned  = dofs.locally_owned_dofs();
    const auto    &layout = dofs.get_layout();
    for (auto *v : {&U, &U_rate, &U_previous, &U_next, &rate_next})
      v->reinit(owned, comm);
    stage_value.reinit(owned, dofs.locally_relevant_dofs(), comm);
    stage_rate.reinit(stage_value);
    for (unsigned int k = 0; k < layout.n_components(); ++k)
      if (layout.field(layout.field_of_component(k)).kind
          == FieldKind::algebraic)
        for (unsigned int i = 0; i < dofs.component_space(k).n_basis(); ++i)
          if (owned.is_element(dofs.dof_index(i, k)))
            algebraic_dofs.push_back(dofs.dof_index(i, k));
  }


  template <int dim>
  void
  GeneralizedAlphaStepper<dim>::set_initial_state(
    const TrilinosWrappers::MPI::Vector &U0,
    const double                         t0)
  {
    U           = U0;
    U_previous  = U0;
    U_rate      = 0;
    t           = t0;
    dt_previous = 0;
  }


  template <int dim>
  void
  GeneralizedAlphaStepper<dim>::set_state(
    const TrilinosWrappers::MPI::Vector &U_n,
    const TrilinosWrappers::MPI::Vector &rate_n,
    const double                         t_n)
  {
    set_initial_state(U_n, t_n);
    U_rate = rate_n;
  }


  template <int dim>
  void
  GeneralizedAlphaStepper<dim>::set_stage(
    const TrilinosWrappers::MPI::Vector &rate_n1)
  {
    const double g = alpha.gamma;
    // (N2): U_{n+1} = U_n + dt rate_n + gamma dt (rate_{n+1} - rate_n).
    TrilinosWrappers::MPI::Vector U_n1(U), tmp(U);
    U_n1.add(dt * (1 - g), U_rate, g * dt, rate_n1);
    tmp.sadd(1 - alpha.alpha_f, alpha.alpha_f, U_n1);
    if (algebraic_at_end)
      {
        for (const auto i : algebraic_dofs)
          tmp[i] = U_n1[i];
        tmp.compress(VectorOperation::insert);
      }
    stage_value = tmp;
    tmp         = U_rate;
    tmp.sadd(1 - alpha.alpha_m, alpha.alpha_m, rate_n1);
    stage_rate = tmp;

    const auto &layout = dofs.get_layout();
    state.value        = &stage_value;
    state.rate         = &stage_rate;
    state.auxiliary    = auxiliary;
    state.value_factor.resize(layout.n_components());
    state.rate_factor.assign(layout.n_components(), alpha.alpha_m);
    for (unsigned int k = 0; k < layout.n_components(); ++k)
      {
        const bool algebraic = layout.field(layout.field_of_component(k)).kind
                               == FieldKind::algebraic;
        state.value_factor[k]
          = (algebraic && algebraic_at_end ? 1. : alpha.alpha_f) * g * dt;
      }
    state.time      = t + dt;
    state.time_step = dt;
  }


  template <int dim>
  void
  GeneralizedAlphaStepper<dim>::assemble(
    const TrilinosWrappers::MPI::Vector &rate_n1,
    TrilinosWrappers::MPI::Vector       *residual,
    const bool                           jacobian)
  {
    std::optional<TimerOutput::Scope> scope;
    if (timer)
      scope.emplace(*timer, jacobian ? "assembly" : "residual");
    set_stage(rate_n1);
    assembler.assemble(state,
                       linear.constraints(),
                       residual,
                       jacobian ? &linear.matrix() : nullptr);
  }


  template <int dim>
  NewtonReport
  GeneralizedAlphaStepper<dim>::solve_step(const NewtonSolver &newton,
                                           const double        step)
  {
    dt             = step;
    const double g = alpha.gamma;
    // Predictor (spec 2.4, step 1): U_{n+1} = U_n with the boundary values
    // at t_{n+1}, and the rate (N2) needs for it.
    U_next = U;
    if (boundary_values)
      {
        AffineConstraints<double> values(dofs.locally_relevant_dofs());
        boundary_values(t + dt, values);
        values.close();
        values.distribute(U_next);
      }
    rate_next = U_next;
    rate_next.add(-1., U, -dt * (1 - g), U_rate);
    rate_next /= g * dt;
    const NewtonReport report = newton.solve(*this, rate_next);
    U_next                    = U;
    U_next.add(dt * (1 - g), U_rate, g * dt, rate_next);
    return report;
  }


  template <int dim>
  void
  GeneralizedAlphaStepper<dim>::assemble_jacobian_at_solution()
  {
    assemble(rate_next, nullptr, true);
    linear.matrix_changed(false, dt);
  }


  template <int dim>
  void
  GeneralizedAlphaStepper<dim>::accept_step()
  {
    U_previous = U;
    U          = U_next;
    U_rate     = rate_next;
    t += dt;
    dt_previous = dt;
  }


  template <int dim>
  double
  GeneralizedAlphaStepper<dim>::local_error(
    const double             atol,
    const double             rtol,
    const std::vector<bool> *selected) const
  {
    if (dt_previous <= 0)
      return -1;
    return local_error_norm(
      U_next, U, U_previous, dt, dt_previous, atol, rtol, selected);
  }


  template <int dim>
  void
  GeneralizedAlphaStepper<dim>::save(Checkpoint        &c,
                                     const std::string &prefix) const
  {
    save_field(c, prefix + ".solution", dofs, U);
    save_field(c, prefix + ".rate", dofs, U_rate);
    save_field(c, prefix + ".previous_solution", dofs, U_previous);
    c.scalars[prefix + ".time"]          = t;
    c.scalars[prefix + ".previous_step"] = dt_previous;
  }


  template <int dim>
  void
  GeneralizedAlphaStepper<dim>::load(const Checkpoint  &c,
                                     const std::string &prefix)
  {
    load_field(c, prefix + ".solution", dofs, U);
    load_field(c, prefix + ".rate", dofs, U_rate);
    load_field(c, prefix + ".previous_solution", dofs, U_previous);
    t           = c.scalar(prefix + ".time");
    dt_previous = c.scalar(prefix + ".previous_step");
  }

  template class GeneralizedAlphaStepper<2>;
  template class GeneralizedAlphaStepper<3>;
} // namespace vesicle_iga
