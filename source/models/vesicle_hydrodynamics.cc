// N vesicles in an RBVMS flow, spec Part H (4.3-4.13), mixed-free (4.13):
// the fields and terms of the vesicles coupled to IncompressibleFlow, the
// global multipliers (H13), the measures of 4.12.

#include <deal.II/base/function.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/base/solver_failure.h>
#include <vesicle_iga/fields/dirichlet_constraints.h>
#include <vesicle_iga/models/vesicle_hydrodynamics.h>
#include <vesicle_iga/solvers/gram_solver.h>
#include <vesicle_iga/solvers/multiplier_secant.h>
#include <vesicle_iga/solvers/vesicle_block_preconditioner.h>
#include <vesicle_iga/time/generalized_alpha.h>

#include <cmath>
#include <limits>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    /// Per vesicle: A (H12c), V (int phi of (H12c), or int chi(phi) with
    /// 'Volume multiplier = indicator'), and the zeroth, first and second
    /// moments of the indicator c = (1 + phi) / 2 (spec 4.12). The sums: 0 A, 1
    /// V, 2 int c, 3-4 the x and y first moments, 5-7 the x-y second moments,
    /// 8-11 the circular moments of periodic x and y, in 3D 12 the z first
    /// moment and 13-14 the circular moments of periodic z.
    template <int dim>
    class VesicleGeometry : public Integrand<dim>
    {
    public:
      static constexpr unsigned int n_sums = dim == 2 ? 12 : 15;

      /// Moments about @p reference; in a direction of period
      /// `box.period[k]` > 0 the coordinate is wrapped into
      /// [-period / 2, period / 2) about it, and the circular moments
      /// int c cos, int c sin of that direction are added.
      VesicleGeometry(const unsigned int phi,
                      const double       eps,
                      const PeriodicBox &box,
                      const Point<dim>  &reference,
                      const bool         indicator_volume)
        : phi(phi)
        , eps(eps)
        , indicator_volume(indicator_volume)
        , box(box)
        , reference(reference)
      {}
      unsigned int
      n_values() const override
      {
        return n_sums;
      }
      /// The index of the circular moments (cos; sin is the next) of
      /// direction k.
      static unsigned int
      circular(const unsigned int k)
      {
        return k < 2 ? 8 + 2 * k : 13;
      }
      void
      declare(TermDeclaration<dim> &d) override
      {
        value = d.value(phi, Derivative<dim>::value);
        for (unsigned int k = 0; k < dim; ++k)
          gradient[k] = d.value(phi, Derivative<dim>::gradient(k));
        d.needs_points();
      }
      void
      integrate(const QuadratureInputs<dim> &in,
                const double                *JxW,
                double                      *sums) const override
      {
        for (unsigned int q = 0; q < in.size(); ++q)
          {
            const double p  = in[value][q];
            double       g2 = 0;
            for (unsigned int k = 0; k < dim; ++k)
              g2 += in[gradient[k]][q] * in[gradient[k]][q];
            const double c = 0.5 * (1 + p), w = JxW[q];
            double       r[dim];
            for (unsigned int k = 0; k < dim; ++k)
              {
                const double x = in.point(q)[k];
                r[k]           = x - reference[k];
                if (box.period[k] > 0)
                  {
                    r[k]
                      -= box.period[k] * std::floor(r[k] / box.period[k] + 0.5);
                    const double angle
                      = 2 * numbers::PI * (x - box.lower[k]) / box.period[k];
                    sums[circular(k)] += c * std::cos(angle) * w;
                    sums[circular(k) + 1] += c * std::sin(angle) * w;
                  }
              }
            sums[0]
              += (0.5 * eps * g2 + (p * p - 1) * (p * p - 1) / (4 * eps)) * w;
            sums[1]
              += (indicator_volume ? membrane::smoothed_indicator(p) : p) * w;
            sums[2] += c * w;
            sums[3] += c * r[0] * w;
            sums[4] += c * r[1] * w;
            sums[5] += c * r[0] * r[0] * w;
            sums[6] += c * r[0] * r[1] * w;
            sums[7] += c * r[1] * r[1] * w;
            if constexpr (dim == 3)
              sums[12] += c * r[2] * w;
          }
      }

    private:
      const unsigned int           phi;
      const double                 eps;
      const bool                   indicator_volume;
      const PeriodicBox            box;
      const Point<dim>             reference;
      InputHandle                  value;
      std::array<InputHandle, dim> gradient;
    };


    /// b(f; u . grad phi) of (H24)-(H25) summed over the vesicles, written
    /// out with Delta(u . grad phi) expanded (spec 4.13), independently of
    /// the term's momentum rows.
    template <int dim>
    class BendingAdvectionPower : public Integrand<dim>
    {
    public:
      BendingAdvectionPower(const std::vector<unsigned int> &phases,
                            const MembraneCoefficients      &coefficients)
        : phases(phases)
        , coefficients(coefficients)
      {}
      unsigned int
      n_values() const override
      {
        return 1;
      }
      void
      declare(TermDeclaration<dim> &d) override
      {
        using D = Derivative<dim>;
        for (unsigned int a = 0; a < dim; ++a)
          {
            u[a]   = d.value(a, D::value);
            lap[a] = d.value(a, D::laplacian);
            for (unsigned int k = 0; k < dim; ++k)
              grad_u[a][k] = d.value(a, D::gradient(k));
          }
        fields.clear();
        for (const unsigned int phi : phases)
          {
            Phase f;
            f.value     = d.value(phi, D::value);
            f.laplacian = d.value(phi, D::laplacian);
            for (unsigned int k = 0; k < dim; ++k)
              {
                f.gradient[k] = d.value(phi, D::gradient(k));
                f.gradient_of_laplacian[k]
                  = d.value(phi, D::gradient_of_laplacian(k));
                for (unsigned int l = 0; l < dim; ++l)
                  f.hessian[k][l] = d.value(phi, D::hessian(k, l));
              }
            fields.push_back(f);
          }
      }
      void
      integrate(const QuadratureInputs<dim> &in,
                const double                *JxW,
                double                      *sums) const override
      {
        const double eps = coefficients.epsilon;
        const double c   = coefficients.bending_factor();
        for (const Phase &ph : fields)
          for (unsigned int q = 0; q < in.size(); ++q)
            {
              const double p = in[ph.value][q];
              const double f
                = membrane::chemical_potential(p, in[ph.laplacian][q], eps);
              double v = 0, lap_v = 0;
              for (unsigned int a = 0; a < dim; ++a)
                {
                  const double g = in[ph.gradient[a]][q];
                  v += in[u[a]][q] * g;
                  lap_v += in[lap[a]][q] * g
                           + in[u[a]][q] * in[ph.gradient_of_laplacian[a]][q];
                  for (unsigned int k = 0; k < dim; ++k)
                    lap_v += 2 * in[grad_u[a][k]][q] * in[ph.hessian[a][k]][q];
                }
              sums[0] += c * (f * lap_v - (3 * p * p - 1) / (eps * eps) * f * v)
                         * JxW[q];
            }
      }

    private:
      struct Phase
      {
        InputHandle                                   value, laplacian;
        std::array<InputHandle, dim>                  gradient;
        std::array<InputHandle, dim>                  gradient_of_laplacian;
        std::array<std::array<InputHandle, dim>, dim> hessian;
      };
      const std::vector<unsigned int>               phases;
      const MembraneCoefficients                    coefficients;
      std::array<InputHandle, dim>                  u, lap;
      std::array<std::array<InputHandle, dim>, dim> grad_u;
      std::vector<Phase>                            fields;
    };


    /// The initial state as one function of all components.
    template <int dim>
    class InitialFields : public Function<dim>
    {
    public:
      InitialFields(
        const unsigned int   n_components,
        const Function<dim> &velocity,
        const std::vector<std::function<double(const Point<dim> &)>> &phases)
        : Function<dim>(n_components)
        , velocity(velocity)
        , phases(phases)
      {}
      double
      value(const Point<dim> &x, const unsigned int c) const override
      {
        if (c < dim)
          return velocity.value(x, c);
        if (c > dim && c <= dim + phases.size())
          return phases[c - dim - 1](x);
        return 0;
      }

    private:
      const Function<dim>                                          &velocity;
      const std::vector<std::function<double(const Point<dim> &)>> &phases;
    };
  } // namespace


  template <int dim>
  VesicleHydrodynamics<dim>::VesicleHydrodynamics(
    const MPI_Comm                             comm,
    const SplineSpace<dim>                    &space,
    const MembraneCoefficients                &membrane,
    const FlowCoefficients<dim>               &flow,
    const std::vector<VelocityCondition<dim>> &conditions,
    const IncompressibleFlowParameters        &parameters,
    const unsigned int                         n_vesicles,
    TimerOutput                               &timer,
    const PhaseFieldBlockParameters           &phase_field_blocks)
    : membrane(membrane)
    , flow_coefficients(flow)
    , timer(timer)
    , phase_field_blocks(phase_field_blocks)
    , n(n_vesicles)
    , area_0(n_vesicles)
    , volume_0(n_vesicles)
    , lambda_g(n_vesicles)
    , lambda_v(n_vesicles)
    , lambda_g_rate(n_vesicles)
    , lambda_v_rate(n_vesicles)
    , lambda_g_previous_rate(n_vesicles)
    , lambda_v_previous_rate(n_vesicles)
    , rho_inf(parameters.time_integration.rho_inf)
    , bulk_stability(membrane)
  {
    for (unsigned int k = 0; k < dim; ++k)
      if (space.knot_vector(k).is_periodic())
        {
          const auto &breaks     = space.knot_vector(k).breakpoints();
          periodic_box.lower[k]  = breaks.front();
          periodic_box.period[k] = breaks.back() - breaks.front();
        }
    std::array<bool, dim> periodic;
    for (unsigned int k = 0; k < dim; ++k)
      periodic[k] = space.knot_vector(k).is_periodic();
    std::vector<unsigned int> phases;
    for (unsigned int i = 0; i < n; ++i)
      {
        phases.push_back(phase(i));
        advection.push_back(std::make_unique<PhaseFieldAdvection<dim>>(
          PhaseFieldAdvectionFormula<dim>(velocity, phase(i))));
        inflow.push_back(std::make_unique<PhaseFieldInflow<dim>>(velocity,
                                                                 phase(i),
                                                                 periodic));
        bending.push_back(std::make_unique<HydrodynamicBending<dim>>(
          HydrodynamicBendingFormula<dim>(velocity, phase(i), membrane)));
        constraint.push_back(std::make_unique<GlobalConstraintForcing<dim>>(
          GlobalConstraintForcingFormula<dim>(velocity, phase(i), membrane)));
        inextensibility.push_back(std::make_unique<LocalInextensibility<dim>>(
          LocalInextensibilityFormula<dim>(
            velocity, phase(i), tension(i), membrane)));
        tension_schur.push_back(std::make_unique<TensionLumpedSchur<dim>>(
          velocity, phase(i), tension(i), flow_coefficients, membrane));
        for (unsigned int j = 0; j < i && membrane.interaction; ++j)
          {
            pairs.emplace_back(j, i);
            interaction.push_back(std::make_unique<VesicleInteraction<dim>>(
              VesicleInteractionFormula<dim>(
                velocity, phase(j), phase(i), membrane)));
          }
      }
    if (membrane.viscosity_ratio != 1)
      viscosity = std::make_unique<ViscosityContrast<dim>>(
        ViscosityContrastFormula<dim>(velocity, phases, membrane));
    flow_model = std::make_unique<IncompressibleFlow<dim>>(
      comm, space, flow_coefficients, conditions, parameters, timer, this);
    const auto        &dofs = flow_model->dofs();
    const unsigned int nc   = dofs.n_components();
    for (const auto g : dofs.locally_owned_dofs())
      phase_entries.push_back(g % nc > dim && g % nc <= dim + n);
    const bool zero_normal_derivative = membrane.zero_normal_derivative;
    phase_gram                        = std::make_unique<GramSolver<dim>>(
      flow_model->mesh(),
      dofs.get_space(),
      flow_model->get_assembler().get_quadrature(),
      [zero_normal_derivative](const SplineDofHandler<dim> &d,
                               AffineConstraints<double>   &c) {
        if (zero_normal_derivative)
          add_zero_normal_derivative_constraints<dim>(d, {true}, c);
      });
  }


  template <int dim>
  VesicleHydrodynamics<dim>::~VesicleHydrodynamics() = default;


  template <int dim>
  void
  VesicleHydrodynamics<dim>::add_fields(FieldLayout<dim> &layout) const
  {
    for (unsigned int i = 0; i < n; ++i)
      layout.add_field("phi_" + std::to_string(i + 1),
                       1,
                       0,
                       FieldKind::differential);
    for (unsigned int i = 0; i < n; ++i)
      layout.add_field("lambda_" + std::to_string(i + 1),
                       1,
                       0,
                       FieldKind::algebraic);
  }


  template <int dim>
  std::vector<Term<dim> *>
  VesicleHydrodynamics<dim>::terms()
  {
    std::vector<Term<dim> *> list;
    for (unsigned int i = 0; i < n; ++i)
      {
        list.push_back(advection[i].get());
        list.push_back(inflow[i].get());
        list.push_back(bending[i].get());
        list.push_back(constraint[i].get());
        list.push_back(inextensibility[i].get());
      }
    for (auto &term : interaction)
      list.push_back(term.get());
    if (viscosity)
      list.push_back(viscosity.get());
    return list;
  }


  template <int dim>
  std::unique_ptr<LumpedOperatorPreconditioner>
  VesicleHydrodynamics<dim>::block_preconditioner(
    std::unique_ptr<FlowBlockPreconditioner> flow,
    const SplineDofHandler<dim>             &dofs,
    const AffineConstraints<double>         &increments,
    const FlowBlockPreconditionerParameters &parameters)
  {
    const unsigned int                                 nc = dofs.n_components();
    std::vector<std::unique_ptr<MatrixPreconditioner>> phase_blocks(n);
    if (phase_field_blocks.preconditioner == "spline-multigrid")
      for (unsigned int i = 0; i < n; ++i)
        {
          // Row of basis b in the phase-field block: new_index(b). The
          // rows tied by d phi_i / dn = 0 hold only their diagonal in the
          // assembled block (their couplings went to the coefficient they
          // are tied to), so the levels keep them as decoupled unknowns.
          IndexSet owned(dofs.get_space().n_basis());
          for (const auto g : dofs.locally_owned_dofs())
            if (g % nc == phase(i))
              owned.add_index(g / nc);
          owned.compress();
          SplineMultigridParameters mg;
          mg.smoother = phase_field_blocks.smoother;
          mg.sweeps   = phase_field_blocks.sweeps;
          if (phase_field_blocks.coarse_size > 0)
            mg.coarse_size = phase_field_blocks.coarse_size;
          phase_blocks[i] = std::make_unique<SplineMultigrid<dim>>(
            dofs,
            1,
            [&dofs, nc](const unsigned int b, const unsigned int) {
              return dofs.dof_index(b, 0) / nc;
            },
            owned,
            [](const types::global_dof_index) { return false; },
            mg);
        }
    return std::make_unique<VesicleBlockPreconditioner>(
      dim,
      n,
      dofs.locally_owned_dofs(),
      dofs.get_mesh().get_communicator(),
      std::move(flow),
      std::move(phase_blocks),
      [&increments](const types::global_dof_index g) {
        return increments.is_constrained(g);
      },
      parameters,
      phase_field_blocks.tolerance);
  }


  template <int dim>
  double
  VesicleHydrodynamics<dim>::local_error(const double atol,
                                         const double rtol) const
  {
    return flow_model->get_stepper().local_error(atol, rtol, &phase_entries);
  }


  template <int dim>
  std::vector<Term<dim> *>
  VesicleHydrodynamics<dim>::lumped_operator_terms()
  {
    std::vector<Term<dim> *> list;
    for (auto &t : tension_schur)
      list.push_back(t.get());
    return list;
  }


  template <int dim>
  void
  VesicleHydrodynamics<dim>::prepare_lumped_operators(
    const AssemblyState &state)
  {
    for (unsigned int i = 0; i < n; ++i)
      tension_schur[i]->set_factor(state.value_factor[tension(i)]);
  }


  template <int dim>
  void
  VesicleHydrodynamics<dim>::boundary_values(const SplineDofHandler<dim> &dofs,
                                             const double,
                                             AffineConstraints<double> &c) const
  {
    // lambda_i = 0 on the whole (non-periodic) boundary, spec 4.10.
    std::vector<bool> mask(dofs.n_components(), false);
    for (unsigned int i = 0; i < n; ++i)
      mask[tension(i)] = true;
    const BoundarySelection<dim> everywhere("all", "lambda boundary");
    add_strong_dirichlet_constraints<dim>(dofs,
                                          nullptr,
                                          everywhere,
                                          Functions::ZeroFunction<dim>(
                                            dofs.n_components()),
                                          mask,
                                          c);
    // d phi_i / dn = 0 on the same boundary (spec 4.10, the source's pair
    // with the natural d f_i / dn = 0 that (H24) leaves).
    if (membrane.zero_normal_derivative)
      {
        std::vector<bool> phases(dofs.n_components(), false);
        for (unsigned int i = 0; i < n; ++i)
          phases[phase(i)] = true;
        add_zero_normal_derivative_constraints<dim>(dofs, phases, c);
      }
  }


  template <int dim>
  void
  VesicleHydrodynamics<dim>::set_initial_state(
    const Function<dim>                                          &velocity,
    const std::vector<std::function<double(const Point<dim> &)>> &phases)
  {
    AssertThrow(phases.size() == n, ExcDimensionMismatch(phases.size(), n));
    const InitialFields<dim> initial(flow_model->dofs().n_components(),
                                     velocity,
                                     phases);
    flow_model->set_initial_state(initial, 0.);
    const auto measures = measure();
    for (unsigned int i = 0; i < n; ++i)
      {
        area_0[i]   = measures[i].area;
        volume_0[i] = measures[i].volume;
      }
    update_multipliers(0);
  }


  template <int dim>
  std::vector<VesicleMeasures>
  VesicleHydrodynamics<dim>::measure() const
  {
    // Periodic directions: the centroid is the circular mean of the
    // indicator (a first pass), and the moments are taken about it with the
    // coordinate wrapped into one period, so that a vesicle's tails seen
    // through the seam (or a vesicle crossing it) do not pull it across the
    // box.
    bool periodic = false;
    for (unsigned int k = 0; k < dim; ++k)
      periodic = periodic || periodic_box.period[k] > 0;
    constexpr unsigned int  n_sums = VesicleGeometry<dim>::n_sums;
    std::vector<Point<dim>> references(n);
    if (periodic)
      {
        const auto sums = integrate_geometry(references, false);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int k = 0; k < dim; ++k)
            if (periodic_box.period[k] > 0)
              {
                const unsigned int j = VesicleGeometry<dim>::circular(k);
                double             angle
                  = std::atan2(sums[n_sums * i + j + 1], sums[n_sums * i + j]);
                if (angle < 0)
                  angle += 2 * numbers::PI;
                references[i][k]
                  = periodic_box.lower[k]
                    + periodic_box.period[k] / (2 * numbers::PI) * angle;
              }
      }
    const auto                   sums = integrate_geometry(references, true);
    std::vector<VesicleMeasures> result(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const double *s = &sums[n_sums * i];
        const double *b = &sums[n_sums * n + i];
        auto         &m = result[i];
        m.area          = s[0];
        m.volume        = s[1];
        const double dx = s[3] / s[2], dy = s[4] / s[2];
        m.centroid[0] = references[i][0] + dx;
        m.centroid[1] = references[i][1] + dy;
        if constexpr (dim == 3)
          m.centroid[2] = references[i][2] + s[12] / s[2];
        const double Ixx = s[5] / s[2] - dx * dx;
        const double Ixy = s[6] / s[2] - dx * dy;
        const double Iyy = s[7] / s[2] - dy * dy;
        // Spec 4.12: angle of the major principal axis to the x axis.
        m.angle = 0.5 * std::atan2(2 * Ixy, Ixx - Iyy);
        // atan2 returns pi and -pi for the same axis; an axis is a line,
        // so report it in (-pi/2, pi/2].
        if (m.angle <= -0.5 * numbers::PI + 1e-12)
          m.angle += numbers::PI;
        m.bending_energy = b[0];
      }
    return result;
  }


  template <int dim>
  std::vector<double>
  VesicleHydrodynamics<dim>::integrate_geometry(
    const std::vector<Point<dim>>       &references,
    const bool                           with_bending_energy,
    const TrilinosWrappers::MPI::Vector *fields) const
  {
    std::vector<std::unique_ptr<Integrand<dim>>> owned;
    for (unsigned int i = 0; i < n; ++i)
      owned.push_back(
        std::make_unique<VesicleGeometry<dim>>(phase(i),
                                               membrane.epsilon,
                                               periodic_box,
                                               references[i],
                                               indicator_volume()));
    for (unsigned int i = 0; with_bending_energy && i < n; ++i)
      owned.push_back(
        std::make_unique<HydrodynamicBendingEnergy<dim>>(phase(i), membrane));
    std::vector<Integrand<dim> *> list;
    for (auto &o : owned)
      list.push_back(o.get());
    AssemblyState state;
    state.value = fields ? fields : &flow_model->solution();
    return flow_model->get_assembler().integrate(list, state);
  }


  template <int dim>
  double
  VesicleHydrodynamics<dim>::interaction_energy() const
  {
    if (pairs.empty())
      return 0;
    std::vector<std::unique_ptr<Integrand<dim>>> owned;
    std::vector<Integrand<dim> *>                list;
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        owned.push_back(std::make_unique<InteractionEnergy<dim>>(
          phase(pairs[k].first),
          phase(pairs[k].second),
          interaction[k]->get_formula()));
        list.push_back(owned.back().get());
      }
    AssemblyState state;
    state.value     = &flow_model->solution();
    const auto sums = flow_model->get_assembler().integrate(list, state);
    double     sum  = 0;
    for (const double s : sums)
      sum += s;
    return sum;
  }


  template <int dim>
  std::pair<double, double>
  VesicleHydrodynamics<dim>::bending_powers() const
  {
    std::vector<unsigned int> phases;
    for (unsigned int i = 0; i < n; ++i)
      phases.push_back(phase(i));
    BendingAdvectionPower<dim> power(phases, membrane);
    AssemblyState              state;
    state.value            = &flow_model->solution();
    const auto  &assembler = flow_model->get_assembler();
    const double advection = assembler.integrate({&power}, state)[0];

    // The momentum rows of the bending terms, contracted with the velocity
    // coefficients: -(forcing, u).
    SystemAssembler<dim> rows(flow_model->dofs(), assembler.get_quadrature());
    for (const auto &term : bending)
      rows.add_term(*term);
    const auto                     &dofs = flow_model->dofs();
    TrilinosWrappers::MPI::Vector   residual(dofs.locally_owned_dofs(),
                                           dofs.get_mesh().get_communicator());
    const AffineConstraints<double> none;
    rows.assemble(state, none, &residual, nullptr);
    const unsigned int nc      = dofs.n_components();
    double             forcing = 0;
    for (const auto g : dofs.locally_owned_dofs())
      if (g % nc < dim)
        forcing -= residual[g] * flow_model->owned_solution()[g];
    forcing = Utilities::MPI::sum(forcing, dofs.get_mesh().get_communicator());
    return {advection, forcing};
  }


  template <int dim>
  std::array<TrilinosWrappers::MPI::Vector, 3>
  VesicleHydrodynamics<dim>::phase_row_residuals() const
  {
    const auto &dofs  = flow_model->dofs();
    const auto  comm  = dofs.get_mesh().get_communicator();
    const auto &owned = dofs.locally_owned_dofs();
    const TrilinosWrappers::MPI::Vector zero_rate(owned,
                                                  dofs.locally_relevant_dofs(),
                                                  comm);
    AssemblyState                       state;
    state.value            = &flow_model->solution();
    state.rate             = &zero_rate;
    state.time             = time();
    const auto &increments = flow_model->increment_constraints();
    std::array<TrilinosWrappers::MPI::Vector, 3> r;
    for (auto &v : r)
      v.reinit(owned, comm);
    {
      // Every term with a phase-field row but the multipliers'.
      SystemAssembler<dim> rows(dofs,
                                flow_model->get_assembler().get_quadrature());
      for (unsigned int i = 0; i < n; ++i)
        {
          rows.add_term(*advection[i]);
          rows.add_term(*inflow[i]);
          rows.add_term(*bending[i]);
        }
      for (auto &term : interaction)
        rows.add_term(*term);
      rows.assemble(state, increments, &r[0], nullptr);
    }
    SystemAssembler<dim> rows(dofs,
                              flow_model->get_assembler().get_quadrature());
    for (auto &term : constraint)
      rows.add_term(*term);
    // The terms are the step's: their multipliers are put back, so that
    // computing the rate laws leaves no state behind (a restart computes
    // them where the uninterrupted run may not).
    std::vector<std::array<double, 2>> multipliers;
    for (const auto &term : constraint)
      multipliers.push_back({{term->get_formula().area_multiplier(),
                              term->get_formula().volume_multiplier()}});
    for (unsigned int k = 1; k < 3; ++k)
      {
        for (auto &term : constraint)
          term->get_formula().set_multipliers(k == 1, k == 2);
        rows.assemble(state, increments, &r[k], nullptr);
      }
    for (unsigned int i = 0; i < constraint.size(); ++i)
      constraint[i]->get_formula().set_multipliers(multipliers[i][0],
                                                   multipliers[i][1]);
    return r;
  }


  template <int dim>
  std::vector<std::array<double, 6>>
  VesicleHydrodynamics<dim>::rate_laws(const double dt) const
  {
    // (H13) from the discrete equations themselves. On the rows of phi_i,
    // tested with the basis psi_j of the space with its strong conditions,
    //   M d_t phi_i + R_0 + lambda_g F_g + lambda_v F_v = 0,
    // with R_0 the residual of the other terms at zero rate and F_g, F_v
    // that of the multipliers' term per unit multiplier (F_g(v) = eta_phi
    // A'(phi)[v]). Then dV_i/dt = (d_t phi_i, 1) = -(R_0 + ...)(1), as
    // sum_j psi_j = 1, and dA_i/dt = A'[d_t phi_i] = -(R_0 + ...)(Y) /
    // eta_phi with Y = M^-1 F_g, the projection of -eta_phi f_i onto the
    // space. Written with the pointwise f_i instead of Y (as (H13) reads)
    // the area law is off by the projection error of f_i, a constant drift
    // that the relaxation turns into an area error of order dt
    // (doc/hydrodynamics.md, "Global multipliers in time").
    const auto                         residuals = phase_row_residuals();
    std::vector<std::array<double, 6>> laws(n);
    std::vector<std::unique_ptr<Integrand<dim>>> owned;
    std::vector<Integrand<dim> *>                list;
    for (unsigned int i = 0; i < n; ++i)
      {
        owned.push_back(
          std::make_unique<VesicleGeometry<dim>>(phase(i),
                                                 membrane.epsilon,
                                                 periodic_box,
                                                 Point<dim>(),
                                                 indicator_volume()));
        list.push_back(owned.back().get());
      }
    AssemblyState state;
    state.value         = &flow_model->solution();
    const auto geometry = flow_model->get_assembler().integrate(list, state);

    const auto        &dofs = flow_model->dofs();
    const unsigned int nc   = dofs.n_components();
    const double       eta  = membrane.mobility;
    for (unsigned int i = 0; i < n; ++i)
      {
        // The rows of phi_i as vectors of the one-component space.
        std::array<TrilinosWrappers::MPI::Vector, 3> x;
        for (auto &v : x)
          v.reinit(phase_gram->locally_owned_dofs(),
                   dofs.get_mesh().get_communicator());
        for (const auto g : dofs.locally_owned_dofs())
          if (g % nc == phase(i))
            for (unsigned int k = 0; k < 3; ++k)
              x[k](g / nc) = residuals[k](g);
        for (auto &v : x)
          v.compress(VectorOperation::insert);
        TrilinosWrappers::MPI::Vector y;
        phase_gram->solve(x[1], y);
        // X(Y) for X = R_0, F_g, F_v: the row of eta_phi dA/dt (the dot
        // products are global already).
        std::array<double, 6> sums;
        for (unsigned int k = 0; k < 3; ++k)
          sums[3 + k] = x[k] * y;
        if (indicator_volume())
          {
            // V_i = int chi(phi_i) with chi' = c delta_eps: dV/dt = c (beta,
            // d_t phi_i) = -c F_v[d_t phi_i] / eta_phi = (c / eta_phi) (R_0 +
            // lambda_g F_g + lambda_v F_v)(Z), Z = M^-1 F_v, so that the
            // matrix below is [F_v M^-1 F_v, F_g M^-1 F_v; F_v M^-1 F_g, F_g
            // M^-1 F_g] up to the factor -c / eta_phi of its first row: a
            // Gram matrix, whose determinant is >= 0 by Cauchy-Schwarz and 0
            // only where F_v and F_g are parallel.
            TrilinosWrappers::MPI::Vector z;
            phase_gram->solve(x[2], z);
            const double c
              = membrane::indicator_slope_per_delta(membrane.epsilon) / eta;
            for (unsigned int k = 0; k < 3; ++k)
              sums[k] = -c * (x[k] * z);
          }
        else
          {
            // X(1): the row of dV/dt = -(R_0 + lambda_g F_g + lambda_v
            // F_v)(1) for V_i = int phi_i.
            for (unsigned int k = 0; k < 3; ++k)
              {
                double total = 0;
                for (const auto j : x[k].locally_owned_elements())
                  total += x[k](j);
                sums[k] = total;
              }
            Utilities::MPI::sum(ArrayView<const double>(sums.data(), 3),
                                dofs.get_mesh().get_communicator(),
                                ArrayView<double>(sums.data(), 3));
          }
        const double area   = geometry[VesicleGeometry<dim>::n_sums * i];
        const double volume = geometry[VesicleGeometry<dim>::n_sums * i + 1];
        // [F_v(1) F_g(1); F_v(Y) F_g(Y)] (lambda_v, lambda_g) = b: the laws
        // dV/dt = eta_phi (V(0) - V) / (2 dt), dA/dt = the same with A.
        double b_v = -sums[0], b_g = -sums[3];
        if (dt > 0)
          {
            b_v -= eta * (volume_0[i] - volume) / (2 * dt);
            b_g -= eta * eta * (area_0[i] - area) / (2 * dt);
          }
        laws[i] = {{sums[2], sums[1], sums[5], sums[4], b_v, b_g}};
      }
    return laws;
  }


  template <int dim>
  void
  VesicleHydrodynamics<dim>::update_multipliers(const double dt)
  {
    const auto laws = rate_laws(dt);
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto [a_vv, a_vg, a_gv, a_gg, b_v, b_g] = laws[i];
        // With beta = 1 (Volume multiplier = domain) and the pointwise f
        // this was the Gram determinant |Omega| int f^2 - (int f)^2 of spec
        // 4.6; with 'indicator' it is a Gram determinant too (rate_laws).
        // With the membrane weight beta = delta_eps and V = int phi it is
        // not: for f = eps kappa phi' along the membrane and beta ~ phi'^2
        // across it, det ~ m_2^2 L int kappa^2 - m_1 m_3 (int kappa)^2 with
        // m_k = int phi'^k, and m_1 m_3 / m_2^2 = 6/5 for the tanh profile,
        // so det changes sign near a circle (ellipses: chi about 0.93 in
        // the sharp limit; doc/hydrodynamics.md, "A Gram form of (H13)").
        // A negative det still holds both rates of (H13); near zero the
        // multipliers diverge.
        const double det       = a_vv * a_gg - a_vg * a_gv;
        const double scale     = a_vv * a_gg;
        using VolumeMultiplier = MembraneCoefficients::VolumeMultiplier;
        AssertThrow(
          std::abs(det) > 1e-2 * std::abs(scale),
          ExcMessage(
            "(H13) is singular for vesicle " + std::to_string(i + 1)
            + ": its determinant is " + std::to_string(det / scale)
            + " of the product of its diagonal"
            + (membrane.volume_multiplier == VolumeMultiplier::membrane ?
                 " (with 'Volume multiplier = membrane' it changes sign "
                 "between an ellipse and the circle, near a reduced area of "
                 "0.94 (0.93 to 0.99 by eps / R_0 and the profile); use "
                 "'Volume multiplier = indicator', whose (H13) is a Gram "
                 "system)" :
                 " (the area and volume variations are nearly parallel: no "
                 "interface, or a vesicle thinner than the interface)")));
        const double v            = (a_gg * b_v - a_vg * b_g) / det;
        const double g            = (a_vv * b_g - a_gv * b_v) / det;
        lambda_v_previous_rate[i] = lambda_v_rate[i];
        lambda_g_previous_rate[i] = lambda_g_rate[i];
        lambda_v_rate[i]          = dt > 0 ? (v - lambda_v[i]) / dt : 0.;
        lambda_g_rate[i]          = dt > 0 ? (g - lambda_g[i]) / dt : 0.;
        lambda_v[i]               = v;
        lambda_g[i]               = g;
      }
    for (unsigned int i = 0; i < n; ++i)
      constraint[i]->get_formula().set_multipliers(lambda_g[i], lambda_v[i]);
  }


  template <int dim>
  double
  VesicleHydrodynamics<dim>::extrapolation_rate(const double rate,
                                                const double previous_rate)
  {
    // A multiplier whose rate changed sign over the last two steps is not
    // extrapolated (a limiter, as minmod is for slopes): linear
    // extrapolation of an alternating sequence amplifies it, and at the
    // large steps of a slow relaxation the extrapolated multipliers
    // alternated in every step, the energy rising in every other one
    // (doc/hydrodynamics.md, "Extrapolation with a limiter"). A developing
    // flow, whose multipliers change monotonically, keeps the O(dt^2) lag.
    return rate * previous_rate < 0 ? 0. : rate;
  }


  template <int dim>
  StepReport
  VesicleHydrodynamics<dim>::solve_step(const double dt)
  {
    last_dt = dt;
    // (H13) gives the multipliers that hold V_i, A_i at the state of t_n;
    // a step with them lags them by dt, which leaves an area error of
    // order dt per step (relaxed only at eta_phi / 2 per step).
    // Extrapolated to t_{n+1} by their rate over the last step, the lag is
    // of order dt^2. Implicit multipliers start from the same extrapolated
    // values: with the limiter (extrapolation_rate) they need 16 % fewer
    // solves than from the last step's values on the quick doublet; without
    // it the alternation of the first steps of a shear start was amplified
    // (doc/hydrodynamics.md, "Implicit global multipliers").
    const double ahead
      = membrane.extrapolated_multipliers || membrane.implicit_multipliers ?
          dt :
          0.;
    step_lambda_g.resize(n);
    step_lambda_v.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        step_lambda_g[i] = lambda_g[i]
                           + ahead
                               * extrapolation_rate(lambda_g_rate[i],
                                                    lambda_g_previous_rate[i]);
        step_lambda_v[i] = lambda_v[i]
                           + ahead
                               * extrapolation_rate(lambda_v_rate[i],
                                                    lambda_v_previous_rate[i]);
        constraint[i]->get_formula().set_multipliers(step_lambda_g[i],
                                                     step_lambda_v[i]);
      }
    if (membrane.implicit_multipliers)
      return implicit_step(dt);
    return flow_model->solve_step(dt);
  }


  template <int dim>
  std::vector<SecantIteration2>
  VesicleHydrodynamics<dim>::multiplier_secants(const double dt) const
  {
    const double eta = membrane.mobility;
    // The rate laws at the state: needed only before a first step has
    // given a secant estimate.
    const auto                    laws = step_response.size() == n ?
                                           std::vector<std::array<double, 6>>() :
                                           rate_laws(0);
    std::vector<SecantIteration2> secant;
    secant.reserve(n);
    // The last step's secant estimate, scaled to this step (the response
    // is about proportional to dt while the rate term dominates the step
    // matrix), is closer than the rate laws' once a step has been taken.
    for (unsigned int i = 0; i < n; ++i)
      {
        std::array<double, 4> J;
        if (step_response.size() == n)
          for (unsigned int k = 0; k < 4; ++k)
            J[k] = dt * step_response[i][k];
        else
          {
            const auto &a = laws[i];
            J = {{-dt * a[0], -dt * a[1], -dt * a[2] / eta, -dt * a[3] / eta}};
          }
        secant.emplace_back(
          std::array<double, 2>{{step_lambda_v[i], step_lambda_g[i]}}, J);
      }
    return secant;
  }


  template <int dim>
  std::vector<std::array<double, 2>>
  VesicleHydrodynamics<dim>::constraint_errors(
    const TrilinosWrappers::MPI::Vector *fields) const
  {
    const auto geometry
      = integrate_geometry(std::vector<Point<dim>>(n), false, fields);
    std::vector<std::array<double, 2>> errors(n);
    for (unsigned int i = 0; i < n; ++i)
      errors[i]
        = {{geometry[VesicleGeometry<dim>::n_sums * i + 1] - volume_0[i],
            geometry[VesicleGeometry<dim>::n_sums * i] - area_0[i]}};
    return errors;
  }


  template <int dim>
  StepReport
  VesicleHydrodynamics<dim>::implicit_step(const double dt)
  {
    // (H7) at the end of the step instead of the rate laws of (H13): G_i =
    // (V_i, A_i)(phi_{n+1}) - (V_i(0), A_i(0)) = 0 (relative to |V_i(0)|,
    // A_i(0): V_i = int phi_i is negative in a box larger than twice the
    // vesicle) for (lambda_v, lambda_g) of the step, by a secant iteration
    // started from the rate laws' response dt d(dV/dt, dA/dt)/d(lambda_v,
    // lambda_g) (the rows of (H13): dV/dt = -(... + lambda_v F_v + lambda_g
    // F_g)(1), eta_phi dA/dt the same at Y).
    std::vector<SecantIteration2> secant = multiplier_secants(dt);
    // The constraint errors at the start of the step (at most the
    // tolerance): the part J^-1 e_n of the step's multipliers that removes
    // them is not carried into the next step (accept_step).
    const auto  start_errors = constraint_errors(nullptr);
    const auto &dofs         = flow_model->dofs();
    StepReport  report;
    for (unsigned int iteration = 1;; ++iteration)
      {
        const StepReport r = flow_model->solve_step(dt);
        report.newton_iterations += r.newton_iterations;
        report.krylov_iterations += r.krylov_iterations;
        TrilinosWrappers::MPI::Vector trial(dofs.locally_owned_dofs(),
                                            dofs.locally_relevant_dofs(),
                                            dofs.get_mesh().get_communicator());
        trial                = flow_model->get_stepper().next_solution();
        const auto residuals = constraint_errors(&trial);
        double     worst     = 0;
        for (unsigned int i = 0; i < n; ++i)
          worst = std::max({worst,
                            std::abs(residuals[i][0] / volume_0[i]),
                            std::abs(residuals[i][1] / area_0[i])});
        if (worst <= membrane.multiplier_tolerance)
          {
            solved_step_response.resize(n);
            solved_drift_free.resize(n);
            for (unsigned int i = 0; i < n; ++i)
              {
                const auto &J = secant[i].jacobian();
                for (unsigned int k = 0; k < 4; ++k)
                  solved_step_response[i][k] = J[k] / dt;
                // G(lambda) = e_n + c + J lambda = e_{n+1} at the step's
                // lambda; c + J lambda* = 0 defines the multipliers lambda*
                // that keep the constraint errors where they were: lambda*
                // = lambda - J^-1 (e_{n+1} - e_n). At small steps J^-1 e
                // grows like 1 / dt.
                // - Carrying the step's own lambda (with its J^-1 e_n)
                //   into the next step made the multipliers alternate with
                //   growing amplitude (HD2 at IN = 5: lambda_g 219, 1109,
                //   -55, 1101, -100, 3881, -1393, and the stability limit
                //   then cut dt to 3e-6).
                // - Taking e_{n+1} = 0 (lambda* = lambda + J^-1 e_n) for a
                //   step accepted within the tolerance doubled the error of
                //   every step accepted at its first solve: started from
                //   lambda*, the next step adds e_{n+1} again (steps of
                //   1e-5: |dA/A| 5.6e-7, 1.4e-6, 3.6e-6, 9.1e-6).
                // doc/hydrodynamics.md, "Implicit global multipliers".
                solved_drift_free[i] = secant[i].without_change(
                  {{residuals[i][0] - start_errors[i][0],
                    residuals[i][1] - start_errors[i][1]}});
              }
            report.counters = {double(iteration)};
            return report;
          }
        if (iteration >= membrane.max_multiplier_iterations)
          throw SolverFailure(
            "the implicit global multipliers did not hold V_i(0), A_i(0) "
            "to 'Multiplier tolerance' = "
            + std::to_string(membrane.multiplier_tolerance) + " in "
            + std::to_string(iteration)
            + " iterations ('Multiplier iterations'); relative error "
            + std::to_string(worst));
        for (unsigned int i = 0; i < n; ++i)
          {
            const auto &x    = secant[i].next(residuals[i]);
            step_lambda_v[i] = x[0];
            step_lambda_g[i] = x[1];
            constraint[i]->get_formula().set_multipliers(step_lambda_g[i],
                                                         step_lambda_v[i]);
          }
      }
  }


  template <int dim>
  std::vector<std::pair<std::string, std::string>>
  VesicleHydrodynamics<dim>::step_columns() const
  {
    if (!membrane.implicit_multipliers)
      return {};
    return {{"multiplier_iterations", "multiplier_its"}};
  }


  template <int dim>
  void
  VesicleHydrodynamics<dim>::accept_step()
  {
    flow_model->accept_step();
    TimerOutput::Scope scope(timer, "global multipliers");
    if (!membrane.implicit_multipliers)
      {
        update_multipliers(last_dt);
        return;
      }
    // The multipliers of the step just taken without its correction of
    // the start's constraint error (lambda*, implicit_step) and their rate
    // over it (the next step's first iterate), and the step's secant
    // estimate of their response (the next step's first Jacobian; the rate
    // laws are needed only before a first step).
    step_response = solved_step_response;
    for (unsigned int i = 0; i < n; ++i)
      {
        lambda_g_previous_rate[i] = lambda_g_rate[i];
        lambda_v_previous_rate[i] = lambda_v_rate[i];
        lambda_g_rate[i] = (solved_drift_free[i][1] - lambda_g[i]) / last_dt;
        lambda_v_rate[i] = (solved_drift_free[i][0] - lambda_v[i]) / last_dt;
        lambda_g[i]      = solved_drift_free[i][1];
        lambda_v[i]      = solved_drift_free[i][0];
      }
  }


  template <int dim>
  double
  VesicleHydrodynamics<dim>::largest_step() const
  {
    const GeneralizedAlpha method(rho_inf);
    // The last accepted step from the stepper (kept in checkpoints, so that
    // a restart caps the same step).
    const double ahead
      = membrane.extrapolated_multipliers || membrane.implicit_multipliers ?
          flow_model->get_stepper().previous_step() :
          0.;
    double largest = std::numeric_limits<double>::infinity();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double lambda
          = std::min(lambda_g[i],
                     lambda_g[i]
                       + ahead
                           * extrapolation_rate(lambda_g_rate[i],
                                                lambda_g_previous_rate[i]));
        // Half the singular step: the mode's diagonal alpha_m - alpha_f
        // gamma dt sigma keeps half of alpha_m.
        largest = std::min(
          largest,
          0.5 * method.singular_step(bulk_stability.growth_rate(lambda)));
      }
    return largest;
  }


  template <int dim>
  void
  VesicleHydrodynamics<dim>::save(Checkpoint        &c,
                                  const std::string &prefix) const
  {
    flow_model->save(c, prefix + ".flow");
    c.vectors[prefix + ".initial_areas"]   = area_0;
    c.vectors[prefix + ".initial_volumes"] = volume_0;
    // Which volume volume_0 measures: int phi (0) or int chi(phi) (1).
    c.scalars[prefix + ".indicator_volume"]      = indicator_volume() ? 1. : 0.;
    c.vectors[prefix + ".area_multipliers"]      = lambda_g;
    c.vectors[prefix + ".volume_multipliers"]    = lambda_v;
    c.vectors[prefix + ".area_multiplier_rates"] = lambda_g_rate;
    c.vectors[prefix + ".volume_multiplier_rates"] = lambda_v_rate;
    c.vectors[prefix + ".area_multiplier_previous_rates"]
      = lambda_g_previous_rate;
    c.vectors[prefix + ".volume_multiplier_previous_rates"]
      = lambda_v_previous_rate;
    // Implicit multipliers only (an empty vector is no HDF5 data set).
    if (!step_response.empty())
      {
        std::vector<double> response;
        for (const auto &J : step_response)
          response.insert(response.end(), J.begin(), J.end());
        c.vectors[prefix + ".multiplier_step_response"] = response;
      }
  }


  template <int dim>
  void
  VesicleHydrodynamics<dim>::drop_unsaved_state()
  {
    flow_model->drop_unsaved_state();
  }


  template <int dim>
  void
  VesicleHydrodynamics<dim>::load(const Checkpoint  &c,
                                  const std::string &prefix)
  {
    flow_model->load(c, prefix + ".flow");
    const auto get = [&](const std::string &name, std::vector<double> &v) {
      const auto &stored = c.vector(prefix + "." + name);
      check_input(stored.size() == n,
                  "Time stepping/Restart from",
                  c.source,
                  "a checkpoint of " + std::to_string(n)
                    + " vesicles (it holds " + std::to_string(stored.size())
                    + ")");
      v = stored;
    };
    get("initial_areas", area_0);
    get("initial_volumes", volume_0);
    // Checkpoints written before 'indicator' existed hold int phi.
    const bool stored_indicator
      = c.scalars.count(prefix + ".indicator_volume")
        && c.scalar(prefix + ".indicator_volume") == 1.;
    check_input(stored_indicator == indicator_volume(),
                "Time stepping/Restart from",
                c.source,
                std::string("a checkpoint whose initial volumes are those of "
                            "this run's 'Volume multiplier' (the checkpoint "
                            "holds V_i = ")
                  + (stored_indicator ? "int chi(phi_i), of 'indicator'" :
                                        "int phi_i, of 'membrane' or 'domain'")
                  + ")");
    get("area_multipliers", lambda_g);
    get("volume_multipliers", lambda_v);
    // Checkpoints written before the rates were kept: none (lagged once).
    lambda_g_rate.assign(n, 0.);
    lambda_v_rate.assign(n, 0.);
    if (c.vectors.count(prefix + ".area_multiplier_rates"))
      {
        get("area_multiplier_rates", lambda_g_rate);
        get("volume_multiplier_rates", lambda_v_rate);
      }
    // Before 2026-12-07: no previous rates, extrapolation as before.
    lambda_g_previous_rate.assign(n, 0.);
    lambda_v_previous_rate.assign(n, 0.);
    if (c.vectors.count(prefix + ".area_multiplier_previous_rates"))
      {
        get("area_multiplier_previous_rates", lambda_g_previous_rate);
        get("volume_multiplier_previous_rates", lambda_v_previous_rate);
      }
    for (unsigned int i = 0; i < n; ++i)
      constraint[i]->get_formula().set_multipliers(lambda_g[i], lambda_v[i]);
    step_response.clear();
    if (c.vectors.count(prefix + ".multiplier_step_response"))
      {
        const auto &stored = c.vector(prefix + ".multiplier_step_response");
        for (unsigned int i = 0; 4 * i + 3 < stored.size(); ++i)
          step_response.push_back({{stored[4 * i],
                                    stored[4 * i + 1],
                                    stored[4 * i + 2],
                                    stored[4 * i + 3]}});
      }
  }

  template class VesicleHydrodynamics<2>;
  template class VesicleHydrodynamics<3>;
} // namespace vesicle_iga
