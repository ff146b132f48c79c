// Generalized-alpha Newton steps of the RBVMS flow (spec (N2)-(N4), 4.9,
// 4.10). See the header.

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vesicle_iga/assembly/assembler.h>
#include <vesicle_iga/assembly/dirichlet_constraints.h>
#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/parallel/natural_numbering.h>
#include <vesicle_iga/solvers/navier_stokes_solver.h>

#include <cmath>
#include <stdexcept>

namespace vesicle_iga
{
  template <int dim>
  NavierStokesSolver<dim>::NavierStokesSolver(
    const MPI_Comm                             comm,
    const SplineSpace<dim>                    &space,
    const FlowCoefficients<dim>               &coefficients,
    const std::vector<VelocityCondition<dim>> &conditions,
    const double                               weak_penalty_constant,
    const bool                                 weak_inflow_term,
    const bool                                 fix_pressure_mean,
    const Quadrature<1>                       &quadrature,
    const LinearSolverParameters              &linear_solver,
    const FlowNewtonParameters                &newton,
    const double                               rho_inf,
    const bool                                 pressure_at_end,
    TimerOutput                               &timer)
    : comm(comm)
    , space(space)
    , patch_mesh(comm, this->space, nullptr)
    , dof_handler(patch_mesh, this->space, dim + 1)
    , coefficients(coefficients)
    , conditions(conditions)
    , fix_pressure_mean(fix_pressure_mean)
    , quadrature(quadrature)
    , linear_solver(linear_solver)
    , newton(newton)
    , alpha(rho_inf)
    , pressure_at_end(pressure_at_end)
    , timer(timer)
    , rbvms(dof_handler, coefficients)
    , lumped_schur(dof_handler, coefficients)
  {
    // (H21): C_B = 5 (p + 1) unless given.
    const double C_B = weak_penalty_constant > 0 ?
                         weak_penalty_constant :
                         5. * (space.knot_vector(0).degree() + 1);
    for (const auto &c : conditions)
      if (c.weak)
        weak_terms.push_back(
          std::make_unique<WeakVelocityDirichlet<dim>>(dof_handler,
                                                       coefficients,
                                                       c.where,
                                                       *c.velocity,
                                                       C_B,
                                                       weak_inflow_term));
    // The pressure control value of basis function 0 (a corner) fixes the
    // level when no boundary does; output and errors use the zero-mean
    // pressure.
    pinned_pressure = dof_handler.dof_index(0, dim);
    if (linear_solver.method == "fgmres-block")
      block_preconditioner
        = std::make_unique<FlowBlockPreconditioner>(dim, linear_solver.block);

    TimerOutput::Scope                scope(timer, "flow setup");
    TrilinosWrappers::SparsityPattern sparsity;
    dof_handler.make_sparsity_pattern(sparsity);
    system_matrix.reinit(sparsity);
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    U.reinit(owned, comm);
    U_rate.reinit(owned, comm);
    for (auto *v : {&U_alpha, &rate_alpha, &U_end, &ghosted_solution})
      v->reinit(owned, dof_handler.locally_relevant_dofs(), comm);
  }


  template <int dim>
  void
  NavierStokesSolver<dim>::make_constraints(const double time)
  {
    constraints.clear();
    constraints.reinit(dof_handler.locally_relevant_dofs());
    std::vector<bool> velocity_components(dim + 1, true);
    velocity_components[dim] = false;
    for (const auto &c : conditions)
      if (!c.weak)
        {
          c.velocity->set_time(time);
          add_strong_dirichlet_constraints<dim>(dof_handler,
                                                nullptr,
                                                c.where,
                                                *c.velocity,
                                                velocity_components,
                                                constraints);
        }
    if (fix_pressure_mean
        && dof_handler.locally_relevant_dofs().is_element(pinned_pressure))
      constraints.add_line(pinned_pressure);
    constraints.close();

    increment_constraints.clear();
    increment_constraints.reinit(dof_handler.locally_relevant_dofs());
    for (const auto &line : constraints.get_lines())
      increment_constraints.add_line(line.index);
    increment_constraints.close();
  }


  template <int dim>
  void
  NavierStokesSolver<dim>::set_initial_state(const Function<dim> &velocity,
                                             const double         t0)
  {
    t = t0;
    std::vector<double> values(space.n_basis() * (dim + 1), 0.);
    for (unsigned int i = 0; i < space.n_basis(); ++i)
      for (unsigned int c = 0; c < dim; ++c)
        values[i * (dim + 1) + c] = velocity.value(space.greville_point(i), c);
    scatter_natural(dof_handler,
                    interpolate_at_greville_points(space, values, dim + 1),
                    U);
    U_rate = 0;
    make_constraints(t);
    constraints.distribute(U);
    update_ghosted_solution();
  }


  template <int dim>
  void
  NavierStokesSolver<dim>::set_state(
    const TrilinosWrappers::MPI::Vector &solution,
    const TrilinosWrappers::MPI::Vector &rate,
    const double                         time)
  {
    U      = solution;
    U_rate = rate;
    t      = time;
    update_ghosted_solution();
  }


  template <int dim>
  void
  NavierStokesSolver<dim>::set_levels(
    const TrilinosWrappers::MPI::Vector &rate_n1,
    const double                         dt,
    const bool                           with_matrix)
  {
    // (N2): U_{n+1} = U_n + dt rate_n + gamma dt (rate_{n+1} - rate_n).
    TrilinosWrappers::MPI::Vector U_n1(U), tmp(U);
    U_n1.add(dt * (1 - alpha.gamma), U_rate, alpha.gamma * dt, rate_n1);
    tmp = U;
    tmp.sadd(1 - alpha.alpha_f, alpha.alpha_f, U_n1);
    U_alpha = tmp;
    tmp     = U_rate;
    tmp.sadd(1 - alpha.alpha_m, alpha.alpha_m, rate_n1);
    rate_alpha = tmp;
    U_end      = pressure_at_end ? U_n1 : U_alpha;

    FlowState state;
    state.velocity        = &U_alpha;
    state.velocity_rate   = &rate_alpha;
    state.pressure        = &U_end;
    state.rate_factor     = alpha.alpha_m;
    state.velocity_factor = alpha.alpha_f * alpha.gamma * dt;
    state.pressure_factor
      = pressure_at_end ? alpha.gamma * dt : alpha.alpha_f * alpha.gamma * dt;
    state.dt          = dt;
    state.with_matrix = with_matrix;
    rbvms.set_state(state);
    lumped_schur.set_state(state);
    for (auto &w : weak_terms)
      w->set_state(state);
  }


  template <int dim>
  void
  NavierStokesSolver<dim>::assemble(
    const TrilinosWrappers::MPI::Vector &rate_n1,
    const double                         dt,
    const bool                           with_matrix,
    TrilinosWrappers::MPI::Vector       &residual)
  {
    make_constraints(t + dt);
    assemble_system(rate_n1, dt, with_matrix, residual);
  }


  template <int dim>
  void
  NavierStokesSolver<dim>::assemble_system(
    const TrilinosWrappers::MPI::Vector &rate_n1,
    const double                         dt,
    const bool                           with_matrix,
    TrilinosWrappers::MPI::Vector       &residual)
  {
    set_levels(rate_n1, dt, with_matrix);
    std::vector<const AssemblyTerm<dim> *> terms{&rbvms};
    for (auto &w : weak_terms)
      terms.push_back(w.get());
    for (auto *e : extra_terms)
      terms.push_back(e);
    residual.reinit(dof_handler.locally_owned_dofs(), comm);
    if (with_matrix)
      {
        TimerOutput::Scope scope(timer, "flow assembly");
        system_matrix = 0;
        assemble_linear_system<dim>(dof_handler,
                                    nullptr,
                                    quadrature,
                                    terms,
                                    increment_constraints,
                                    system_matrix,
                                    residual);
      }
    else
      {
        TimerOutput::Scope scope(timer, "flow residual");
        assemble_vector<dim>(dof_handler,
                             nullptr,
                             quadrature,
                             terms,
                             increment_constraints,
                             residual);
      }
    // The terms add -R.
    residual *= -1.;
  }


  template <int dim>
  FlowStepResult
  NavierStokesSolver<dim>::advance(const double dt)
  {
    FlowStepResult result{false, 0, 0, 0.};
    make_constraints(t + dt);

    // Predictor (spec 2.4): U_{n+1} = U_n, rate_{n+1} = (gamma-1)/gamma
    // rate_n; then the strong boundary values at t_{n+1}, with the rate that
    // (N2) needs to reach them.
    TrilinosWrappers::MPI::Vector U_n1(U), rate_n1(U_rate);
    constraints.distribute(U_n1);
    rate_n1 = U_n1;
    rate_n1.add(-1., U, -dt * (1 - alpha.gamma), U_rate);
    rate_n1 /= alpha.gamma * dt;

    TrilinosWrappers::MPI::Vector residual, increment(U);
    double                        initial_residual = 0;
    for (unsigned int it = 0;; ++it)
      {
        const bool last = it == newton.max_iterations;
        assemble_system(rate_n1, dt, !last, residual);
        const double r = residual.l2_norm();
        if (!std::isfinite(r))
          break;
        if (it == 0)
          initial_residual = r;
        result.residual = r;
        if (r <= std::max(newton.relative_tolerance * initial_residual,
                          newton.absolute_tolerance))
          {
            result.converged = true;
            break;
          }
        if (last)
          break;
        residual *= -1.;
        increment = 0;
        LinearSolveResult solve;
        try
          {
            if (block_preconditioner)
              {
                TimerOutput::Scope scope(timer, "flow preconditioner setup");
                if (linear_solver.block.velocity_preconditioner
                      == "spline-multigrid"
                    && !velocity_multigrid_set)
                  {
                    // Velocity block row of (basis i, component c):
                    // new_index(i) dim + c; constrained where the
                    // monolithic row is (the strong conditions keep their
                    // unknowns from step to step).
                    IndexSet velocity_owned(space.n_basis() * dim);
                    for (const auto g : dof_handler.locally_owned_dofs())
                      if (g % (dim + 1) < dim)
                        velocity_owned.add_index(g / (dim + 1) * dim
                                                 + g % (dim + 1));
                    velocity_owned.compress();
                    SplineMultigridParameters mg;
                    mg.smoother    = linear_solver.block.velocity_smoother;
                    mg.sweeps      = linear_solver.block.velocity_sweeps;
                    mg.coarse_size = linear_solver.block.velocity_coarse_size;
                    block_preconditioner->set_velocity_preconditioner(
                      std::make_unique<SplineMultigrid<dim>>(
                        dof_handler,
                        dim,
                        [this](const unsigned int i, const unsigned int c) {
                          return dof_handler.dof_index(i, 0) / (dim + 1) * dim
                                 + c;
                        },
                        velocity_owned,
                        [this](const types::global_dof_index g) {
                          return increment_constraints.is_constrained(
                            g / dim * (dim + 1) + g % dim);
                        },
                        mg));
                    velocity_multigrid_set = true;
                  }
                if (linear_solver.block.schur_approximation
                    == "cahouet-chabard")
                  {
                    // At the state of this iteration (set by the assembly).
                    TrilinosWrappers::MPI::Vector lumped(
                      dof_handler.locally_owned_dofs(), comm);
                    const AffineConstraints<double> none;
                    assemble_vector<dim>(dof_handler,
                                         nullptr,
                                         quadrature,
                                         {&lumped_schur},
                                         none,
                                         lumped);
                    block_preconditioner->set_lumped_operators(lumped);
                  }
                block_preconditioner->initialize(system_matrix);
              }
            TimerOutput::Scope scope(timer, "flow linear solve");
            solve = solve_linear_system(linear_solver,
                                        system_matrix,
                                        increment,
                                        residual,
                                        increment_constraints,
                                        block_preconditioner.get());
          }
        catch (const InputError &)
          {
            throw;
          }
        catch (const std::runtime_error &)
          {
            // A Krylov failure fails the step: the caller may retry with a
            // smaller dt (the state is unchanged).
            return result;
          }
        result.krylov_iterations += solve.iterations;
        ++result.newton_iterations;
        rate_n1 += increment;
      }
    if (!result.converged)
      return result;

    U.add(dt * (1 - alpha.gamma), U_rate, alpha.gamma * dt, rate_n1);
    U_rate = rate_n1;
    t += dt;
    update_ghosted_solution();
    return result;
  }


  template <int dim>
  void
  NavierStokesSolver<dim>::update_ghosted_solution()
  {
    ghosted_solution = U;
    if (!fix_pressure_mean)
      return;
    // Shift the pressure to zero mean: the basis is a partition of unity,
    // so subtracting m from every pressure coefficient subtracts m.
    const auto sums
      = integrate_field<dim>(dof_handler,
                             nullptr,
                             quadrature,
                             0,
                             ghosted_solution,
                             2,
                             [](const SplineCellValues<dim>            &v,
                                const unsigned int                      q,
                                const std::vector<std::vector<double>> &c,
                                std::vector<double>                    &s) {
                               s[0] += v.value(c[dim], q) * v.JxW(q);
                               s[1] += v.JxW(q);
                             });
    TrilinosWrappers::MPI::Vector shifted(U);
    for (const auto i : dof_handler.locally_owned_dofs())
      if (i % (dim + 1) == dim)
        shifted[i] -= sums[0] / sums[1];
    shifted.compress(VectorOperation::insert);
    ghosted_solution = shifted;
  }


  template <int dim>
  std::pair<double, double>
  NavierStokesSolver<dim>::kinetic_energy_and_divergence() const
  {
    const auto sums
      = integrate_field<dim>(dof_handler,
                             nullptr,
                             quadrature,
                             1,
                             ghosted_solution,
                             2,
                             [](const SplineCellValues<dim>            &v,
                                const unsigned int                      q,
                                const std::vector<std::vector<double>> &c,
                                std::vector<double>                    &s) {
                               double u2 = 0, div = 0;
                               for (unsigned int a = 0; a < dim; ++a)
                                 {
                                   u2 += std::pow(v.value(c[a], q), 2);
                                   div += v.gradient(c[a], q)[a];
                                 }
                               s[0] += 0.5 * u2 * v.JxW(q);
                               s[1] += div * div * v.JxW(q);
                             });
    return {sums[0], std::sqrt(sums[1])};
  }


  template class NavierStokesSolver<2>;
  template class NavierStokesSolver<3>;
} // namespace vesicle_iga
