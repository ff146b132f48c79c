// Study "willmore-flow": constrained Willmore/Helfrich flow of a vesicle
// (spec Part E with the electric terms off): the phase-field gradient flow
// (E12) in the primal H^2 weak form (E18) on C^1+ splines, clamped boundary
// (E15) through the two outer layers of coefficients, generalized-alpha in
// time (N2)-(N4), Newton with the tangent (E20), volume and area held by
// the modified augmented-Lagrangian method (E19)-(E22) or by penalty,
// adaptive steps (spec section 2.5). This file only orchestrates: the
// energy terms are in physics/, the Newton step in solvers/
// phase_field_newton, the ALM in solvers/modified_alm, the step control in
// time/, the output helpers in io/ and postprocess/.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/assembly/assembler.h>
#include <vesicle_iga/assembly/dirichlet_constraints.h>
#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/io/checkpoint.h>
#include <vesicle_iga/io/spline_output.h>
#include <vesicle_iga/io/time_series.h>
#include <vesicle_iga/io/vesicle_output.h>
#include <vesicle_iga/parallel/natural_numbering.h>
#include <vesicle_iga/physics/bending_energy.h>
#include <vesicle_iga/physics/electric_energies.h>
#include <vesicle_iga/physics/electric_potential.h>
#include <vesicle_iga/physics/electromechanics_material.h>
#include <vesicle_iga/physics/phase_field_operator.h>
#include <vesicle_iga/physics/vesicle_shape.h>
#include <vesicle_iga/postprocess/level_set_extent.h>
#include <vesicle_iga/solvers/modified_alm.h>
#include <vesicle_iga/solvers/phase_field_newton.h>
#include <vesicle_iga/spline/box_space_parameters.h>
#include <vesicle_iga/studies/study.h>
#include <vesicle_iga/time/local_error_estimate.h>
#include <vesicle_iga/time/step_size_controller.h>

#include <cmath>

namespace vesicle_iga
{
  namespace
  {
    const char *section = "Willmore flow";

    template <int dim>
    class WillmoreFlow : public Study
    {
    public:
      WillmoreFlow(ParameterHandler &prm, RunContext &context);
      void
      run() override;

    private:
      /// What is monitored after every accepted step.
      struct Monitor
      {
        std::vector<double> functionals; // one per term (energies, A, V)
        double              energy = 0, area = 0, volume = 0;
        /// E + Lambda_A (A - A0) + Lambda_V (V - V0): insensitive to first
        /// order to the constraint errors that the ALM tolerance allows,
        /// so it decreases along the discrete flow where E itself may
        /// jitter at the level of that tolerance.
        double              lagrangian = 0;
        std::vector<double> extents;
      };

      void
      setup();
      Monitor
      monitor(const TrilinosWrappers::MPI::Vector &phi_owned);
      /// How the interface moved over the last accepted step: the rigid
      /// drift velocity U that best explains phi_n - phi_nm1, and the RMS
      /// normal speed of what is left (the shape change),
      /// ||phi_n - phi_nm1 + dt U . grad phi_n|| / (dt ||grad phi_n||): a
      /// front moving at normal speed v changes phi by v dt |grad phi|.
      struct InterfaceMotion
      {
        Tensor<1, dim> drift;
        double         speed = 0;
      };
      InterfaceMotion
      interface_motion(const double dt);
      /// Solve the step t -> t + dt with the constraint method; false on
      /// failure.
      bool
      constrained_step(const double  dt,
                       ModifiedALM  &alm,
                       unsigned int &newton_its,
                       unsigned int &krylov_its,
                       unsigned int &alm_its);
      std::vector<double>
      natural_coefficients(const TrilinosWrappers::MPI::Vector &v) const;
      void
      from_natural(const std::vector<double>     &c,
                   TrilinosWrappers::MPI::Vector &v) const;
      void
      write_vtu(const unsigned int step);
      /// Staggered scheme (spec 3.9): psi from the phase field in @p v.
      void
      solve_potential(const TrilinosWrappers::MPI::Vector &v);
      /// The zero crossings along the field axis through the centre.
      std::vector<double>
      field_axis_crossings(const TrilinosWrappers::MPI::Vector &v) const;
      /// The inverse 2x2 Jacobian of (E21) from the linearised step.
      std::array<double, 4>
      linearised_alm_inverse(const double                 dt,
                             const std::array<double, 4> &fallback);

      RunContext                    &context;
      BoxSpaceParameters             box;
      unsigned int                   degree, quadrature_points;
      int                            continuity;
      double                         kappa, spontaneous_curvature;
      double                         epsilon_over_h;
      std::string                    epsilon_reference;
      VesicleShape<dim>              shape;
      std::string                    constraint_method, alm_jacobian;
      double                         M1, M2, constraint_tolerance;
      unsigned int                   max_alm_iterations;
      double                         rho_inf, end_time, stationarity_tolerance;
      std::string                    stationarity_measure;
      double                         stationary_interface_speed;
      unsigned int                   max_steps;
      unsigned int                   vtu_interval, checkpoint_interval;
      std::string                    restart_file;
      bool                           check_jacobian_first;
      std::vector<double>            solver_benchmark_dts;
      NewtonParameters               newton_parameters;
      LinearSolverParameters         solver;
      StepSizeController::Parameters time_step;
      ElectromechanicsMaterial       material;
      LinearSolverParameters         potential_solver;
      std::string                    coupling;
      double                         fixed_point_tolerance;
      unsigned int                   max_fixed_point_iterations;

      // Discrete state, set up in setup().
      std::unique_ptr<TimerOutput>           timer;
      std::unique_ptr<SplineSpace<dim>>      space;
      std::unique_ptr<PatchMesh<dim>>        mesh;
      std::unique_ptr<SplineDofHandler<dim>> dofs;
      AffineConstraints<double>              phi_constraints;
      AffineConstraints<double>              increment_constraints;
      TrilinosWrappers::MPI::Vector          phi_n, phidot_n, phi_nm1;
      TrilinosWrappers::MPI::Vector          phi, phidot, ghosted;
      std::unique_ptr<BendingEnergy<dim>>    bending;
      std::unique_ptr<AreaConstraint<dim>>   area;
      VolumeConstraint<dim>                  volume;
      /// Energy terms, then the constraint terms if any.
      std::vector<const PhaseFieldTerm<dim> *> terms;
      unsigned int                             n_energy_terms = 0;
      std::unique_ptr<PhaseFieldOperator<dim>> op;
      std::unique_ptr<PhaseFieldNewton<dim>>   newton;
      std::unique_ptr<ElectricPotential<dim>>  potential;
      std::unique_ptr<PhaseFieldTerm<dim>> flexoelectric, membrane_dielectric,
        electrolyte_dielectric;
      unsigned int                      potential_iterations = 0;
      std::unique_ptr<GeneralizedAlpha> alpha;
      double                            epsilon = 0, h = 0;
      double                            V0 = 0, A0 = 0;
      Monitor                           current;
    };


    template <int dim>
    WillmoreFlow<dim>::WillmoreFlow(ParameterHandler &prm, RunContext &context)
      : context(context)
    {
      prm.enter_subsection(section);
      box.parse(prm, dim);
      degree                     = prm.get_integer("Degree");
      continuity                 = prm.get_integer("Continuity");
      quadrature_points          = prm.get_integer("Quadrature points");
      kappa                      = prm.get_double("Bending rigidity");
      spontaneous_curvature      = prm.get_double("Spontaneous curvature");
      epsilon_over_h             = prm.get_double("Epsilon over h");
      epsilon_reference          = prm.get("Element size for epsilon");
      constraint_method          = prm.get("Constraint method");
      alm_jacobian               = prm.get("ALM initial Jacobian");
      M1                         = prm.get_double("M1");
      M2                         = prm.get_double("M2");
      constraint_tolerance       = prm.get_double("Constraint tolerance");
      max_alm_iterations         = prm.get_integer("Max ALM iterations");
      rho_inf                    = prm.get_double("rho_inf");
      end_time                   = prm.get_double("End time");
      max_steps                  = prm.get_integer("Max steps");
      stationarity_tolerance     = prm.get_double("Stationarity tolerance");
      stationarity_measure       = prm.get("Stationarity measure");
      stationary_interface_speed = prm.get_double("Stationary interface speed");
      vtu_interval               = prm.get_integer("VTU interval");
      checkpoint_interval        = prm.get_integer("Checkpoint interval");
      restart_file               = prm.get("Restart from");
      check_jacobian_first       = prm.get_bool("Check Jacobian");
      solver_benchmark_dts
        = parse_double_list(prm.get("Linear solver benchmark"),
                            "Linear solver benchmark");
      shape.parse(prm);
      newton_parameters.parse(prm);
      solver.parse(prm);
      time_step.parse(prm);
      material.parse(prm, dim);
      prm.enter_subsection("Electric field");
      potential_solver.parse(prm);
      coupling              = prm.get("Coupling");
      fixed_point_tolerance = prm.get_double("Fixed-point tolerance");
      max_fixed_point_iterations
        = prm.get_integer("Max fixed-point iterations");
      prm.leave_subsection();
      prm.leave_subsection();

      const int k = continuity < 0 ? int(degree) - 1 : continuity;
      check_input(k >= 1 && k <= int(degree) - 1,
                  "Continuity",
                  std::to_string(continuity),
                  "1 <= k <= p-1 (the primal H^2 form (E18) needs C^1 "
                  "splines; degree "
                    + std::to_string(degree) + ")");
      check_input(kappa > 0,
                  "Bending rigidity",
                  std::to_string(kappa),
                  "a positive value");
      check_input(epsilon_over_h >= 1,
                  "Epsilon over h",
                  std::to_string(epsilon_over_h),
                  ">= 1: the tanh profile (E1) has width ~2.8 eps and must "
                  "span several elements");
      // Validate the mesh now.
      box.make_space<dim>(degree, continuity);
    }


    template <int dim>
    void
    WillmoreFlow<dim>::setup()
    {
      space = std::make_unique<SplineSpace<dim>>(
        box.make_space<dim>(degree, continuity));
      // h: the longest edge of the smallest element (spec 7.13: epsilon =
      // 2 max(h) on the anisotropic EM1 mesh), or its shortest edge.
      double     h_long = 0., h_short = std::numeric_limits<double>::max();
      Point<dim> lower, upper;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const KnotVector &kv       = space->knot_vector(d);
          double            shortest = std::numeric_limits<double>::max();
          for (unsigned int e = 0; e < kv.n_elements(); ++e)
            shortest = std::min(shortest, kv.element_length(e));
          h_long   = std::max(h_long, shortest);
          h_short  = std::min(h_short, shortest);
          lower[d] = kv.breakpoints().front();
          upper[d] = kv.breakpoints().back();
        }
      h       = epsilon_reference == "largest edge" ? h_long : h_short;
      epsilon = epsilon_over_h * h;
      check_input(epsilon >= h_long * (1 - 1e-12),
                  "Epsilon over h",
                  std::to_string(epsilon_over_h),
                  "epsilon = " + std::to_string(epsilon)
                    + " at least the longest edge of the smallest element ("
                    + std::to_string(h_long)
                    + "): the tanh profile (E1) must span several elements");
      shape.check_fits(lower, upper, epsilon, context.pcout);

      timer = std::make_unique<TimerOutput>(context.communicator,
                                            context.pcout,
                                            context.print_details ?
                                              TimerOutput::summary :
                                              TimerOutput::never,
                                            TimerOutput::wall_times);
      mesh  = std::make_unique<PatchMesh<dim>>(context.communicator,
                                              *space,
                                              nullptr);
      dofs  = std::make_unique<SplineDofHandler<dim>>(*mesh, *space, 1);

      // Clamped boundary (E15): the two outer layers of coefficients are 1
      // for phi and 0 for its rate and every Newton increment.
      const BoundarySelection<dim> all("all", "boundary");
      const auto                   zero_normal
        = [](const Point<dim> &, const Tensor<1, dim> &) { return 0.; };
      phi_constraints.reinit(dofs->locally_relevant_dofs());
      add_clamped_constraints<dim>(*dofs,
                                   all,
                                   Functions::ConstantFunction<dim>(1.),
                                   zero_normal,
                                   phi_constraints);
      phi_constraints.close();
      increment_constraints.reinit(dofs->locally_relevant_dofs());
      add_clamped_constraints<dim>(*dofs,
                                   all,
                                   Functions::ZeroFunction<dim>(),
                                   zero_normal,
                                   increment_constraints);
      increment_constraints.close();

      const IndexSet &owned = dofs->locally_owned_dofs();
      for (auto *v : {&phi_n, &phidot_n, &phi_nm1, &phi, &phidot})
        v->reinit(owned, context.communicator);
      ghosted.reinit(owned,
                     dofs->locally_relevant_dofs(),
                     context.communicator);

      bending = std::make_unique<BendingEnergy<dim>>(kappa,
                                                     epsilon,
                                                     spontaneous_curvature);
      area    = std::make_unique<AreaConstraint<dim>>(epsilon);
      terms   = {bending.get()};
      // The electric energies of (E6)-(E8) in the normalised units of spec
      // 3.10, each switchable.
      if (material.active())
        {
          if (material.flexoelectric)
            {
              flexoelectric = std::make_unique<FlexoelectricEnergy<dim>>(
                material.flexoelectric_coefficient(),
                material.membrane_thickness(),
                epsilon);
              terms.push_back(flexoelectric.get());
            }
          if (material.membrane_dielectric)
            {
              membrane_dielectric
                = std::make_unique<MembraneDielectricEnergy<dim>>(
                  material.membrane_thickness(),
                  material.permittivity(material.e_m),
                  epsilon);
              terms.push_back(membrane_dielectric.get());
            }
          if (material.electrolyte_dielectric)
            {
              electrolyte_dielectric
                = std::make_unique<ElectrolyteDielectricEnergy<dim>>(
                  material.permittivity(material.e_in),
                  material.permittivity(material.e_out));
              terms.push_back(electrolyte_dielectric.get());
            }
        }
      n_energy_terms = terms.size();
      if (constraint_method != "none")
        {
          terms.push_back(area.get());
          terms.push_back(&volume);
        }
      op = std::make_unique<PhaseFieldOperator<dim>>(*dofs, terms);
      if (material.active())
        {
          potential
            = std::make_unique<ElectricPotential<dim>>(*dofs,
                                                       material,
                                                       QGauss<1>(
                                                         quadrature_points),
                                                       potential_solver,
                                                       *timer);
          op->set_potential(&potential->potential());
        }
      alpha = std::make_unique<GeneralizedAlpha>(rho_inf);
      newton
        = std::make_unique<PhaseFieldNewton<dim>>(*dofs,
                                                  *op,
                                                  increment_constraints,
                                                  QGauss<1>(quadrature_points),
                                                  solver,
                                                  newton_parameters,
                                                  *timer);
    }


    template <int dim>
    std::vector<double>
    WillmoreFlow<dim>::natural_coefficients(
      const TrilinosWrappers::MPI::Vector &v) const
    {
      return gather_natural(*dofs, v);
    }


    template <int dim>
    void
    WillmoreFlow<dim>::from_natural(const std::vector<double>     &c,
                                    TrilinosWrappers::MPI::Vector &v) const
    {
      scatter_natural(*dofs, c, v);
    }


    template <int dim>
    typename WillmoreFlow<dim>::Monitor
    WillmoreFlow<dim>::monitor(const TrilinosWrappers::MPI::Vector &v)
    {
      TimerOutput::Scope t(*timer, "monitor");
      ghosted = v;
      Monitor m;
      m.functionals
        = op->integrate_terms(terms, ghosted, QGauss<1>(quadrature_points));
      for (unsigned int k = 0; k < n_energy_terms; ++k)
        m.energy += m.functionals[k];
      if (constraint_method != "none")
        {
          m.area   = m.functionals[n_energy_terms];
          m.volume = m.functionals[n_energy_terms + 1];
        }
      m.lagrangian = m.energy + area->multiplier() * (m.area - A0)
                     + volume.multiplier() * (m.volume - V0);
      const auto c = natural_coefficients(v);
      for (unsigned int d = 0; d < dim; ++d)
        m.extents.push_back(zero_level_set_extent(*space, c, shape.center, d));
      return m;
    }


    template <int dim>
    typename WillmoreFlow<dim>::InterfaceMotion
    WillmoreFlow<dim>::interface_motion(const double dt)
    {
      TimerOutput::Scope t(*timer, "monitor");
      // With r = (phi_n - phi_nm1) / dt: the rigid velocity U that best
      // explains r, r ~ -U . grad phi (least squares: M U = -b with
      // M = (grad phi, grad phi^T), b = (r, grad phi)), and what is left,
      // ||r + U . grad phi||^2 = ||r||^2 + U . b.
      TrilinosWrappers::MPI::Vector change(phi_n);
      change -= phi_nm1;
      change /= dt;
      TrilinosWrappers::MPI::Vector ghosted_change(ghosted);
      ghosted_change = change;
      ghosted        = phi_n;
      const auto sums
        = op->integrate(&ghosted,
                        &ghosted_change,
                        QGauss<1>(quadrature_points),
                        1 + dim + dim * dim,
                        [](const PhaseFieldPoint<dim> &p,
                           const PhaseFieldPoint<dim> &r,
                           const double                JxW,
                           std::vector<double>        &sum) {
                          sum[0] += r.phi * r.phi * JxW;
                          for (unsigned int i = 0; i < dim; ++i)
                            {
                              sum[1 + i] += r.phi * p.grad_phi[i] * JxW;
                              for (unsigned int j = 0; j < dim; ++j)
                                sum[1 + dim + dim * i + j]
                                  += p.grad_phi[i] * p.grad_phi[j] * JxW;
                            }
                        });
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
    bool
    WillmoreFlow<dim>::constrained_step(const double  dt,
                                        ModifiedALM  &alm,
                                        unsigned int &newton_its,
                                        unsigned int &krylov_its,
                                        unsigned int &alm_its)
    {
      const auto newton_solve = [&]() {
        const auto r = newton->solve(*alpha, dt, phi_n, phidot_n, phi, phidot);
        newton_its += r.newton_iterations;
        krylov_its += r.krylov_iterations;
        return r.converged;
      };
      if (constraint_method == "alm")
        {
          const auto solve = [&](double al, double be, double &v, double &a) {
            // (E19): multipliers explicit in V(phi_n), A(phi_n).
            volume.set_multiplier(M1 * (current.volume - al));
            area->set_multiplier(M2 * (current.area - be));
            if (!newton_solve())
              return false;
            ghosted      = phi;
            const auto f = op->integrate_terms({area.get(), &volume},
                                               ghosted,
                                               QGauss<1>(quadrature_points));
            a            = f[0];
            v            = f[1];
            return true;
          };
          const auto refresh = [&](std::array<double, 4> &T) {
            if (alm_jacobian != "linearised")
              return false;
            T = linearised_alm_inverse(dt, T);
            return true;
          };
          const auto r = alm.step(solve, current.volume, current.area, refresh);
          alm_its      = r.iterations;
          return r.converged;
        }
      if (constraint_method == "penalty")
        {
          volume.set_multiplier(M1 * (current.volume - V0));
          area->set_multiplier(M2 * (current.area - A0));
        }
      return newton_solve();
    }


    template <int dim>
    std::array<double, 4>
    WillmoreFlow<dim>::linearised_alm_inverse(
      const double                 dt,
      const std::array<double, 4> &fallback)
    {
      // T = d(V(phi_{n+1}), A(phi_{n+1})) / d(alpha, beta) of (E21) from
      // the linearisation of the step just solved: with g_V = (dV/dphi,
      // N_i), g_A = (dA/dphi, N_i) at that solution (the constraint terms
      // of (E18) with unit multiplier), dphi_{n+1}/dLambda_X = -gamma dt
      // K^{-1} g_X, dV/dLambda_X = g_V . dphi_{n+1}/dLambda_X (likewise A),
      // and (E19) gives dLambda_V/dalpha = -M1, dLambda_A/dbeta = -M2.
      TimerOutput::Scope    t(*timer, "ALM Jacobian");
      AreaConstraint<dim>   unit_area(epsilon);
      VolumeConstraint<dim> unit_volume;
      unit_area.set_multiplier(1.);
      unit_volume.set_multiplier(1.);
      std::vector<TrilinosWrappers::MPI::Vector> g(2), x;
      TrilinosWrappers::MPI::Vector              ghosted_rate(ghosted);
      ghosted_rate = 0;
      ghosted      = phi;
      for (unsigned int k = 0; k < 2; ++k)
        {
          const PhaseFieldTerm<dim> *term
            = k == 0 ? static_cast<const PhaseFieldTerm<dim> *>(&unit_volume) :
                       static_cast<const PhaseFieldTerm<dim> *>(&unit_area);
          PhaseFieldOperator<dim> variation(*dofs, {term});
          variation.set_state(ghosted, ghosted_rate, 0., 0., false);
          g[k].reinit(phi_n);
          assemble_vector<dim>(*dofs,
                               nullptr,
                               QGauss<1>(quadrature_points),
                               {&variation},
                               increment_constraints,
                               g[k]);
          g[k] *= -1.; // assemble_vector gives -R
        }
      newton->linear_response(g, x);
      const double c = -alpha->gamma * dt;
      // d(V, A)/d(Lambda_V, Lambda_A)
      const double dV_dLV = c * (g[0] * x[0]), dV_dLA = c * (g[0] * x[1]);
      const double dA_dLV = c * (g[1] * x[0]), dA_dLA = c * (g[1] * x[1]);
      const double T00 = -M1 * dV_dLV, T01 = -M2 * dV_dLA;
      const double T10 = -M1 * dA_dLV, T11 = -M2 * dA_dLA;
      const double det = T00 * T11 - T01 * T10;
      if (!std::isfinite(det) || std::abs(det) < 1e-300)
        return fallback;
      return {{T11 / det, -T01 / det, -T10 / det, T00 / det}};
    }


    template <int dim>
    void
    WillmoreFlow<dim>::write_vtu(const unsigned int step)
    {
      TimerOutput::Scope t(*timer, "output");
      ghosted                = phi_n;
      const std::string name = Utilities::int_to_string(step, 5);
      write_vesicle_vtu(*dofs,
                        ghosted,
                        potential ? &potential->potential() : nullptr,
                        material,
                        context.output_directory,
                        (potential ? "fields-" : "phi-") + name);
      // Profiles of phi, sigma (and psi, |grad psi|) along the axes.
      const auto          phi_natural = natural_coefficients(phi_n);
      std::vector<double> psi_natural;
      if (potential)
        psi_natural = natural_coefficients(potential->owned_potential());
      if (Utilities::MPI::this_mpi_process(context.communicator) == 0)
        write_axis_profiles(*space,
                            phi_natural,
                            potential ? &psi_natural : nullptr,
                            material,
                            shape.center,
                            context.output_directory + "/profiles-" + name
                              + ".csv");
      // The plane of the field axis and the first other axis (x-y for the
      // default field along y; x-y in 2D).
      const unsigned int field_axis   = material.direction();
      const unsigned int lateral_axis = field_axis == 0 ? 1 : 0;
      if (Utilities::MPI::this_mpi_process(context.communicator) == 0)
        write_plane_section(*space,
                            phi_natural,
                            shape.center,
                            std::min(lateral_axis, field_axis),
                            std::max(lateral_axis, field_axis),
                            context.output_directory + "/section-" + name
                              + ".csv");
    }


    template <int dim>
    void
    WillmoreFlow<dim>::solve_potential(const TrilinosWrappers::MPI::Vector &v)
    {
      if (!potential)
        return;
      ghosted = v;
      potential_iterations += potential->solve(ghosted).iterations;
    }


    template <int dim>
    std::vector<double>
    WillmoreFlow<dim>::field_axis_crossings(
      const TrilinosWrappers::MPI::Vector &v) const
    {
      return zero_crossings_along_axis(*space,
                                       natural_coefficients(v),
                                       shape.center,
                                       material.direction());
    }


    template <int dim>
    void
    WillmoreFlow<dim>::run()
    {
      setup();
      const MPI_Comm comm = context.communicator;
      context.pcout << "Willmore flow: " << dim << "D, degree " << degree
                    << ", " << space->n_elements() << " elements, "
                    << dofs->n_dofs() << " unknowns, h = " << h
                    << ", epsilon = " << epsilon << " (" << epsilon_over_h
                    << " h)" << std::endl;
      if (context.print_details)
        context.pcout << "linear solver: " << newton->solver_description()
                      << std::endl;

      // Initial condition (E1)/(E3) or the state of a checkpoint.
      StepSizeController controller(time_step);
      ModifiedALM        alm(1., 1., constraint_tolerance, max_alm_iterations);
      double             t = 0, dt_prev = 0, monitored_prev = 0;
      // Energies are compared on the scale of the shape-dependent part: the
      // bending energy plus what the flow has released so far. The
      // electrolyte term (E8) carries a large shape-independent part
      // (-1/2 int e |grad psi|^2 over the whole box) that would make a
      // change relative to the total meaningless.
      double     lagrangian_initial = 0;
      const auto energy_scale       = [&](const auto &state) {
        return std::abs(state.functionals[0])
               + std::abs(lagrangian_initial - state.lagrangian);
      };
      unsigned int step = 0, rejected = 0;
      // For the closing summary: worst constraint error and largest
      // increases of E and of the Lagrangian between accepted steps.
      double max_constraint_error = 0, max_energy_increase = 0,
             max_lagrangian_increase = 0;
      const std::vector<std::string> vector_names
        = {"phi_n", "phidot_n", "phi_nm1"};
      const std::vector<std::string> scalar_names = {"t",
                                                     "dt_prev",
                                                     "step",
                                                     "energy_prev",
                                                     "dt",
                                                     "c_prev",
                                                     "steps_since_cut",
                                                     "alm_alpha",
                                                     "alm_beta",
                                                     "alm_T00",
                                                     "alm_T01",
                                                     "alm_T10",
                                                     "alm_T11",
                                                     "V0",
                                                     "A0",
                                                     "n_basis",
                                                     "max_constraint_error",
                                                     "max_energy_increase",
                                                     "max_lagrangian_increase",
                                                     "Lambda_V",
                                                     "Lambda_A",
                                                     "lagrangian_initial"};
      if (restart_file.empty())
        {
          from_natural(shape.phase_field(*space, epsilon), phi_n);
          phi_constraints.distribute(phi_n);
          phi_nm1 = phi_n;
          solve_potential(phi_n);
          current            = monitor(phi_n);
          V0                 = current.volume;
          A0                 = current.area;
          monitored_prev     = current.lagrangian;
          lagrangian_initial = current.lagrangian;
          alm = ModifiedALM(V0, A0, constraint_tolerance, max_alm_iterations);
        }
      else
        {
          const Checkpoint c
            = Checkpoint::read(restart_file, comm, vector_names, scalar_names);
          check_input(c.scalars.at("n_basis") == space->n_basis(),
                      "Restart from",
                      restart_file,
                      "a checkpoint of the same mesh and degree (it has "
                        + std::to_string(int(c.scalars.at("n_basis")))
                        + " unknowns, this run "
                        + std::to_string(space->n_basis()) + ")");
          from_natural(c.vectors.at("phi_n"), phi_n);
          from_natural(c.vectors.at("phidot_n"), phidot_n);
          from_natural(c.vectors.at("phi_nm1"), phi_nm1);
          const auto &s      = c.scalars;
          t                  = s.at("t");
          dt_prev            = s.at("dt_prev");
          step               = s.at("step");
          monitored_prev     = s.at("energy_prev");
          lagrangian_initial = s.at("lagrangian_initial");
          controller.set_state(s.at("dt"),
                               s.at("c_prev"),
                               s.at("steps_since_cut"));
          V0  = s.at("V0");
          A0  = s.at("A0");
          alm = ModifiedALM(V0, A0, constraint_tolerance, max_alm_iterations);
          alm.set_state(s.at("alm_alpha"),
                        s.at("alm_beta"),
                        {{s.at("alm_T00"),
                          s.at("alm_T01"),
                          s.at("alm_T10"),
                          s.at("alm_T11")}});
          max_constraint_error    = s.at("max_constraint_error");
          max_energy_increase     = s.at("max_energy_increase");
          max_lagrangian_increase = s.at("max_lagrangian_increase");
          volume.set_multiplier(s.at("Lambda_V"));
          area->set_multiplier(s.at("Lambda_A"));
          solve_potential(phi_n);
          current = monitor(phi_n);
        }
      context.pcout << (restart_file.empty() ? "initial" : "restart")
                    << " (t = " << t << ", step " << step
                    << "): bending energy / kappa = "
                    << current.functionals[0] / kappa << ", area A0 = " << A0
                    << ", volume V0 = " << V0 << std::endl;

      if (!solver_benchmark_dts.empty())
        {
          for (const double dt : solver_benchmark_dts)
            newton->benchmark_linear_solver(
              *alpha, dt, phi_n, phidot_n, context.pcout);
          return;
        }
      if (check_jacobian_first)
        {
          area->set_multiplier(0.3);
          volume.set_multiplier(0.2);
          newton->check_jacobian(*alpha, phi_n, phidot_n, context.pcout);
          area->set_multiplier(0);
          volume.set_multiplier(0);
        }

      // Time series: one row per accepted step (energies in units of
      // kappa).
      std::vector<std::string> columns = {"step",
                                          "t",
                                          "dt",
                                          "newton_iterations",
                                          "krylov_iterations",
                                          "alm_iterations",
                                          "rejected_steps"};
      for (unsigned int k = 0; k < n_energy_terms; ++k)
        columns.push_back(terms[k]->name());
      for (const char *c : {"total_energy",
                            "lagrangian",
                            "area_error",
                            "volume_error",
                            "tension_multiplier",
                            "pressure_multiplier"})
        columns.emplace_back(c);
      for (unsigned int d = 0; d < dim; ++d)
        columns.push_back(std::string("extent_") + "xyz"[d]);
      columns.emplace_back("interface_speed");
      for (unsigned int d = 0; d < dim; ++d)
        columns.push_back(std::string("drift_velocity_") + "xyz"[d]);
      if (potential)
        {
          // Energies in eV (spec 3.10), the potential solver's
          // iterations, and the midpoint of the zero crossings along the
          // field axis through the centre (0 for a shape that is mirror
          // symmetric about the mid-plane normal to the field).
          for (unsigned int k = 0; k < n_energy_terms; ++k)
            columns.push_back(terms[k]->name() + "_eV");
          for (const char *c : {"total_energy_eV",
                                "potential_iterations",
                                "field_axis_midpoint"})
            columns.emplace_back(c);
        }
      TimeSeriesWriter series(context.output_directory + "/time-series.csv",
                              columns,
                              comm,
                              restart_file.empty() ? -1 : long(step));
      if (vtu_interval > 0 && restart_file.empty())
        write_vtu(0);

      const auto write_checkpoint = [&]() {
        TimerOutput::Scope t_(*timer, "output");
        Checkpoint         c;
        c.vectors["phi_n"]    = natural_coefficients(phi_n);
        c.vectors["phidot_n"] = natural_coefficients(phidot_n);
        c.vectors["phi_nm1"]  = natural_coefficients(phi_nm1);
        const auto &T         = alm.inverse_jacobian();
        c.scalars             = {{"t", t},
                                 {"dt_prev", dt_prev},
                                 {"step", step},
                                 {"energy_prev", monitored_prev},
                                 {"lagrangian_initial", lagrangian_initial},
                                 {"dt", controller.dt()},
                                 {"c_prev", controller.previous_filter_value()},
                                 {"steps_since_cut", controller.steps_since_failure()},
                                 {"alm_alpha", alm.alpha()},
                                 {"alm_beta", alm.beta()},
                                 {"alm_T00", T[0]},
                                 {"alm_T01", T[1]},
                                 {"alm_T10", T[2]},
                                 {"alm_T11", T[3]},
                                 {"V0", V0},
                                 {"A0", A0},
                                 {"n_basis", double(space->n_basis())},
                                 {"max_constraint_error", max_constraint_error},
                                 {"max_energy_increase", max_energy_increase},
                                 {"max_lagrangian_increase", max_lagrangian_increase},
                                 {"Lambda_V", volume.multiplier()},
                                 {"Lambda_A", area->multiplier()}};
        c.write(context.output_directory + "/checkpoint.h5", comm);
      };

      while (t < end_time * (1 - 1e-12) && step < max_steps)
        {
          const double dt         = std::min(controller.dt(), end_time - t);
          unsigned int newton_its = 0, krylov_its = 0, alm_its = 0;
          const double alpha_save = alm.alpha(), beta_save = alm.beta();
          const auto   Tinv_save = alm.inverse_jacobian();
          bool ok = constrained_step(dt, alm, newton_its, krylov_its, alm_its);
          // Fixed-point coupling (spec 3.9 option): psi from phi_{n+1}, and
          // the step again from phi_n, until psi settles.
          unsigned int fixed_point_its = 0;
          while (ok && potential && coupling == "fixed-point")
            {
              const TrilinosWrappers::MPI::Vector psi_old(
                potential->owned_potential());
              solve_potential(phi);
              TrilinosWrappers::MPI::Vector change(psi_old);
              change -= potential->owned_potential();
              if (change.l2_norm() <= fixed_point_tolerance
                                        * potential->owned_potential().l2_norm()
                  || ++fixed_point_its >= max_fixed_point_iterations)
                break;
              alm.set_state(alpha_save, beta_save, Tinv_save);
              ok = constrained_step(dt, alm, newton_its, krylov_its, alm_its);
            }
          double error = -1;
          if (ok && step > 0)
            error = local_error_norm(
              phi, phi_n, phi_nm1, dt, dt_prev, time_step.atol, time_step.rtol);
          if (!ok || !controller.accept(error))
            {
              ++rejected;
              alm.set_state(alpha_save, beta_save, Tinv_save);
              if (potential && coupling == "fixed-point")
                solve_potential(phi_n);
              if (!ok && !controller.reject_failure())
                {
                  write_checkpoint();
                  throw std::runtime_error(
                    "Willmore flow: the step failed (Newton or ALM did not "
                    "converge) with dt at its minimum at t = "
                    + std::to_string(t)
                    + "; the time series up to that point is in "
                    + context.output_directory
                    + "/time-series.csv, the last accepted state in "
                      "checkpoint.h5");
                }
              continue;
            }

          // Accept.
          phi_nm1  = phi_n;
          phi_n    = phi;
          phidot_n = phidot;
          t += dt;
          dt_prev = dt;
          ++step;
          const double energy_prev     = current.energy;
          const double lagrangian_prev = current.lagrangian;
          // The step minimises E(phi, psi^n) with psi^n frozen (spec 3.9),
          // so that is the energy that must not rise over it: measured
          // before psi is updated. With psi^{n+1} the reported total may
          // move either way (e.g. E_DE (E8) changes with sigma(phi) though
          // its phi-derivative vanishes for e_in = e_out).
          double energy_frozen = 0, lagrangian_frozen = 0;
          if (potential && coupling != "fixed-point")
            {
              const auto frozen = monitor(phi_n);
              energy_frozen     = frozen.energy;
              lagrangian_frozen = frozen.lagrangian;
            }
          // psi^{n+1} from the accepted phase field: the potential of the
          // next step (staggered), and the one the energies are reported
          // with (the fixed-point loop has it already).
          if (coupling != "fixed-point")
            solve_potential(phi_n);
          current = monitor(phi_n);
          if (!(potential && coupling != "fixed-point"))
            {
              energy_frozen     = current.energy;
              lagrangian_frozen = current.lagrangian;
            }
          const double area_error   = current.area / A0 - 1;
          const double volume_error = current.volume / V0 - 1;
          if (constraint_method != "none")
            max_constraint_error = std::max({max_constraint_error,
                                             std::abs(area_error),
                                             std::abs(volume_error)});
          max_energy_increase
            = std::max(max_energy_increase,
                       (energy_frozen - energy_prev) / energy_scale(current));
          max_lagrangian_increase
            = std::max(max_lagrangian_increase,
                       (lagrangian_frozen - lagrangian_prev)
                         / energy_scale(current));

          std::vector<double> row = {double(step),
                                     t,
                                     dt,
                                     double(newton_its),
                                     double(krylov_its),
                                     double(alm_its),
                                     double(rejected)};
          for (unsigned int k = 0; k < n_energy_terms; ++k)
            row.push_back(current.functionals[k] / kappa);
          for (const double v : {current.energy / kappa,
                                 current.lagrangian / kappa,
                                 area_error,
                                 volume_error,
                                 area->multiplier(),
                                 volume.multiplier()})
            row.push_back(v);
          for (const double e : current.extents)
            row.push_back(e);
          const InterfaceMotion motion = interface_motion(dt);
          const double          speed  = motion.speed;
          row.push_back(speed);
          for (unsigned int d = 0; d < dim; ++d)
            row.push_back(motion.drift[d]);
          if (potential)
            {
              for (unsigned int k = 0; k < n_energy_terms; ++k)
                row.push_back(material.to_eV(current.functionals[k]));
              row.push_back(material.to_eV(current.energy));
              row.push_back(potential_iterations);
              const auto x = field_axis_crossings(phi_n);
              row.push_back(x.size() >= 2 ? 0.5 * (x.front() + x.back()) : 0.);
              potential_iterations = 0;
            }
          series.add_row(row);

          context.pcout << "step " << step << " t=" << t << " dt=" << dt
                        << " newton=" << newton_its;
          if (context.print_details)
            context.pcout << " krylov=" << krylov_its;
          context.pcout << " alm=" << alm_its
                        << " E/kappa=" << current.energy / kappa
                        << " area_error=" << area_error
                        << " volume_error=" << volume_error << std::endl;
          rejected = 0;
          if (vtu_interval > 0 && step % vtu_interval == 0)
            write_vtu(step);
          if (checkpoint_interval > 0 && step % checkpoint_interval == 0)
            write_checkpoint();
          const double change = std::abs(current.lagrangian - monitored_prev)
                                / energy_scale(current);
          monitored_prev       = current.lagrangian;
          const bool saturated = !time_step.adaptive
                                 || controller.dt() >= time_step.max_dt * 0.999;
          if (saturated && stationarity_measure == "lagrangian"
              && change <= stationarity_tolerance)
            {
              context.pcout << "stationary: relative change of the "
                               "Lagrangian "
                            << change << " over the last step" << std::endl;
              break;
            }
          if (saturated && stationarity_measure == "interface-speed"
              && speed <= stationary_interface_speed)
            {
              context.pcout << "stationary: interface speed " << speed
                            << " over the last step" << std::endl;
              break;
            }
        }
      if (vtu_interval > 0 && step % vtu_interval != 0)
        write_vtu(step);
      write_checkpoint();
      context.pcout << "final: t=" << t << " steps=" << step
                    << " E_B/kappa=" << current.functionals[0] / kappa
                    << " area_error=" << current.area / A0 - 1
                    << " volume_error=" << current.volume / V0 - 1;
      for (unsigned int d = 0; d < dim; ++d)
        context.pcout << " extent_"
                      << "xyz"[d] << "=" << current.extents[d];
      context.pcout << std::endl;
      if (step > 0)
        context.pcout << "largest |A/A0-1|, |V/V0-1| over the accepted steps: "
                      << max_constraint_error
                      << (constraint_method == "alm" ?
                            (max_constraint_error <= constraint_tolerance ?
                               " (within the ALM tolerance)" :
                               " (ABOVE the ALM tolerance)") :
                            "")
                      << std::endl
                      << "largest relative increase over an accepted step"
                      << (potential && coupling != "fixed-point" ?
                            " (psi frozen, as the step minimises)" :
                            "")
                      << ": energy " << std::max(0., max_energy_increase)
                      << ", Lagrangian "
                      << std::max(0., max_lagrangian_increase) << std::endl;
    }
  } // namespace


  StudyDescription
  willmore_flow_description()
  {
    return {
      "willmore-flow",
      "Spec Part E: constrained Willmore/Helfrich flow of a vesicle, "
      "generalized-alpha, Newton, modified ALM or penalty, adaptive steps; "
      "with subsection 'Electric field' the flexoelectric and dielectric "
      "energies and the electric potential (staggered or fixed-point).",
      [](ParameterHandler &prm) {
        prm.enter_subsection(section);
        BoxSpaceParameters::declare(prm, "-2", "2", "32");
        // GMRES with one V-cycle of the spline multigrid (ILU(0) smoother):
        // robust for the fourth-order Newton matrix at large dt, where
        // ILU and AMG alone need hundreds of iterations (doc/willmore.md).
        LinearSolverParameters::declare(prm, "gmres-mg", "1e-8", "ilu", "1");
        // Spec section 2.5 / 6.2: dt_0 = 1e-10, dt_max = 1.
        StepSizeController::Parameters::declare(prm, "1e-10", "1");
        VesicleShape<2>::declare(prm);
        NewtonParameters::declare(prm);
        prm.declare_entry("Degree",
                          "3",
                          Patterns::Integer(2, max_spline_degree),
                          "Spline degree p (spec: cubic).");
        prm.declare_entry("Continuity",
                          "-1",
                          Patterns::Integer(-1),
                          "C^k at interior breakpoints, 1 <= k <= p-1; -1: "
                          "p-1.");
        prm.declare_entry("Quadrature points",
                          "6",
                          Patterns::Integer(1, 12),
                          "Gauss points per direction (spec section 2.2: 6).");
        prm.declare_entry("Bending rigidity",
                          "1",
                          Patterns::Double(0),
                          "kappa in units of the energy unit (spec 3.10: "
                          "kappa = 1e-19 J = 1).");
        prm.declare_entry("Spontaneous curvature",
                          "0",
                          Patterns::Double(),
                          "H_sp of (E4), per length unit (um).");
        prm.declare_entry("Epsilon over h",
                          "2",
                          Patterns::Double(0),
                          "Interface width epsilon as a multiple of the "
                          "element size h (spec: 2).");
        prm.declare_entry("Element size for epsilon",
                          "largest edge",
                          Patterns::Selection("largest edge|shortest edge"),
                          "h in 'Epsilon over h': the largest or the "
                          "shortest edge of the smallest element (spec 7.13: "
                          "epsilon = 2 max(h) for the anisotropic EM1 "
                          "mesh).");
        prm.declare_entry("Constraint method",
                          "alm",
                          Patterns::Selection("alm|penalty|none"),
                          "alm: modified augmented Lagrangian (spec 3.8); "
                          "penalty: fixed targets V0, A0 with M1, M2; none.");
        prm.declare_entry(
          "ALM initial Jacobian",
          "linearised",
          Patterns::Selection("linearised|previous step"),
          "The inverse 2x2 Jacobian T^{-1} that the first three ALM "
          "iterations of a step use (Algorithm 1, lines 5-10; spec 7 item "
          "7). previous step: the last secant estimate throughout (the "
          "source's literal reading; I before the first step). "
          "linearised: the first iteration uses it too, and after an "
          "unconverged iteration it is replaced by the Jacobian of the "
          "linearised step (two linear solves with the Newton matrix at "
          "hand), which keeps the ALM at 1-2 iterations per step when dt "
          "or the shape change. The secant update (E22) takes over from "
          "iteration 4 either way.");
        prm.declare_entry("M1", "1", Patterns::Double(0), "Volume penalty M1.");
        prm.declare_entry("M2", "1", Patterns::Double(0), "Area penalty M2.");
        prm.declare_entry("Constraint tolerance",
                          "1e-4",
                          Patterns::Double(0),
                          "ALM: max(|V/V0-1|, |A/A0-1|) to accept a step.");
        prm.declare_entry("Max ALM iterations",
                          "20",
                          Patterns::Integer(3),
                          "ALM iterations before the step is rejected.");
        prm.declare_entry("rho_inf",
                          "0.5",
                          Patterns::Double(0, 1),
                          "Spectral radius at infinity of generalized-alpha.");
        prm.declare_entry("End time",
                          "300",
                          Patterns::Double(0),
                          "End time (normalised units; spec 6.2: 300).");
        prm.declare_entry("Max steps",
                          "100000",
                          Patterns::Integer(1),
                          "Upper bound on accepted steps.");
        prm.declare_entry("Stationarity tolerance",
                          "1e-6",
                          Patterns::Double(0),
                          "Stop when the change of the Lagrangian "
                          "L = E + Lambda_A (A - A0) + Lambda_V (V - V0) over "
                          "one step, relative to the bending energy plus the "
                          "energy released since the start (|E_B| + |L(0) - "
                          "L|), falls below this, once dt has reached Max dt. "
                          "(The electrolyte dielectric energy has a large "
                          "shape-independent part, so a change relative to L "
                          "itself would stop too early.)");
        prm.declare_entry(
          "Stationarity measure",
          "lagrangian",
          Patterns::Selection("lagrangian|interface-speed"),
          "What decides that the flow is stationary (once dt has reached "
          "Max dt). lagrangian: 'Stationarity tolerance' on the relative "
          "change of L over a step. interface-speed: 'Stationary interface "
          "speed' on the RMS normal speed of the shape change, "
          "||phi_{n+1} - phi_n + dt U . grad phi_{n+1}|| / (dt ||grad "
          "phi_{n+1}||) (L2 norms), where U is the rigid drift velocity "
          "that best explains the change (written to time-series.csv as "
          "drift_velocity_*). With a "
          "field the Lagrangian is dominated by the electrolyte dielectric "
          "energy (E8), which follows every small shape change through psi: "
          "its change over a step is noisy and, near the minimum, "
          "quadratic in the remaining shape change; the speed measures the "
          "shape change itself, and a flexoelectric vesicle that drifts "
          "along the field at a settled shape counts as stationary.");
        prm.declare_entry("Stationary interface speed",
                          "1e-4",
                          Patterns::Double(0),
                          "With 'Stationarity measure = interface-speed': "
                          "stop when the RMS normal speed of the interface "
                          "falls below this (um per unit time in the "
                          "normalised units; 1e-4 moves the interface by "
                          "0.03 um over T = 300).");
        prm.declare_entry("VTU interval",
                          "0",
                          Patterns::Integer(0),
                          "Write phi every N accepted steps (0: never).");
        prm.declare_entry("Checkpoint interval",
                          "10",
                          Patterns::Integer(0),
                          "Write <Output directory>/checkpoint.h5 every N "
                          "accepted steps (0: only at the end and on "
                          "failure).");
        prm.declare_entry("Restart from",
                          "",
                          Patterns::Anything(),
                          "A checkpoint.h5 to continue from (same mesh and "
                          "degree; any number of ranks); empty: start from "
                          "the initial shape.");
        prm.declare_entry("Linear solver benchmark",
                          "",
                          Patterns::Anything(),
                          "A list of time steps: instead of the flow, solve "
                          "the Newton system of the first step for each dt "
                          "with a known solution and print iterations, "
                          "times and errors (tools/bench); empty: off.");
        ElectromechanicsMaterial::declare(prm);
        prm.enter_subsection("Electric field");
        // CG with the spline multigrid: the Galerkin coarse operators keep
        // the seven orders of magnitude of sigma(phi). Chebyshev(3)
        // smoothing: on 2 ranks SSOR spends its time copying rows per rank
        // (Ifpack's local filter) and made the solve slower than on one
        // (tools/bench/run-electromechanics-3d.sh, 40^3: 21.0 s per solve
        // on 2 ranks against 16.1 s on 1; Chebyshev 8.9 s and 15.2 s).
        LinearSolverParameters::declare(
          prm, "cg-mg", "1e-10", "chebyshev", "3");
        prm.declare_entry("Coupling",
                          "staggered",
                          Patterns::Selection("staggered|fixed-point"),
                          "staggered: psi once per step from phi_n (spec "
                          "3.9, the reference); fixed-point: then psi again "
                          "from phi_{n+1} and the step repeated until psi "
                          "changes by less than the tolerance.");
        prm.declare_entry("Fixed-point tolerance",
                          "1e-6",
                          Patterns::Double(0),
                          "Relative change of psi (l2) that ends the "
                          "fixed-point iteration.");
        prm.declare_entry("Max fixed-point iterations",
                          "10",
                          Patterns::Integer(1),
                          "Fixed-point iterations per step at most.");
        prm.leave_subsection();
        prm.declare_entry("Check Jacobian",
                          "false",
                          Patterns::Bool(),
                          "Compare the tangent with central differences of "
                          "the residual before the first step.");
        prm.leave_subsection();
      },
      [](ParameterHandler &prm, RunContext &context) -> std::unique_ptr<Study> {
        if (context.dimension == 2)
          return std::make_unique<WillmoreFlow<2>>(prm, context);
        return std::make_unique<WillmoreFlow<3>>(prm, context);
      }};
  }
} // namespace vesicle_iga
