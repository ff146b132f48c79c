#include <deal.II/base/quadrature_lib.h>

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vesicle_iga/base/solver_failure.h>
#include <vesicle_iga/kernel/jacobian_check.h>
#include <vesicle_iga/models/phase_field_flow.h>
#include <vesicle_iga/solvers/spline_multigrid.h>
#include <vesicle_iga/terms/dielectric_energies.h>
#include <vesicle_iga/terms/flexoelectric_energy.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  PhaseFieldFlow<dim>::PhaseFieldFlow(
    const SplineDofHandler<dim>     &dofs,
    const AffineConstraints<double> &increment_constraints,
    const PhaseFieldFlowParameters  &p,
    TimerOutput                     &timer)
    : dofs(dofs)
    , increment_constraints(increment_constraints)
    , parameters(p)
    , timer(timer)
    , bending(0, p.kappa, p.epsilon, p.spontaneous_curvature)
    , area(0, p.epsilon)
    , volume(0)
    , rate({0})
    , assembler(dofs, QGauss<1>(p.quadrature_points))
    , newton(p.newton)
    , alm(1.,
          1.,
          p.constraint_tolerance,
          p.max_alm_iterations,
          p.alm_first_update == "predicted drift" ?
            ModifiedALM::FirstUpdate::predicted_drift :
            ModifiedALM::FirstUpdate::carried_error)
  {
    // One pattern for the Jacobian and the potential's matrix: they share
    // its graph.
    TrilinosWrappers::SparsityPattern sparsity;
    dofs.make_sparsity_pattern(sparsity);
    const auto &m = p.material;
    energies      = {&bending};
    if (m.active())
      {
        // The electric energies (E6)-(E8) in the normalised units of spec
        // 3.10, each switchable; psi^n is auxiliary field 0.
        electric
          = std::make_unique<ElectricPotential<dim>>(dofs,
                                                     m,
                                                     QGauss<1>(
                                                       p.quadrature_points),
                                                     p.potential_solver,
                                                     timer,
                                                     &sparsity);
        assembler.add_auxiliary_field(dofs);
        if (m.flexoelectric)
          electric_terms.push_back(std::make_unique<FlexoelectricEnergy<dim>>(
            0, 0, m.flexoelectric_prefactor(p.epsilon), p.epsilon));
        if (m.membrane_dielectric)
          electric_terms.push_back(
            std::make_unique<MembraneDielectricEnergy<dim>>(
              0, 0, m.membrane_thickness(), m.permittivity(m.e_m), p.epsilon));
        if (m.electrolyte_dielectric)
          electric_terms.push_back(
            std::make_unique<ElectrolyteDielectricEnergy<dim>>(
              0, 0, m.permittivity(m.e_in), m.permittivity(m.e_out)));
        for (auto &t : electric_terms)
          energies.push_back(dynamic_cast<Integrand<dim> *>(t.get()));
      }
    // Summation order of (E18): energies, constraint terms, rate.
    assembler.add_term(bending);
    for (auto &t : electric_terms)
      assembler.add_term(*t);
    if (p.constraint_method != "none")
      {
        assembler.add_term(area);
        assembler.add_term(volume);
      }
    assembler.add_term(rate);

    linear = std::make_unique<JacobianSolver>(p.solver,
                                              increment_constraints,
                                              sparsity,
                                              &timer);
    if (p.solver.uses_multigrid())
      linear->set_preconditioner(
        std::make_unique<SplineMultigrid<dim>>(dofs,
                                               increment_constraints,
                                               p.solver.multigrid),
        JacobianSolver::Reuse::while_effective);
    stepper = std::make_unique<GeneralizedAlphaStepper<dim>>(
      assembler,
      *linear,
      p.time_integration,
      typename GeneralizedAlphaStepper<dim>::BoundaryValues(),
      &timer);
    if (electric)
      stepper->set_auxiliary_fields({&electric->potential()});
    ghosted.reinit(dofs.locally_owned_dofs(),
                   dofs.locally_relevant_dofs(),
                   dofs.get_mesh().get_communicator());
  }


  template <int dim>
  TrilinosWrappers::MPI::Vector &
  PhaseFieldFlow<dim>::ghost(const TrilinosWrappers::MPI::Vector &owned)
  {
    ghosted = owned;
    return ghosted;
  }


  template <int dim>
  std::vector<std::string>
  PhaseFieldFlow<dim>::energy_names() const
  {
    std::vector<std::string> n = {bending.name()};
    for (const auto &t : electric_terms)
      n.push_back(t->name());
    return n;
  }


  template <int dim>
  void
  PhaseFieldFlow<dim>::solve_potential(const TrilinosWrappers::MPI::Vector &phi)
  {
    if (!electric)
      return;
    potential_iterations += electric->solve(ghost(phi)).iterations;
  }


  template <int dim>
  unsigned int
  PhaseFieldFlow<dim>::take_potential_iterations()
  {
    const unsigned int n = potential_iterations;
    potential_iterations = 0;
    return n;
  }


  template <int dim>
  typename PhaseFieldFlow<dim>::Functionals
  PhaseFieldFlow<dim>::functionals(const TrilinosWrappers::MPI::Vector &phi)
  {
    TimerOutput::Scope            t(timer, "monitor");
    std::vector<Integrand<dim> *> integrands = energies;
    const bool constrained = parameters.constraint_method != "none";
    if (constrained)
      {
        integrands.push_back(&area);
        integrands.push_back(&volume);
      }
    AssemblyState state;
    state.value = &ghost(phi);
    if (electric)
      state.auxiliary = {&electric->potential()};
    const auto  sums = assembler.integrate(integrands, state);
    Functionals f;
    f.energies.assign(sums.begin(), sums.begin() + energies.size());
    for (const double e : f.energies)
      f.energy += e;
    if (constrained)
      {
        f.area   = sums[energies.size()];
        f.volume = sums[energies.size() + 1];
      }
    f.lagrangian = f.energy + area.multiplier() * (f.area - A0)
                   + volume.multiplier() * (f.volume - V0);
    return f;
  }


  template <int dim>
  void
  PhaseFieldFlow<dim>::set_initial_state(
    const TrilinosWrappers::MPI::Vector &phi0)
  {
    stepper->set_initial_state(phi0, 0.);
    solve_potential(phi0);
    current = functionals(phi0);
    V0      = current.volume;
    A0      = current.area;
    frozen  = current;
    alm.reset_targets(V0, A0);
  }


  template <int dim>
  void
  PhaseFieldFlow<dim>::set_constraint_targets(const double volume_target,
                                              const double area_target)
  {
    const double dv = volume_target - V0, da = area_target - A0;
    alm.shift_targets(dv, da);
    V0 = volume_target;
    A0 = area_target;
    // The Lagrangian (E14) is measured against the targets.
    const double change = -area.multiplier() * da - volume.multiplier() * dv;
    current.lagrangian += change;
    frozen.lagrangian += change;
  }


  template <int dim>
  StepReport
  PhaseFieldFlow<dim>::solve_step(const double dt)
  {
    alm_at_step_start = alm;
    step_size         = dt;
    StepReport report = constrained_step(dt);
    // Fixed-point coupling (spec 3.9 option): psi from phi_{n+1}, and the
    // step again from phi_n, until psi settles.
    unsigned int fixed_point_iterations = 0;
    while (electric && parameters.coupling == "fixed-point")
      {
        const TrilinosWrappers::MPI::Vector psi_old(
          electric->owned_potential());
        solve_potential(stepper->next_solution());
        TrilinosWrappers::MPI::Vector change(psi_old);
        change -= electric->owned_potential();
        if (change.l2_norm() <= parameters.fixed_point_tolerance
                                  * electric->owned_potential().l2_norm()
            || ++fixed_point_iterations
                 >= parameters.max_fixed_point_iterations)
          break;
        alm                    = *alm_at_step_start;
        const StepReport again = constrained_step(dt);
        report.newton_iterations += again.newton_iterations;
        report.krylov_iterations += again.krylov_iterations;
        report.counters = again.counters;
      }
    return report;
  }


  template <int dim>
  StepReport
  PhaseFieldFlow<dim>::constrained_step(const double dt)
  {
    StepReport report;
    report.counters         = {0.};
    const auto newton_solve = [&]() {
      const NewtonReport r = stepper->solve_step(newton, dt);
      report.newton_iterations += r.iterations;
      report.krylov_iterations += r.krylov_iterations;
    };
    const std::string &method = parameters.constraint_method;
    if (method == "penalty")
      {
        volume.set_multiplier(parameters.M1 * (current.volume - V0));
        area.set_multiplier(parameters.M2 * (current.area - A0));
      }
    if (method != "alm")
      {
        newton_solve();
        return report;
      }
    const auto solve = [&](double al, double be, double &v, double &a) {
      // (E19): multipliers explicit in V(phi_n), A(phi_n).
      volume.set_multiplier(parameters.M1 * (current.volume - al));
      area.set_multiplier(parameters.M2 * (current.area - be));
      newton_solve();
      AssemblyState state;
      state.value  = &ghost(stepper->next_solution());
      const auto f = assembler.integrate({&area, &volume}, state);
      a            = f[0];
      v            = f[1];
      return true;
    };
    const auto refresh = [&](std::array<double, 4> &T) {
      if (parameters.alm_jacobian != "linearised")
        return false;
      T = linearised_alm_inverse(dt, T);
      return true;
    };
    const auto r = alm.step(solve, current.volume, current.area, dt, refresh);
    report.counters[0] = r.iterations;
    if (!r.converged)
      {
        std::ostringstream s;
        s << "modified ALM: the constraints are not met after " << r.iterations
          << " iterations (|V/V0 - 1| = " << std::abs(r.volume / V0 - 1)
          << ", |A/A0 - 1| = " << std::abs(r.area / A0 - 1) << ", tolerance "
          << parameters.constraint_tolerance << ")";
        throw SolverFailure(s.str());
      }
    return report;
  }


  template <int dim>
  std::array<double, 4>
  PhaseFieldFlow<dim>::linearised_alm_inverse(
    const double                 dt,
    const std::array<double, 4> &fallback)
  {
    // T = d(V(phi_{n+1}), A(phi_{n+1})) / d(alpha, beta) of (E21) from the
    // linearisation of the step just solved: with g_V = (dV/dphi, N_i),
    // g_A = (dA/dphi, N_i) at that solution (the constraint terms of (E18)
    // with unit multiplier), dphi_{n+1}/dLambda_X = -gamma dt K^{-1} g_X,
    // dV/dLambda_X = g_V . dphi_{n+1}/dLambda_X (likewise A), and (E19)
    // gives dLambda_V/dalpha = -M1, dLambda_A/dbeta = -M2.
    // With full Newton the matrix is the tangent at the last iterate but
    // one; a Jacobian kept across solves may be steps old, and T from it
    // moved the ALM iterates (E_B by 2e-4 relative after two 3D steps,
    // doc/performance.md): assembled at the solution instead, it then
    // serves the next Newton solve as a fresh one.
    if (newton.get_parameters().keep_jacobian)
      stepper->assemble_jacobian_at_solution();
    TimerOutput::Scope    t(timer, "ALM Jacobian");
    VolumeConstraint<dim> unit_volume(0);
    AreaConstraint<dim>   unit_area(0, parameters.epsilon);
    unit_volume.set_multiplier(1.);
    unit_area.set_multiplier(1.);
    AssemblyState state;
    state.value = &ghost(stepper->next_solution());
    std::vector<TrilinosWrappers::MPI::Vector> g(2), x(2);
    Term<dim> *const terms[2] = {&unit_volume, &unit_area};
    for (unsigned int k = 0; k < 2; ++k)
      {
        SystemAssembler<dim> gradient(dofs, assembler.get_quadrature());
        gradient.add_term(*terms[k]);
        g[k].reinit(stepper->solution());
        gradient.assemble(state, increment_constraints, &g[k], nullptr);
        x[k].reinit(g[k]);
        linear->solve(x[k], g[k]);
      }
    const double c = -stepper->method().gamma * dt;
    // d(V, A)/d(Lambda_V, Lambda_A)
    const double dV_dLV = c * (g[0] * x[0]), dV_dLA = c * (g[0] * x[1]);
    const double dA_dLV = c * (g[1] * x[0]), dA_dLA = c * (g[1] * x[1]);
    const double T00 = -parameters.M1 * dV_dLV, T01 = -parameters.M2 * dV_dLA;
    const double T10 = -parameters.M1 * dA_dLV, T11 = -parameters.M2 * dA_dLA;
    const double det = T00 * T11 - T01 * T10;
    if (!std::isfinite(det) || std::abs(det) < 1e-300)
      return fallback;
    return {{T11 / det, -T01 / det, -T10 / det, T00 / det}};
  }


  template <int dim>
  void
  PhaseFieldFlow<dim>::accept_step()
  {
    stepper->accept_step();
    const Functionals before = current;
    const bool staggered     = electric && parameters.coupling != "fixed-point";
    // The step minimises E(phi, psi^n) with psi^n frozen (spec 3.9), so
    // that is the energy that must not rise over it: measured before psi
    // is updated. psi^{n+1} from the accepted phase field is the potential
    // of the next step (staggered) and the one energies are reported with.
    if (staggered)
      {
        frozen = functionals(solution());
        solve_potential(solution());
      }
    current = functionals(solution());
    if (!staggered)
      frozen = current;
    alm.record_accepted_step(current.volume - before.volume,
                             current.area - before.area,
                             step_size);
  }


  template <int dim>
  void
  PhaseFieldFlow<dim>::reject_step()
  {
    alm = *alm_at_step_start;
    if (electric && parameters.coupling == "fixed-point")
      solve_potential(solution());
  }


  namespace
  {
    /// The sums of interface_motion(): with phi the value and r the rate
    /// of the state, int r^2, int r grad phi, int grad phi grad phi^T.
    template <int dim>
    class InterfaceMotionSums : public Integrand<dim>
    {
    public:
      unsigned int
      n_values() const override
      {
        return 1 + dim + dim * dim;
      }
      void
      declare(TermDeclaration<dim> &d) override
      {
        r = d.rate(0, Derivative<dim>::value);
        for (unsigned int k = 0; k < dim; ++k)
          g[k] = d.value(0, Derivative<dim>::gradient(k));
      }
      void
      integrate(const QuadratureInputs<dim> &in,
                const double                *JxW,
                double                      *sum) const override
      {
        for (unsigned int q = 0; q < in.size(); ++q)
          {
            const double rq = in[r][q];
            sum[0] += rq * rq * JxW[q];
            for (unsigned int i = 0; i < dim; ++i)
              {
                sum[1 + i] += rq * in[g[i]][q] * JxW[q];
                for (unsigned int j = 0; j < dim; ++j)
                  sum[1 + dim + dim * i + j]
                    += in[g[i]][q] * in[g[j]][q] * JxW[q];
              }
          }
      }

    private:
      InputHandle                  r;
      std::array<InputHandle, dim> g;
    };
  } // namespace


  template <int dim>
  typename PhaseFieldFlow<dim>::InterfaceMotion
  PhaseFieldFlow<dim>::interface_motion(const double dt)
  {
    TimerOutput::Scope t(timer, "monitor");
    // With r = (phi_n - phi_{n-1}) / dt: the rigid velocity U that best
    // explains r, r ~ -U . grad phi (least squares: M U = -b with
    // M = (grad phi, grad phi^T), b = (r, grad phi)), and what is left,
    // ||r + U . grad phi||^2 = ||r||^2 + U . b.
    TrilinosWrappers::MPI::Vector change(solution());
    change -= previous_solution();
    change /= dt;
    TrilinosWrappers::MPI::Vector ghosted_change(ghosted);
    ghosted_change = change;
    InterfaceMotionSums<dim> sums_of;
    AssemblyState            state;
    state.value         = &ghost(solution());
    state.rate          = &ghosted_change;
    const auto     sums = assembler.integrate({&sums_of}, state);
    Tensor<2, dim> M;
    Tensor<1, dim> b;
    for (unsigned int i = 0; i < dim; ++i)
      {
        b[i] = sums[1 + i];
        for (unsigned int j = 0; j < dim; ++j)
          M[i][j] = sums[1 + dim + dim * i + j];
      }
    InterfaceMotion motion;
    const double    gradient_norm_sq = trace(M);
    // No interface left in the box (phi constant): nothing moves.
    if (!(determinant(M) > 1e-12 * std::pow(gradient_norm_sq, dim)))
      return motion;
    motion.drift                 = -(invert(M) * b);
    const double shape_change_sq = std::max(0., sums[0] + motion.drift * b);
    motion.speed = std::sqrt(shape_change_sq / gradient_norm_sq);
    return motion;
  }


  template <int dim>
  void
  PhaseFieldFlow<dim>::check_jacobian(std::ostream &out)
  {
    // At the initial state (phi_n, zero rate) with dt = 1, so that the
    // energy part alpha_f gamma dt DR of K (N4) dominates the mass part,
    // and non-zero multipliers.
    area.set_multiplier(0.3);
    volume.set_multiplier(0.2);
    const GeneralizedAlpha       &ga = stepper->method();
    TrilinosWrappers::MPI::Vector zero_rate(ghosted);
    zero_rate = 0;
    AssemblyState state;
    state.value = &ghost(solution());
    state.rate  = &zero_rate;
    if (electric)
      state.auxiliary = {&electric->potential()};
    state.value_factor = {ga.alpha_f * ga.gamma};
    state.rate_factor  = {ga.alpha_m};
    const auto result
      = vesicle_iga::check_jacobian(assembler,
                                    state,
                                    increment_constraints,
                                    test_direction(dofs, increment_constraints),
                                    {1e-2, 1e-3, 1e-4});
    out << "Jacobian check: |alpha_f gamma dt DR d| / |K d| = "
        << std::setprecision(3) << result.norm_value_part / result.norm_Kd
        << std::setprecision(6) << std::endl
        << "Jacobian check (tangent (E20) against central differences of the "
           "residual (E18)):"
        << std::endl;
    const std::vector<double> steps = {1e-2, 1e-3, 1e-4};
    for (unsigned int k = 0; k < steps.size(); ++k)
      out << "  h = " << steps[k]
          << ": |FD - K d| / |K d| = " << std::scientific
          << std::setprecision(1) << result.relative_difference[k]
          << std::defaultfloat << std::setprecision(6) << std::endl;
    area.set_multiplier(0);
    volume.set_multiplier(0);
  }


  template <int dim>
  void
  PhaseFieldFlow<dim>::save(Checkpoint &c, const std::string &prefix) const
  {
    stepper->save(c, prefix + ".stepper");
    alm.save(c, prefix + ".alm");
    c.scalars[prefix + ".area_multiplier"]   = area.multiplier();
    c.scalars[prefix + ".volume_multiplier"] = volume.multiplier();
  }


  template <int dim>
  void
  PhaseFieldFlow<dim>::drop_unsaved_state()
  {
    linear->forget_jacobian();
  }


  template <int dim>
  void
  PhaseFieldFlow<dim>::load(const Checkpoint &c, const std::string &prefix)
  {
    stepper->load(c, prefix + ".stepper");
    alm.load(c, prefix + ".alm");
    V0 = alm.volume_target();
    A0 = alm.area_target();
    area.set_multiplier(c.scalar(prefix + ".area_multiplier"));
    volume.set_multiplier(c.scalar(prefix + ".volume_multiplier"));
    solve_potential(solution());
    current = functionals(solution());
    frozen  = current;
  }

  template class PhaseFieldFlow<2>;
  template class PhaseFieldFlow<3>;
} // namespace vesicle_iga
