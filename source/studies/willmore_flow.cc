// Study "willmore-flow": constrained Willmore/Helfrich flow of a vesicle
// (spec Part E with the electric terms off): the phase-field gradient flow
// (E12) in the primal H^2 weak form (E18) on C^1+ splines, clamped boundary
// (E15) through the two outer layers of coefficients, generalized-alpha in
// time (N2)-(N4), Newton with the tangent (E20), volume and area held by
// the modified augmented-Lagrangian method (E19)-(E22) or by penalty,
// adaptive steps (spec section 2.5). Writes time-series.csv (one row per
// accepted step) and VTU every N steps.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/assembly/assembler.h>
#include <vesicle_iga/assembly/dirichlet_constraints.h>
#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/io/checkpoint.h>
#include <vesicle_iga/io/spline_output.h>
#include <vesicle_iga/physics/bending_energy.h>
#include <vesicle_iga/physics/ellipsoid_distance.h>
#include <vesicle_iga/physics/phase_field_operator.h>
#include <vesicle_iga/solvers/linear_solver.h>
#include <vesicle_iga/solvers/modified_alm.h>
#include <vesicle_iga/spline/box_space_parameters.h>
#include <vesicle_iga/studies/study.h>
#include <vesicle_iga/time/generalized_alpha.h>
#include <vesicle_iga/time/step_size_controller.h>

#include <cmath>
#include <fstream>
#include <iomanip>

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
      struct Integrals
      {
        double bending, area, volume;
      };
      Integrals
      integrals(const TrilinosWrappers::MPI::Vector &ghosted_phi) const;
      /// Newton solve of one generalized-alpha step with fixed
      /// multipliers; false on failure (no convergence, NaN, linear solver).
      bool
      newton_step(const double  dt,
                  unsigned int &newton_iterations,
                  unsigned int &krylov_iterations);
      /// Zero crossings of phi along the axis d through the centre.
      double
      extent(const std::vector<double> &natural_phi,
             const unsigned int         d) const;
      /// A vector in the natural numbering of the basis, complete on every
      /// rank: for point evaluation and partition-independent checkpoints.
      std::vector<double>
      natural_coefficients(const TrilinosWrappers::MPI::Vector &v) const;
      void
      check_jacobian();

      RunContext                    &context;
      BoxSpaceParameters             box;
      unsigned int                   degree, quadrature_points;
      int                            continuity;
      double                         kappa, spontaneous_curvature;
      double                         epsilon_over_h;
      std::string                    shape;
      std::vector<double>            center, semi_axes;
      std::string                    constraint_method;
      double                         M1, M2, constraint_tolerance;
      unsigned int                   max_alm_iterations;
      double                         rho_inf, end_time, stationarity_tolerance;
      unsigned int                   max_steps, max_newton_iterations;
      double                         newton_rtol, newton_atol;
      unsigned int                   vtu_interval, checkpoint_interval;
      std::string                    restart_file;
      bool                           check_jacobian_first;
      LinearSolverParameters         solver;
      StepSizeController::Parameters time_step;

      // Discrete state, set up in run().
      std::unique_ptr<SplineSpace<dim>>        space;
      std::unique_ptr<PatchMesh<dim>>          mesh;
      std::unique_ptr<SplineDofHandler<dim>>   dofs;
      AffineConstraints<double>                increment_constraints;
      TrilinosWrappers::SparseMatrix           matrix;
      TrilinosWrappers::MPI::Vector            phi_n, phidot_n, phi, phidot;
      TrilinosWrappers::MPI::Vector            ghost_a, ghost_b;
      std::unique_ptr<BendingEnergy<dim>>      bending;
      std::unique_ptr<AreaConstraint<dim>>     area;
      VolumeConstraint<dim>                    volume;
      std::unique_ptr<PhaseFieldOperator<dim>> op;
      std::unique_ptr<GeneralizedAlpha>        alpha;
      double                                   epsilon = 0;
      TimerOutput                             *timer   = nullptr;
    };


    template <int dim>
    WillmoreFlow<dim>::WillmoreFlow(ParameterHandler &prm, RunContext &context)
      : context(context)
    {
      prm.enter_subsection(section);
      box.parse(prm, dim);
      degree                        = prm.get_integer("Degree");
      continuity                    = prm.get_integer("Continuity");
      quadrature_points             = prm.get_integer("Quadrature points");
      kappa                         = prm.get_double("Bending rigidity");
      spontaneous_curvature         = prm.get_double("Spontaneous curvature");
      epsilon_over_h                = prm.get_double("Epsilon over h");
      shape                         = prm.get("Initial shape");
      const std::string center_text = prm.get("Center");
      center                        = parse_double_list(center_text, "Center");
      semi_axes         = parse_double_list(prm.get("Semi-axes"), "Semi-axes");
      constraint_method = prm.get("Constraint method");
      M1                = prm.get_double("M1");
      M2                = prm.get_double("M2");
      constraint_tolerance   = prm.get_double("Constraint tolerance");
      max_alm_iterations     = prm.get_integer("Max ALM iterations");
      rho_inf                = prm.get_double("rho_inf");
      end_time               = prm.get_double("End time");
      max_steps              = prm.get_integer("Max steps");
      stationarity_tolerance = prm.get_double("Stationarity tolerance");
      max_newton_iterations  = prm.get_integer("Max Newton iterations");
      newton_rtol            = prm.get_double("Newton relative tolerance");
      newton_atol            = prm.get_double("Newton absolute tolerance");
      vtu_interval           = prm.get_integer("VTU interval");
      checkpoint_interval    = prm.get_integer("Checkpoint interval");
      restart_file           = prm.get("Restart from");
      check_jacobian_first   = prm.get_bool("Check Jacobian");
      solver.parse(prm);
      time_step.parse(prm);
      prm.leave_subsection();

      const int k = continuity < 0 ? int(degree) - 1 : continuity;
      check_input(k >= 1 && k <= int(degree) - 1,
                  "Continuity",
                  std::to_string(continuity),
                  "1 <= k <= p-1 (the primal H^2 form (E18) needs C^1 "
                  "splines; degree "
                    + std::to_string(degree) + ")");
      check_input(center.size() == dim,
                  "Center",
                  center_text,
                  std::to_string(dim) + " coordinates");
      check_input(semi_axes.size() == 1 || semi_axes.size() == dim,
                  "Semi-axes",
                  std::to_string(semi_axes.size()) + " values",
                  "one value (sphere/circle) or one per direction");
      for (const double a : semi_axes)
        check_input(a > 0, "Semi-axes", std::to_string(a), "positive");
      if (semi_axes.size() == 1)
        semi_axes.assign(dim, semi_axes[0]);
      check_input(shape == "ellipsoid"
                    || *std::max_element(semi_axes.begin(), semi_axes.end())
                         == *std::min_element(semi_axes.begin(),
                                              semi_axes.end()),
                  "Semi-axes",
                  "unequal values",
                  "equal semi-axes for 'Initial shape = sphere' (use "
                  "ellipsoid for a spheroid or an ellipse)");
      check_input(epsilon_over_h >= 1,
                  "Epsilon over h",
                  std::to_string(epsilon_over_h),
                  ">= 1: the tanh profile (E1) has width ~2.8 eps and must "
                  "span several elements");
      check_input(rho_inf >= 0 && rho_inf <= 1,
                  "rho_inf",
                  std::to_string(rho_inf),
                  "0 <= rho_inf <= 1");
      // Validate the mesh now.
      box.make_space<dim>(degree, continuity);
    }


    template <int dim>
    typename WillmoreFlow<dim>::Integrals
    WillmoreFlow<dim>::integrals(const TrilinosWrappers::MPI::Vector &g) const
    {
      const auto s = integrate_field<dim>(
        *dofs,
        nullptr,
        QGauss<1>(quadrature_points),
        2,
        g,
        3,
        [&](const SplineCellValues<dim>            &v,
            const unsigned int                      q,
            const std::vector<std::vector<double>> &c,
            std::vector<double>                    &sums) {
          const auto p = PhaseFieldOperator<dim>::point(v, q, c[0]);
          sums[0] += bending->energy_density(p) * v.JxW(q);
          sums[1] += area->area_density(p) * v.JxW(q);
          sums[2] += VolumeConstraint<dim>::volume_density(p) * v.JxW(q);
        });
      return {s[0], s[1], s[2]};
    }


    template <int dim>
    bool
    WillmoreFlow<dim>::newton_step(const double  dt,
                                   unsigned int &newton_iterations,
                                   unsigned int &krylov_iterations)
    {
      const auto  &ga = *alpha;
      const double s  = ga.alpha_f * ga.gamma * dt;
      // Predictor (spec section 2.4, step 1).
      phidot = phidot_n;
      phidot *= (ga.gamma - 1) / ga.gamma;
      phi = phi_n;
      TrilinosWrappers::MPI::Vector rhs(dofs->locally_owned_dofs(),
                                        context.communicator);
      TrilinosWrappers::MPI::Vector tmp(rhs), increment(rhs);
      double                        r0 = -1;
      for (unsigned int it = 0; it <= max_newton_iterations; ++it)
        {
          // phidot_{n+alpha_m}, phi_{n+alpha_f} (N2).
          tmp = phidot;
          tmp.sadd(ga.alpha_m, 1 - ga.alpha_m, phidot_n);
          ghost_b = tmp;
          tmp     = phi;
          tmp.sadd(ga.alpha_f, 1 - ga.alpha_f, phi_n);
          ghost_a = tmp;
          op->set_state(ghost_a, ghost_b, ga.alpha_m, s, true);
          {
            TimerOutput::Scope t(*timer, "assembly");
            assemble_linear_system<dim>(*dofs,
                                        nullptr,
                                        QGauss<1>(quadrature_points),
                                        {op.get()},
                                        increment_constraints,
                                        matrix,
                                        rhs);
          }
          const double r = rhs.l2_norm();
          if (!std::isfinite(r))
            return false;
          if (r0 < 0)
            r0 = r;
          newton_iterations = it;
          if (r <= std::max(newton_atol, newton_rtol * r0))
            return true;
          if (it == max_newton_iterations)
            return false;
          try
            {
              TimerOutput::Scope t(*timer, "solve");
              increment = 0;
              krylov_iterations += solve_linear_system(solver,
                                                       matrix,
                                                       increment,
                                                       rhs,
                                                       increment_constraints)
                                     .iterations;
            }
          catch (const std::exception &)
            {
              return false;
            }
          phidot += increment;
          phi.add(ga.gamma * dt, increment);
        }
      return false;
    }


    template <int dim>
    std::vector<double>
    WillmoreFlow<dim>::natural_coefficients(
      const TrilinosWrappers::MPI::Vector &v) const
    {
      TrilinosWrappers::MPI::Vector all(dofs->locally_owned_dofs(),
                                        complete_index_set(dofs->n_dofs()),
                                        context.communicator);
      all = v;
      std::vector<double> c(space->n_basis());
      for (unsigned int i = 0; i < c.size(); ++i)
        c[i] = all[dofs->dof_index(i)];
      return c;
    }


    template <int dim>
    double
    WillmoreFlow<dim>::extent(const std::vector<double> &c,
                              const unsigned int         d) const
    {
      std::vector<double> value;
      const auto          phi_at = [&](const double s) {
        Point<dim> x;
        for (unsigned int k = 0; k < dim; ++k)
          x[k] = center[k];
        x[d] = s;
        space->evaluate(c, 1, x, value);
        return value[0];
      };
      const double        a = box.lower[d], b = box.upper[d];
      const unsigned int  n = 20 * space->knot_vector(d).n_elements();
      std::vector<double> crossings;
      double              s0 = a, f0 = phi_at(a);
      for (unsigned int i = 1; i <= n; ++i)
        {
          const double s1 = a + (b - a) * i / n, f1 = phi_at(s1);
          if ((f0 < 0) != (f1 < 0))
            {
              double lo = s0, hi = s1, flo = f0;
              for (unsigned int k = 0; k < 50; ++k)
                {
                  const double m = 0.5 * (lo + hi), fm = phi_at(m);
                  if ((fm < 0) == (flo < 0))
                    {
                      lo  = m;
                      flo = fm;
                    }
                  else
                    hi = m;
                }
              crossings.push_back(0.5 * (lo + hi));
            }
          s0 = s1;
          f0 = f1;
        }
      return crossings.size() >= 2 ? crossings.back() - crossings.front() : 0.;
    }


    template <int dim>
    void
    WillmoreFlow<dim>::check_jacobian()
    {
      // K d  against  (R(phidot + h d) - R(phidot - h d)) / 2h, with the
      // state of the first step (phidot = 0, phi = phi_0), a pseudo-random
      // direction d (zero on the clamped layers) and dt = 1, so that the
      // energy part alpha_f gamma dt DR of K (N4) dominates the mass part.
      const auto                   &ga = *alpha;
      const double                  dt = 1., s = ga.alpha_f * ga.gamma * dt;
      TrilinosWrappers::MPI::Vector d(dofs->locally_owned_dofs(),
                                      context.communicator);
      // Defined on the natural numbering: the same direction on any number
      // of ranks.
      for (unsigned int i = 0; i < space->n_basis(); ++i)
        if (d.in_local_range(dofs->dof_index(i)))
          d[dofs->dof_index(i)] = std::sin(0.37 * i) * std::cos(0.11 * i);
      d.compress(VectorOperation::insert);
      increment_constraints.set_zero(d);
      TrilinosWrappers::MPI::Vector rhs(d), Kd(d), rp(d), rm(d), tmp(d);
      const auto                    residual = [&](const double                   h,
                                TrilinosWrappers::MPI::Vector &r,
                                const bool                     with_matrix) {
        tmp = phidot_n;
        tmp.add(ga.alpha_m * h, d);
        ghost_b = tmp;
        tmp     = phi_n;
        tmp.add(s * h, d);
        ghost_a = tmp;
        op->set_state(ghost_a, ghost_b, ga.alpha_m, s, with_matrix);
        if (with_matrix)
          assemble_linear_system<dim>(*dofs,
                                      nullptr,
                                      QGauss<1>(quadrature_points),
                                      {op.get()},
                                      increment_constraints,
                                      matrix,
                                      r);
        else
          assemble_vector<dim>(*dofs,
                               nullptr,
                               QGauss<1>(quadrature_points),
                               {op.get()},
                               increment_constraints,
                               r);
      };
      residual(0, rhs, true);
      matrix.vmult(Kd, d);
      {
        // Share of the energy tangent in K d (the rest is the mass term).
        op->set_state(ghost_a, ghost_b, 0., s, true);
        assemble_linear_system<dim>(*dofs,
                                    nullptr,
                                    QGauss<1>(quadrature_points),
                                    {op.get()},
                                    increment_constraints,
                                    matrix,
                                    tmp);
        matrix.vmult(tmp, d);
        context.pcout << "Jacobian check: |alpha_f gamma dt DR d| / |K d| = "
                      << std::setprecision(3) << tmp.l2_norm() / Kd.l2_norm()
                      << std::setprecision(6) << std::endl;
      }
      context.pcout << "Jacobian check (tangent (E20) against central "
                       "differences of the residual (E18)):"
                    << std::endl;
      for (const double h : {1e-2, 1e-3, 1e-4})
        {
          residual(h, rp, false);
          residual(-h, rm, false);
          // rhs = -R, so -(rp - rm)/2h approximates K d.
          rp -= rm;
          rp *= -1. / (2 * h);
          rp -= Kd;
          context.pcout << "  h = " << h
                        << ": |FD - K d| / |K d| = " << std::scientific
                        << std::setprecision(1) << rp.l2_norm() / Kd.l2_norm()
                        << std::defaultfloat << std::setprecision(6)
                        << std::endl;
        }
    }


    template <int dim>
    void
    WillmoreFlow<dim>::run()
    {
      space = std::make_unique<SplineSpace<dim>>(
        box.make_space<dim>(degree, continuity));
      double h = std::numeric_limits<double>::max();
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int e = 0; e < space->knot_vector(d).n_elements(); ++e)
          h = std::min(h, space->knot_vector(d).element_length(e));
      epsilon = epsilon_over_h * h;

      // The initial shape must fit: phi = 1 to within 1e-3 (5.4 eps) plus
      // the two clamped layers of elements before the boundary.
      const double margin = 5.4 * epsilon;
      for (unsigned int d = 0; d < dim; ++d)
        check_input(center[d] - semi_axes[d] - margin >= box.lower[d]
                      && center[d] + semi_axes[d] + margin <= box.upper[d],
                    "Semi-axes",
                    std::to_string(semi_axes[d]) + " (direction "
                      + std::string(1, "xyz"[d]) + ")",
                    "a shape that fits in the domain with a margin of "
                    "5.4 epsilon = "
                      + std::to_string(margin)
                      + " to every face (phi = 1 there to 1e-3)");

      TimerOutput timer_output(context.communicator,
                               context.pcout,
                               context.print_details ? TimerOutput::summary :
                                                       TimerOutput::never,
                               TimerOutput::wall_times);
      timer = &timer_output;
      mesh  = std::make_unique<PatchMesh<dim>>(context.communicator,
                                              *space,
                                              nullptr);
      dofs  = std::make_unique<SplineDofHandler<dim>>(*mesh, *space, 1);
      const IndexSet &owned = dofs->locally_owned_dofs();
      const MPI_Comm  comm  = context.communicator;

      // Clamped boundary (E15): the two outer layers of coefficients are 1
      // for phi and 0 for its rate and every Newton increment.
      const BoundarySelection<dim> all("all", "boundary");
      AffineConstraints<double> phi_constraints(dofs->locally_relevant_dofs());
      const Functions::ConstantFunction<dim> one(1.);
      const auto                             zero_normal
        = [](const Point<dim> &, const Tensor<1, dim> &) { return 0.; };
      add_clamped_constraints<dim>(
        *dofs, all, one, zero_normal, phi_constraints);
      phi_constraints.close();
      increment_constraints.reinit(dofs->locally_relevant_dofs());
      add_clamped_constraints<dim>(*dofs,
                                   all,
                                   Functions::ZeroFunction<dim>(),
                                   zero_normal,
                                   increment_constraints);
      increment_constraints.close();

      TrilinosWrappers::SparsityPattern sparsity;
      dofs->make_sparsity_pattern(sparsity);
      matrix.reinit(sparsity);
      phi_n.reinit(owned, comm);
      phidot_n.reinit(owned, comm);
      phi.reinit(owned, comm);
      phidot.reinit(owned, comm);
      ghost_a.reinit(owned, dofs->locally_relevant_dofs(), comm);
      ghost_b.reinit(owned, dofs->locally_relevant_dofs(), comm);

      // Initial condition (E1)/(E3): tanh of the signed distance to the
      // sphere or ellipsoid, interpolated at the Greville points.
      {
        std::vector<double>     values(space->n_basis());
        std::array<double, dim> axes;
        for (unsigned int d = 0; d < dim; ++d)
          axes[d] = semi_axes[d];
        for (unsigned int i = 0; i < space->n_basis(); ++i)
          {
            Point<dim> y = space->greville_point(i);
            for (unsigned int d = 0; d < dim; ++d)
              y[d] -= center[d];
            values[i] = std::tanh(signed_distance_to_ellipsoid<dim>(y, axes)
                                  / (std::sqrt(2.) * epsilon));
          }
        const auto c = interpolate_at_greville_points(*space, values, 1);
        for (unsigned int i = 0; i < space->n_basis(); ++i)
          if (owned.is_element(dofs->dof_index(i)))
            phi_n[dofs->dof_index(i)] = c[i];
        phi_n.compress(VectorOperation::insert);
        phi_constraints.distribute(phi_n);
      }

      bending = std::make_unique<BendingEnergy<dim>>(kappa,
                                                     epsilon,
                                                     spontaneous_curvature);
      area    = std::make_unique<AreaConstraint<dim>>(epsilon);
      std::vector<const PhaseFieldTerm<dim> *> terms = {bending.get()};
      if (constraint_method != "none")
        {
          terms.push_back(area.get());
          terms.push_back(&volume);
        }
      op    = std::make_unique<PhaseFieldOperator<dim>>(*dofs, terms);
      alpha = std::make_unique<GeneralizedAlpha>(rho_inf);

      const auto from_natural
        = [&](const std::vector<double> &c, TrilinosWrappers::MPI::Vector &v) {
            for (unsigned int i = 0; i < c.size(); ++i)
              if (owned.is_element(dofs->dof_index(i)))
                v[dofs->dof_index(i)] = c[i];
            v.compress(VectorOperation::insert);
          };

      StepSizeController            controller(time_step);
      TrilinosWrappers::MPI::Vector phi_nm1(phi_n);
      double                        t = 0, dt_prev = 0, energy_prev = 0;
      double                        V0 = 0, A0 = 0;
      unsigned int                  step = 0, rejected = 0;
      // For the closing summary: worst constraint error and largest energy
      // increase between accepted steps.
      double                max_constraint_error = 0, max_energy_increase = 0;
      std::array<double, 4> alm_state{{0, 0, 0, 0}};
      double                alm_alpha = 0, alm_beta = 0;
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
                                                     "max_energy_increase"};
      if (!restart_file.empty())
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
          t           = c.scalars.at("t");
          dt_prev     = c.scalars.at("dt_prev");
          step        = c.scalars.at("step");
          energy_prev = c.scalars.at("energy_prev");
          controller.set_state(c.scalars.at("dt"),
                               c.scalars.at("c_prev"),
                               c.scalars.at("steps_since_cut"));
          alm_alpha            = c.scalars.at("alm_alpha");
          alm_beta             = c.scalars.at("alm_beta");
          alm_state            = {{c.scalars.at("alm_T00"),
                                   c.scalars.at("alm_T01"),
                                   c.scalars.at("alm_T10"),
                                   c.scalars.at("alm_T11")}};
          V0                   = c.scalars.at("V0");
          A0                   = c.scalars.at("A0");
          max_constraint_error = c.scalars.at("max_constraint_error");
          max_energy_increase  = c.scalars.at("max_energy_increase");
        }
      ghost_a                 = phi_n;
      const Integrals initial = integrals(ghost_a);
      if (restart_file.empty())
        {
          V0          = initial.volume;
          A0          = initial.area;
          energy_prev = initial.bending;
          alm_alpha   = V0;
          alm_beta    = A0;
          alm_state   = {{1, 0, 0, 1}};
        }
      Integrals current = initial;
      context.pcout << "Willmore flow: " << dim << "D, degree " << degree
                    << ", " << space->n_elements() << " elements, "
                    << dofs->n_dofs() << " unknowns, h = " << h
                    << ", epsilon = " << epsilon << " (" << epsilon_over_h
                    << " h)" << std::endl
                    << (restart_file.empty() ? "initial" : "restart")
                    << " (t = " << t << ", step " << step
                    << "): bending energy / kappa = " << initial.bending / kappa
                    << ", area A0 = " << A0 << ", volume V0 = " << V0
                    << std::endl;

      if (check_jacobian_first)
        {
          area->set_multiplier(0.3);
          volume.set_multiplier(0.2);
          check_jacobian();
          area->set_multiplier(0);
          volume.set_multiplier(0);
        }

      // Time series: one row per accepted step, flushed at once so that a
      // killed run keeps what it had. A restart keeps the rows up to its
      // checkpoint and continues the file.
      std::ofstream     csv;
      const std::string csv_name
        = context.output_directory + "/time-series.csv";
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          std::vector<std::string> kept;
          if (!restart_file.empty())
            {
              std::ifstream old(csv_name);
              std::string   line;
              while (std::getline(old, line))
                if (kept.empty()
                    || std::stoul(line.substr(0, line.find(','))) <= step)
                  kept.push_back(line);
            }
          csv.open(csv_name);
          if (kept.empty())
            {
              csv << "step,t,dt,newton_iterations,krylov_iterations,"
                     "alm_iterations,rejected_steps,bending_energy,"
                     "total_energy,area_error,volume_error";
              for (unsigned int d = 0; d < dim; ++d)
                csv << ",extent_"
                    << "xyz"[d];
              csv << '\n';
            }
          for (const auto &line : kept)
            csv << line << '\n';
          csv << std::setprecision(12) << std::flush;
        }
      const auto write_vtu = [&](const unsigned int step) {
        TimerOutput::Scope t(*timer, "output");
        ghost_a = phi_n;
        SplineFieldWriter<dim> writer(*dofs, nullptr);
        writer.add_components({"phi"});
        writer.write(ghost_a,
                     context.output_directory,
                     "phi-" + Utilities::int_to_string(step, 5));
      };
      if (vtu_interval > 0 && restart_file.empty())
        write_vtu(0);

      ModifiedALM alm(V0, A0, constraint_tolerance, max_alm_iterations);
      alm.set_state(alm_alpha, alm_beta, alm_state);
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
                                 {"energy_prev", energy_prev},
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
                                 {"max_energy_increase", max_energy_increase}};
        c.write(context.output_directory + "/checkpoint.h5", comm);
      };
      while (t < end_time * (1 - 1e-12) && step < max_steps)
        {
          const double dt         = std::min(controller.dt(), end_time - t);
          unsigned int newton_its = 0, krylov_its = 0, alm_its = 0;
          bool         ok         = true;
          const double alpha_save = alm.alpha(), beta_save = alm.beta();
          const auto   Tinv_save = alm.inverse_jacobian();
          if (constraint_method == "alm")
            {
              const auto solve
                = [&](double al, double be, double &v, double &a) {
                    // (E19): multipliers explicit in V(phi_n), A(phi_n).
                    volume.set_multiplier(M1 * (current.volume - al));
                    area->set_multiplier(M2 * (current.area - be));
                    unsigned int n = 0;
                    if (!newton_step(dt, n, krylov_its))
                      return false;
                    newton_its += n;
                    ghost_a                   = phi;
                    const Integrals candidate = integrals(ghost_a);
                    v                         = candidate.volume;
                    a                         = candidate.area;
                    return true;
                  };
              const auto r = alm.step(solve, current.volume, current.area);
              ok           = r.converged;
              alm_its      = r.iterations;
            }
          else
            {
              if (constraint_method == "penalty")
                {
                  volume.set_multiplier(M1 * (current.volume - V0));
                  area->set_multiplier(M2 * (current.area - A0));
                }
              ok = newton_step(dt, newton_its, krylov_its);
            }

          double error = -1;
          if (ok && step > 0)
            {
              // (N5): local error estimate from three levels.
              const double                  a = 1 + dt_prev / dt;
              TrilinosWrappers::MPI::Vector lte(phi);
              lte *= 1 / a;
              lte.add(-1 / (a - 1), phi_n, 1 / (a * (a - 1)), phi_nm1);
              double sum = 0;
              for (const auto i : owned)
                {
                  const double w = time_step.atol
                                   + time_step.rtol
                                       * std::max(std::abs(phi[i]),
                                                  std::abs(phi[i] + lte[i]));
                  sum += std::pow(lte[i] / w, 2);
                }
              error
                = std::sqrt(Utilities::MPI::sum(sum, comm) / dofs->n_dofs());
            }
          if (!ok || !controller.accept(error))
            {
              ++rejected;
              alm.set_state(alpha_save, beta_save, Tinv_save);
              if (!ok && !controller.reject_failure())
                {
                  write_checkpoint();
                  throw std::runtime_error(
                    "Willmore flow: the step failed (Newton or ALM did not "
                    "converge) with dt at its minimum at t = "
                    + std::to_string(t)
                    + "; the time series up to that "
                      "point is in "
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
          ghost_a              = phi_n;
          current              = integrals(ghost_a);
          const double energy  = current.bending;
          max_constraint_error = std::max({max_constraint_error,
                                           std::abs(current.area / A0 - 1),
                                           std::abs(current.volume / V0 - 1)});
          max_energy_increase
            = std::max(max_energy_increase,
                       (energy - energy_prev) / std::abs(energy_prev));
          const std::vector<double> natural_phi = natural_coefficients(phi_n);
          std::vector<double>       extents(dim);
          for (unsigned int d = 0; d < dim; ++d)
            extents[d] = extent(natural_phi, d);
          if (csv.is_open())
            {
              csv << step << ',' << t << ',' << dt << ',' << newton_its << ','
                  << krylov_its << ',' << alm_its << ',' << rejected << ','
                  << energy / kappa << ',' << energy / kappa << ','
                  << current.area / A0 - 1 << ',' << current.volume / V0 - 1;
              for (const double e : extents)
                csv << ',' << e;
              csv << std::endl;
            }
          context.pcout << "step " << step << " t=" << t << " dt=" << dt
                        << " newton=" << newton_its;
          if (context.print_details)
            context.pcout << " krylov=" << krylov_its;
          context.pcout << " alm=" << alm_its << " E_B/kappa=" << energy / kappa
                        << " area_error=" << current.area / A0 - 1
                        << " volume_error=" << current.volume / V0 - 1
                        << std::endl;
          rejected = 0;
          if (vtu_interval > 0 && step % vtu_interval == 0)
            write_vtu(step);
          if (checkpoint_interval > 0 && step % checkpoint_interval == 0)
            write_checkpoint();
          const bool saturated = !time_step.adaptive
                                 || controller.dt() >= time_step.max_dt * 0.999;
          if (saturated
              && std::abs(energy - energy_prev)
                   <= stationarity_tolerance * std::abs(energy))
            {
              context.pcout << "stationary: relative energy change "
                            << std::abs(energy - energy_prev) / std::abs(energy)
                            << " over the last step" << std::endl;
              break;
            }
          energy_prev = energy;
        }
      if (vtu_interval > 0 && step % vtu_interval != 0)
        write_vtu(step);
      write_checkpoint();
      context.pcout << "final: t=" << t << " steps=" << step
                    << " E_B/kappa=" << current.bending / kappa
                    << " area_error=" << current.area / A0 - 1
                    << " volume_error=" << current.volume / V0 - 1;
      const std::vector<double> natural_phi = natural_coefficients(phi_n);
      for (unsigned int d = 0; d < dim; ++d)
        context.pcout << " extent_"
                      << "xyz"[d] << "=" << extent(natural_phi, d);
      context.pcout << std::endl;
      if (step > 0)
        context.pcout
          << "largest |A/A0-1|, |V/V0-1| over the accepted steps: "
          << max_constraint_error
          << (constraint_method == "alm" ?
                (max_constraint_error <= constraint_tolerance ?
                   " (within the ALM tolerance)" :
                   " (ABOVE the ALM tolerance)") :
                "")
          << std::endl
          << "largest relative energy increase between accepted steps: "
          << std::max(0., max_energy_increase) << std::endl;
    }
  } // namespace


  StudyDescription
  willmore_flow_description()
  {
    return {
      "willmore-flow",
      "Spec Part E without electric terms: constrained Willmore/Helfrich "
      "flow of a vesicle, generalized-alpha, Newton, modified ALM or "
      "penalty, adaptive steps.",
      [](ParameterHandler &prm) {
        prm.enter_subsection(section);
        BoxSpaceParameters::declare(prm, "-2", "2", "32");
        // GMRES with ILU(1): on the 2D ellipse (13.8k unknowns) 7-8
        // iterations per Newton step at small dt and 5x faster than KLU.
        LinearSolverParameters::declare(prm, "gmres-ilu");
        StepSizeController::Parameters::declare(prm, "1e-4", "0.1");
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
                          "smallest element size (spec: 2).");
        prm.declare_entry("Initial shape",
                          "sphere",
                          Patterns::Selection("sphere|ellipsoid"),
                          "sphere (circle in 2D) or ellipsoid (spheroid, "
                          "ellipse) with the tanh profile (E3).");
        prm.declare_entry("Center",
                          "0,0",
                          Patterns::Anything(),
                          "Centre of the initial shape (one per direction).");
        prm.declare_entry("Semi-axes",
                          "1",
                          Patterns::Anything(),
                          "Radius, or semi-axes per direction.");
        prm.declare_entry("Constraint method",
                          "alm",
                          Patterns::Selection("alm|penalty|none"),
                          "alm: modified augmented Lagrangian (spec 3.8); "
                          "penalty: fixed targets V0, A0 with M1, M2; none.");
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
        prm.declare_entry("End time", "1", Patterns::Double(0), "End time.");
        prm.declare_entry("Max steps",
                          "100000",
                          Patterns::Integer(1),
                          "Upper bound on accepted steps.");
        prm.declare_entry("Stationarity tolerance",
                          "1e-6",
                          Patterns::Double(0),
                          "Stop when the relative change of the energy over "
                          "one step falls below this, once dt has reached "
                          "Max dt.");
        prm.declare_entry("Max Newton iterations",
                          "12",
                          Patterns::Integer(1),
                          "Newton iterations before the step is cut.");
        prm.declare_entry("Newton relative tolerance",
                          "1e-8",
                          Patterns::Double(0),
                          "Residual reduction of Newton.");
        prm.declare_entry("Newton absolute tolerance",
                          "1e-10",
                          Patterns::Double(0),
                          "Absolute residual norm of Newton.");
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
