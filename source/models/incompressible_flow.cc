#include <deal.II/base/quadrature_lib.h>

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/fields/dirichlet_constraints.h>
#include <vesicle_iga/fields/natural_numbering.h>
#include <vesicle_iga/models/incompressible_flow.h>
#include <vesicle_iga/solvers/flow_block_preconditioner.h>
#include <vesicle_iga/solvers/gram_solver.h>
#include <vesicle_iga/solvers/spline_multigrid.h>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    /// The layout of the flow: velocity (differential) and pressure
    /// (algebraic) on one space, interleaved per basis function, then the
    /// fields of the coupling.
    template <int dim>
    FieldLayout<dim>
    flow_layout(const SplineSpace<dim>  &space,
                const FlowCoupling<dim> *coupling)
    {
      FieldLayout<dim> layout;
      layout.add_space(space);
      layout.add_field("velocity", dim, 0, FieldKind::differential, 0);
      layout.add_field("pressure", 1, 0, FieldKind::algebraic, 1);
      if (coupling)
        coupling->add_fields(layout);
      return layout;
    }


    /// Kinetic energy (1/2) |u|^2 and (div u)^2.
    template <int dim>
    class KineticEnergyAndDivergence : public Integrand<dim>
    {
    public:
      unsigned int
      n_values() const override
      {
        return 2;
      }
      void
      declare(TermDeclaration<dim> &d) override
      {
        for (unsigned int a = 0; a < dim; ++a)
          {
            u[a]  = d.value(a, Derivative<dim>::value);
            du[a] = d.value(a, Derivative<dim>::gradient(a));
          }
      }
      void
      integrate(const QuadratureInputs<dim> &in,
                const double                *JxW,
                double                      *sums) const override
      {
        for (unsigned int q = 0; q < in.size(); ++q)
          {
            double u2 = 0, div = 0;
            for (unsigned int a = 0; a < dim; ++a)
              {
                u2 += in[u[a]][q] * in[u[a]][q];
                div += in[du[a]][q];
              }
            sums[0] += 0.5 * u2 * JxW[q];
            sums[1] += div * div * JxW[q];
          }
      }

    private:
      std::array<InputHandle, dim> u, du;
    };


    /// The pressure average int p / |Omega|.
    template <int dim>
    class PressureMean : public Integrand<dim>
    {
    public:
      unsigned int
      n_values() const override
      {
        return 2;
      }
      void
      declare(TermDeclaration<dim> &d) override
      {
        p = d.value(dim, Derivative<dim>::value);
      }
      void
      integrate(const QuadratureInputs<dim> &in,
                const double                *JxW,
                double                      *sums) const override
      {
        for (unsigned int q = 0; q < in.size(); ++q)
          {
            sums[0] += in[p][q] * JxW[q];
            sums[1] += JxW[q];
          }
      }

    private:
      InputHandle p;
    };
  } // namespace


  template <int dim>
  IncompressibleFlow<dim>::IncompressibleFlow(
    const MPI_Comm                             comm,
    const SplineSpace<dim>                    &space_,
    const FlowCoefficients<dim>               &coefficients,
    const std::vector<VelocityCondition<dim>> &conditions,
    const IncompressibleFlowParameters        &parameters,
    TimerOutput                               &timer,
    FlowCoupling<dim>                         *coupling)
    : comm(comm)
    , space(space_)
    , patch_mesh(comm, space, nullptr)
    , dof_handler(patch_mesh, flow_layout(space, coupling))
    , coefficients(coefficients)
    , conditions(conditions)
    , parameters(parameters)
    , timer(timer)
    , rbvms(0, dim, coefficients)
    , lumped_schur(0, dim, coefficients)
    , assembler(dof_handler, QGauss<1>(parameters.quadrature_points))
    , newton(parameters.newton)
    , coupling(coupling)
  {
    TimerOutput::Scope scope(timer, "setup");
    // (H21): C_B = 5 (p + 1) unless given.
    const double C_B = parameters.weak_penalty_constant > 0 ?
                         parameters.weak_penalty_constant :
                         5. * (space.knot_vector(0).degree() + 1);
    assembler.add_term(rbvms);
    for (const auto &c : conditions)
      if (c.weak)
        {
          weak_terms.push_back(std::make_unique<WeakVelocityDirichlet<dim>>(
            0,
            dim,
            coefficients,
            c.where,
            *c.velocity,
            C_B,
            parameters.weak_inflow_term));
          assembler.add_term(*weak_terms.back());
        }
    if (coupling)
      for (Term<dim> *term : coupling->terms())
        assembler.add_term(*term);
    // The pressure control value of basis function 0 (a corner) fixes the
    // level when no boundary does; output and errors use the zero-mean
    // pressure.
    pinned_pressure = dof_handler.dof_index(0, dim);
    AffineConstraints<double> values(dof_handler.locally_relevant_dofs());
    boundary_values(0., values);
    values.close();
    increments.reinit(dof_handler.locally_relevant_dofs());
    // The homogeneous version: Dirichlet lines fix their increment to zero,
    // lines that tie a coefficient to others (du/dn = 0 of the phase
    // fields) tie the increments the same way.
    for (const auto &line : values.get_lines())
      {
        increments.add_line(line.index);
        increments.add_entries(line.index, line.entries);
      }
    increments.close();

    TrilinosWrappers::SparsityPattern sparsity;
    dof_handler.make_sparsity_pattern(sparsity);
    linear = std::make_unique<JacobianSolver>(parameters.solver,
                                              increments,
                                              sparsity,
                                              &timer);
    if (parameters.solver.method == "fgmres-block")
      setup_block_preconditioner();
    stepper = std::make_unique<GeneralizedAlphaStepper<dim>>(
      assembler,
      *linear,
      parameters.time_integration,
      [this](const double t, AffineConstraints<double> &c) {
        boundary_values(t, c);
      },
      &timer);
    ghosted_solution.reinit(dof_handler.locally_owned_dofs(),
                            dof_handler.locally_relevant_dofs(),
                            comm);
  }


  template <int dim>
  IncompressibleFlow<dim>::~IncompressibleFlow() = default;


  template <int dim>
  void
  IncompressibleFlow<dim>::boundary_values(const double               t,
                                           AffineConstraints<double> &c) const
  {
    std::vector<bool> velocity_components(dim + 1, true);
    velocity_components[dim] = false;
    for (const auto &condition : conditions)
      if (!condition.weak)
        {
          condition.velocity->set_time(t);
          add_strong_dirichlet_constraints<dim>(dof_handler,
                                                nullptr,
                                                condition.where,
                                                *condition.velocity,
                                                velocity_components,
                                                c);
        }
    if (coupling)
      coupling->boundary_values(dof_handler, t, c);
    if (parameters.fix_pressure_mean
        && dof_handler.locally_relevant_dofs().is_element(pinned_pressure)
        && !c.is_constrained(pinned_pressure))
      c.add_line(pinned_pressure);
  }


  template <int dim>
  std::shared_ptr<const TrilinosWrappers::SparseMatrix>
  IncompressibleFlow<dim>::pressure_mass_matrix() const
  {
    // The Gram matrix of the flow's spline space, numbered as the pressure
    // of the flow block (one scalar field on the same mesh: the same
    // owners and order of the basis functions), as the Jacobian of a rate
    // term with respect to the rate.
    const SplineDofHandler<dim> pressure_dofs(patch_mesh, space, 1);
    auto mass = std::make_shared<TrilinosWrappers::SparseMatrix>();
    assemble_gram_matrix(pressure_dofs,
                         assembler.get_quadrature(),
                         AffineConstraints<double>(),
                         *mass);
    return mass;
  }


  template <int dim>
  void
  IncompressibleFlow<dim>::setup_block_preconditioner()
  {
    const auto        &block = parameters.solver.block;
    const unsigned int nc    = dof_handler.n_components();
    auto preconditioner = std::make_unique<FlowBlockPreconditioner>(dim, block);
    if (block.velocity_preconditioner == "spline-multigrid")
      {
        // Velocity block row of (basis i, component c): new_index(i) dim +
        // c; constrained where the monolithic row is (the strong
        // conditions keep their unknowns from step to step).
        IndexSet velocity_owned(space.n_basis() * dim);
        for (const auto g : dof_handler.locally_owned_dofs())
          if (g % nc < dim)
            velocity_owned.add_index(g / nc * dim + g % nc);
        velocity_owned.compress();
        SplineMultigridParameters mg;
        mg.smoother    = block.velocity_smoother;
        mg.sweeps      = block.velocity_sweeps;
        mg.coarse_size = block.velocity_coarse_size;
        preconditioner->set_velocity_preconditioner(
          std::make_unique<SplineMultigrid<dim>>(
            dof_handler,
            dim,
            [this, nc](const unsigned int i, const unsigned int c) {
              return dof_handler.dof_index(i, 0) / nc * dim + c;
            },
            velocity_owned,
            [this, nc](const types::global_dof_index g) {
              return increments.is_constrained(g / dim * nc + g % dim);
            },
            mg));
      }
    if (block.schur_approximation == "stabilized-cahouet-chabard")
      preconditioner->set_pressure_mass(pressure_mass_matrix());
    // With coupled fields the coupling wraps the flow blocks.
    std::unique_ptr<LumpedOperatorPreconditioner> whole;
    if (coupling)
      {
        whole = coupling->block_preconditioner(std::move(preconditioner),
                                               dof_handler,
                                               increments,
                                               block);
        check_input(whole != nullptr,
                    "Linear solver/Method",
                    parameters.solver.method,
                    "direct, gmres-ilu or gmres-amg: the fields coupled to "
                    "the flow have no block preconditioner");
      }
    else
      whole = std::move(preconditioner);
    LumpedOperatorPreconditioner *target = whole.get();
    std::function<void()>         lumped_operators;
    if (block.schur_approximation == "cahouet-chabard"
        || block.schur_approximation == "stabilized-cahouet-chabard"
        || coupling)
      {
        schur_assembler
          = std::make_unique<SystemAssembler<dim>>(dof_handler,
                                                   assembler.get_quadrature());
        schur_assembler->add_term(lumped_schur);
        if (coupling)
          for (Term<dim> *term : coupling->lumped_operator_terms())
            schur_assembler->add_term(*term);
        // At the state of the Jacobian just assembled.
        lumped_operators = [this, target]() {
          const AssemblyState &state = stepper->stage();
          lumped_schur.set_factors(state.rate_factor[0],
                                   state.value_factor[dim]);
          if (coupling)
            coupling->prepare_lumped_operators(state);
          TrilinosWrappers::MPI::Vector lumped(dof_handler.locally_owned_dofs(),
                                               comm);
          const AffineConstraints<double> none;
          schur_assembler->assemble(state, none, &lumped, nullptr);
          target->set_lumped_operators(lumped);
        };
      }
    // Across steps: rebuilt when the step size (the rate factor of the
    // Jacobian's mass terms) changes.
    const bool across_steps
      = parameters.solver.preconditioner_reuse == "across-steps";
    linear->set_preconditioner(std::move(whole),
                               across_steps ?
                                 JacobianSolver::Reuse::across_steps :
                                 JacobianSolver::Reuse::every_matrix,
                               lumped_operators,
                               [this]() {
                                 return stepper->stage().rate_factor[0];
                               });
  }


  template <int dim>
  void
  IncompressibleFlow<dim>::set_initial_state(const Function<dim> &initial,
                                             const double         t0)
  {
    const unsigned int n = dof_handler.n_components();
    AssertThrow(initial.n_components == n,
                ExcDimensionMismatch(initial.n_components, n));
    std::vector<double> values(space.n_basis() * n, 0.);
    for (unsigned int i = 0; i < space.n_basis(); ++i)
      for (unsigned int c = 0; c < n; ++c)
        values[i * n + c] = initial.value(space.greville_point(i), c);
    TrilinosWrappers::MPI::Vector U(dof_handler.locally_owned_dofs(), comm);
    scatter_natural(dof_handler,
                    interpolate_at_greville_points(space, values, n),
                    U);
    AffineConstraints<double> c(dof_handler.locally_relevant_dofs());
    boundary_values(t0, c);
    c.close();
    c.distribute(U);
    stepper->set_initial_state(U, t0);
    update_ghosted_solution();
  }


  template <int dim>
  void
  IncompressibleFlow<dim>::set_state(const TrilinosWrappers::MPI::Vector &U,
                                     const TrilinosWrappers::MPI::Vector &rate,
                                     const double                         t)
  {
    stepper->set_state(U, rate, t);
    update_ghosted_solution();
  }


  template <int dim>
  StepReport
  IncompressibleFlow<dim>::solve_step(const double dt)
  {
    const double t = stepper->time() + dt;
    coefficients.set_time(t);
    for (const auto &c : conditions)
      c.velocity->set_time(t);
    const NewtonReport r = stepper->solve_step(newton, dt);
    return {r.iterations, r.krylov_iterations, {}};
  }


  template <int dim>
  void
  IncompressibleFlow<dim>::accept_step()
  {
    stepper->accept_step();
    update_ghosted_solution();
  }


  template <int dim>
  NewtonReport
  IncompressibleFlow<dim>::advance(const double dt)
  {
    const StepReport r = solve_step(dt);
    accept_step();
    NewtonReport report;
    report.iterations        = r.newton_iterations;
    report.krylov_iterations = r.krylov_iterations;
    return report;
  }


  template <int dim>
  void
  IncompressibleFlow<dim>::update_ghosted_solution()
  {
    ghosted_solution = stepper->solution();
    if (!parameters.fix_pressure_mean)
      return;
    // Shift the pressure to zero mean: the basis is a partition of unity,
    // so subtracting m from every pressure coefficient subtracts m.
    PressureMean<dim> mean;
    AssemblyState     state;
    state.value                        = &ghosted_solution;
    const auto                    sums = assembler.integrate({&mean}, state);
    TrilinosWrappers::MPI::Vector shifted(stepper->solution());
    const unsigned int            n = dof_handler.n_components();
    for (const auto i : dof_handler.locally_owned_dofs())
      if (i % n == dim)
        shifted[i] -= sums[0] / sums[1];
    shifted.compress(VectorOperation::insert);
    ghosted_solution = shifted;
  }


  template <int dim>
  std::pair<double, double>
  IncompressibleFlow<dim>::kinetic_energy_and_divergence() const
  {
    KineticEnergyAndDivergence<dim> integrand;
    AssemblyState                   state;
    state.value     = &ghosted_solution;
    const auto sums = assembler.integrate({&integrand}, state);
    return {sums[0], std::sqrt(sums[1])};
  }


  template <int dim>
  void
  IncompressibleFlow<dim>::save(Checkpoint &c, const std::string &prefix) const
  {
    stepper->save(c, prefix + ".stepper");
  }


  template <int dim>
  void
  IncompressibleFlow<dim>::drop_unsaved_state()
  {
    linear->forget_jacobian();
  }


  template <int dim>
  void
  IncompressibleFlow<dim>::load(const Checkpoint &c, const std::string &prefix)
  {
    stepper->load(c, prefix + ".stepper");
    update_ghosted_solution();
  }

  template class IncompressibleFlow<2>;
  template class IncompressibleFlow<3>;
} // namespace vesicle_iga
