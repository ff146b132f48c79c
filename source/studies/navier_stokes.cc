// Study "navier-stokes": incompressible flow on a box by RBVMS on spline
// spaces (spec Part H, (H14) without vesicles, (H18)-(H21)), with strong,
// weak (Bazilevs-Hughes) and stress-free boundaries and periodic
// directions; generalized-alpha in time, steady states by pseudo-time
// stepping; errors against an exact solution over refinement levels
// (convergence.csv); time series of kinetic energy, divergence and
// iterations; VTU of velocity, pressure and vorticity.

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <vesicle_iga/assembly/assembler.h>
#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/io/checkpoint.h>
#include <vesicle_iga/io/spline_output.h>
#include <vesicle_iga/io/time_series.h>
#include <vesicle_iga/parallel/natural_numbering.h>
#include <vesicle_iga/postprocess/convergence_study_table.h>
#include <vesicle_iga/postprocess/line_sample.h>
#include <vesicle_iga/solvers/navier_stokes_solver.h>
#include <vesicle_iga/spline/box_space_parameters.h>
#include <vesicle_iga/studies/convergence_parameters.h>
#include <vesicle_iga/studies/study.h>

#include <cmath>
#include <iomanip>

namespace vesicle_iga
{
  namespace
  {
    const char        *section        = "Navier-Stokes";
    const unsigned int n_boundaries   = 8;
    const unsigned int n_line_samples = 2;

    /// A vector-valued formula of the .prm ("expr_1; expr_2[; expr_3]" in
    /// x, y, z and t, constants pi and Re) with @p extra trailing zero
    /// components; errors name the parameter.
    template <int dim>
    std::shared_ptr<FunctionParser<dim>>
    parse_function(const std::string &text,
                   const unsigned int n_components,
                   const unsigned int extra,
                   const double       reynolds_number,
                   const std::string &parameter)
    {
      auto parts = Utilities::split_string_list(text, ';');
      check_input(parts.size() == n_components,
                  parameter,
                  text,
                  std::to_string(n_components)
                    + " expression(s) separated by ';'");
      for (unsigned int i = 0; i < extra; ++i)
        parts.push_back("0");
      // Derivatives (H1 errors) by fourth-order differences with h = 1e-4:
      // truncation and round-off both near 1e-12 for the studies' data.
      auto f
        = std::make_shared<FunctionParser<dim>>(n_components + extra, 0., 1e-4);
      f->set_formula(AutoDerivativeFunction<dim>::FourthOrder);
      const std::string variables = dim == 2 ? "x,y,t" : "x,y,z,t";
      try
        {
          f->initialize(variables,
                        parts,
                        {{"pi", M_PI}, {"Re", reynolds_number}},
                        true);
          // Evaluate once so that unknown symbols are reported here.
          Vector<double> values(n_components + extra);
          f->vector_value(Point<dim>(), values);
        }
      catch (...)
        {
          check_input(false,
                      parameter,
                      text,
                      "expressions in " + variables
                        + " (muparser syntax; constants pi, Re)");
        }
      return f;
    }


    template <int dim>
    class NavierStokesStudy : public Study
    {
    public:
      NavierStokesStudy(ParameterHandler &prm, RunContext &context);
      void
      run() override;

    private:
      /// One run at degree p and refinement level r; returns the errors
      /// (velocity L2, H1, pressure L2) if an exact solution is given.
      std::vector<double>
      run_level(const unsigned int p, const unsigned int r, TimerOutput &timer);

      RunContext            &context;
      BoxSpaceParameters     box;
      ConvergenceParameters  convergence;
      LinearSolverParameters linear_solver;
      FlowNewtonParameters   newton;

      double      reynolds_number;
      std::string viscosity_text, force_text, initial_text;
      std::string exact_velocity_text, exact_pressure_text;
      struct BoundaryEntry
      {
        std::string type, where, velocity;
      };
      std::vector<BoundaryEntry> boundaries;
      std::vector<LineSample>    line_samples;
      double                     weak_penalty;
      bool                       weak_inflow;
      std::string                pressure_level;
      double       dt0, dt_max, dt_growth, end_time, steady_tolerance, rho_inf;
      unsigned int max_steps, quadrature_points, vtu_interval;
      unsigned int checkpoint_interval;
      std::string  restart_file;
      bool         pressure_at_end;
    };


    template <int dim>
    NavierStokesStudy<dim>::NavierStokesStudy(ParameterHandler &prm,
                                              RunContext       &context)
      : context(context)
    {
      prm.enter_subsection(section);
      box.parse(prm, dim);
      convergence.parse(prm, 0);
      linear_solver.parse_flow(prm);
      reynolds_number     = prm.get_double("Reynolds number");
      viscosity_text      = prm.get("Viscosity");
      force_text          = prm.get("Body force");
      initial_text        = prm.get("Initial velocity");
      exact_velocity_text = prm.get("Exact velocity");
      exact_pressure_text = prm.get("Exact pressure");
      weak_penalty        = prm.get_double("Weak penalty constant");
      weak_inflow         = prm.get_bool("Weak inflow term");
      pressure_level      = prm.get("Pressure level");
      quadrature_points   = prm.get_integer("Quadrature points");
      for (unsigned int b = 1; b <= n_boundaries; ++b)
        {
          prm.enter_subsection("Boundary " + std::to_string(b));
          boundaries.push_back(
            {prm.get("Type"), prm.get("Where"), prm.get("Velocity")});
          prm.leave_subsection();
        }
      std::vector<std::string> field_names{"u", "v"};
      if (dim == 3)
        field_names.push_back("w");
      field_names.push_back("p");
      for (unsigned int l = 1; l <= n_line_samples; ++l)
        {
          const std::string name = "Line sample " + std::to_string(l);
          prm.enter_subsection(name);
          LineSample sample;
          sample.parse(prm,
                       std::string(section) + "/" + name + "/",
                       field_names,
                       dim);
          if (!sample.name.empty())
            line_samples.push_back(sample);
          prm.leave_subsection();
        }
      prm.enter_subsection("Time stepping");
      dt0                 = prm.get_double("Time step");
      dt_max              = prm.get_double("Max time step");
      dt_growth           = prm.get_double("Time step growth");
      end_time            = prm.get_double("End time");
      max_steps           = prm.get_integer("Max steps");
      steady_tolerance    = prm.get_double("Steady tolerance");
      rho_inf             = prm.get_double("rho_inf");
      pressure_at_end     = prm.get("Pressure time level") == "t_n+1";
      vtu_interval        = prm.get_integer("VTU interval");
      checkpoint_interval = prm.get_integer("Checkpoint interval");
      restart_file        = prm.get("Restart from");
      prm.leave_subsection();
      prm.enter_subsection("Newton");
      newton.relative_tolerance = prm.get_double("Relative tolerance");
      newton.absolute_tolerance = prm.get_double("Absolute tolerance");
      newton.max_iterations     = prm.get_integer("Max iterations");
      prm.leave_subsection();
      prm.leave_subsection();

      // Report bad input before any work.
      const std::string prefix = std::string(section) + "/";
      check_input(reynolds_number > 0,
                  prefix + "Reynolds number",
                  std::to_string(reynolds_number),
                  "> 0");
      check_input(dt0 > 0 && dt_max >= dt0,
                  prefix + "Time stepping/Time step",
                  std::to_string(dt0),
                  "> 0 and <= 'Max time step'");
      check_input(dt_growth >= 1,
                  prefix + "Time stepping/Time step growth",
                  std::to_string(dt_growth),
                  ">= 1");
      check_input(rho_inf >= 0 && rho_inf <= 1,
                  prefix + "Time stepping/rho_inf",
                  std::to_string(rho_inf),
                  "in [0, 1]");
      check_input(restart_file.empty()
                    || (convergence.degrees.size() == 1
                        && convergence.refinements == 0),
                  prefix + "Time stepping/Restart from",
                  restart_file,
                  "empty for a convergence study (several degrees or "
                  "refinements); a restart continues a single run");
      for (const unsigned int p : convergence.degrees)
        box.make_space<dim>(p, convergence.continuity);
      for (unsigned int b = 0; b < n_boundaries; ++b)
        {
          const auto       &e    = boundaries[b];
          const std::string name = prefix + "Boundary " + std::to_string(b + 1);
          BoundarySelection<dim>(e.where, name + "/Where");
          if (e.type == "strong" || e.type == "weak")
            parse_function<dim>(
              e.velocity, dim, 1, reynolds_number, name + "/Velocity");
        }
      parse_function<dim>(
        viscosity_text, 1, 0, reynolds_number, prefix + "Viscosity");
      parse_function<dim>(
        force_text, dim, 0, reynolds_number, prefix + "Body force");
      parse_function<dim>(
        initial_text, dim, 1, reynolds_number, prefix + "Initial velocity");
      if (!exact_velocity_text.empty())
        parse_function<dim>(exact_velocity_text,
                            dim,
                            0,
                            reynolds_number,
                            prefix + "Exact velocity");
      if (!exact_pressure_text.empty())
        parse_function<dim>(exact_pressure_text,
                            1,
                            0,
                            reynolds_number,
                            prefix + "Exact pressure");
    }


    template <int dim>
    std::vector<double>
    NavierStokesStudy<dim>::run_level(const unsigned int p,
                                      const unsigned int r,
                                      TimerOutput       &timer)
    {
      const std::string      prefix = std::string(section) + "/";
      const SplineSpace<dim> space
        = box.make_space<dim>(p, convergence.continuity).h_refined(r);

      const auto viscosity = parse_function<dim>(
        viscosity_text, 1, 0, reynolds_number, prefix + "Viscosity");
      const auto force = parse_function<dim>(
        force_text, dim, 0, reynolds_number, prefix + "Body force");
      FlowCoefficients<dim> coefficients;
      coefficients.reynolds_number           = reynolds_number;
      coefficients.viscosity                 = viscosity.get();
      coefficients.body_force                = force.get();
      coefficients.inverse_estimate_constant = 6. * std::pow(p, 4);

      std::vector<VelocityCondition<dim>> conditions;
      bool                                level_fixed = false;
      std::array<bool, 2 * dim>           face_touched{};
      for (unsigned int b = 0; b < n_boundaries; ++b)
        {
          const auto       &e    = boundaries[b];
          const std::string name = prefix + "Boundary " + std::to_string(b + 1);
          const BoundarySelection<dim> where(e.where, name + "/Where");
          for (unsigned int f = 0; f < 2 * dim; ++f)
            face_touched[f] = face_touched[f] || where.touches_face(f);
          if (e.type == "outflow")
            level_fixed = true;
          else if (e.type == "strong" || e.type == "weak")
            conditions.push_back(
              {where,
               parse_function<dim>(
                 e.velocity, dim, 1, reynolds_number, name + "/Velocity"),
               e.type == "weak"});
        }
      // A face of an open direction that no condition names is stress-free.
      for (unsigned int f = 0; f < 2 * dim; ++f)
        if (!box.periodic[f / 2] && !face_touched[f])
          level_fixed = true;
      const bool fix_mean = pressure_level == "mean zero"
                            || (pressure_level == "auto" && !level_fixed);

      const unsigned int n_q
        = quadrature_points > 0 ? quadrature_points : p + 2;
      NavierStokesSolver<dim> solver(context.communicator,
                                     space,
                                     coefficients,
                                     conditions,
                                     weak_penalty,
                                     weak_inflow,
                                     fix_mean,
                                     QGauss<1>(n_q),
                                     linear_solver,
                                     newton,
                                     rho_inf,
                                     pressure_at_end,
                                     timer);
      const auto              initial = parse_function<dim>(
        initial_text, dim, 1, reynolds_number, prefix + "Initial velocity");
      solver.set_initial_state(*initial, 0.);
      double       dt   = dt0;
      unsigned int step = 0;
      if (!restart_file.empty())
        {
          const Checkpoint c = Checkpoint::read(restart_file,
                                                context.communicator);
          check_input(c.scalar("n_basis") == space.n_basis(),
                      prefix + "Time stepping/Restart from",
                      restart_file,
                      "a checkpoint of the same mesh and degree (it has "
                        + std::to_string(int(c.scalar("n_basis")))
                        + " basis functions, this run "
                        + std::to_string(space.n_basis()) + ")");
          TrilinosWrappers::MPI::Vector solution(solver.owned_solution()),
            rate(solver.owned_rate());
          scatter_natural(solver.dofs(), c.vector("solution"), solution);
          scatter_natural(solver.dofs(), c.vector("rate"), rate);
          solver.set_state(solution, rate, c.scalar("t"));
          dt   = c.scalar("dt");
          step = static_cast<unsigned int>(c.scalar("step"));
          context.pcout << "restart from " << restart_file << ": step " << step
                        << ", t = " << solver.time() << ", dt = " << dt
                        << std::endl;
        }
      const auto write_checkpoint = [&]() {
        TimerOutput::Scope scope(timer, "output");
        Checkpoint         c;
        c.vectors["solution"]
          = gather_natural(solver.dofs(), solver.owned_solution());
        c.vectors["rate"] = gather_natural(solver.dofs(), solver.owned_rate());
        c.scalars         = {{"t", solver.time()},
                             {"dt", dt},
                             {"step", double(step)},
                             {"n_basis", double(space.n_basis())}};
        c.write(context.output_directory + "/checkpoint.h5",
                context.communicator);
      };

      const std::string tag
        = "p" + std::to_string(p) + "-level" + std::to_string(r);
      const bool single_run
        = convergence.degrees.size() == 1 && convergence.refinements == 0;
      TimeSeriesWriter series(context.output_directory + "/time-series"
                                + (single_run ? "" : "-" + tag) + ".csv",
                              {"step",
                               "t",
                               "dt",
                               "newton_iterations",
                               "krylov_iterations",
                               "kinetic_energy",
                               "divergence_l2",
                               "relative_change"},
                              context.communicator,
                              restart_file.empty() ? -1 : long(step));
      context.pcout
        << "Navier-Stokes (RBVMS): " << dim << "D, degree " << p << ", C^"
        << (convergence.continuity < 0 ? int(p) - 1 : convergence.continuity)
        << ", " << space.n_elements() << " elements, " << solver.dofs().n_dofs()
        << " unknowns, Re = " << reynolds_number << ", pressure level "
        << (fix_mean ? "zero mean" : "set by the boundary") << std::endl;

      SplineFieldWriter<dim> writer(solver.dofs(), nullptr);
      {
        std::vector<std::string> names;
        for (unsigned int a = 0; a < dim; ++a)
          names.push_back(std::string("u_") + "xyz"[a]);
        names.push_back("p");
        writer.add_components(names);
        writer.add_quantity(
          "vorticity",
          [](const SplineCellValues<dim>            &v,
             const unsigned int                      q,
             const std::vector<std::vector<double>> &c) {
            // 2D: the scalar vorticity; 3D: its magnitude.
            const Tensor<1, dim> gu = v.gradient(c[0], q),
                                 gv = v.gradient(c[1], q);
            if (dim == 2)
              return gv[0] - gu[1];
            const Tensor<1, dim> gw = v.gradient(c[2], q);
            return std::sqrt(std::pow(gw[1] - gv[2], 2)
                             + std::pow(gu[2] - gw[0], 2)
                             + std::pow(gv[0] - gu[1], 2));
          },
          1);
      }
      const auto write_vtu = [&](const unsigned int step) {
        TimerOutput::Scope scope(timer, "output");
        writer.write(solver.solution(),
                     context.output_directory,
                     "flow-" + (single_run ? "" : tag + "-")
                       + Utilities::int_to_string(step, 5));
      };
      if (vtu_interval > 0 && convergence.write_vtu && restart_file.empty())
        write_vtu(0);

      bool steady = false;
      while (solver.time() < end_time * (1 - 1e-12) && step < max_steps)
        {
          double step_dt = std::min(dt, end_time - solver.time());
          TrilinosWrappers::MPI::Vector previous(solver.owned_solution());
          FlowStepResult                result = solver.advance(step_dt);
          // A step whose Newton iteration fails is repeated with dt / 4
          // (the state is unchanged), as the phase-field controller does.
          unsigned int rejected = 0;
          while (!result.converged && rejected < 10)
            {
              ++rejected;
              dt      = step_dt / 4;
              step_dt = dt;
              context.pcout << "  Newton did not converge (residual "
                            << result.residual
                            << "): retry with dt = " << step_dt << std::endl;
              result = solver.advance(step_dt);
            }
          if (!result.converged && single_run)
            write_checkpoint();
          check_input(result.converged,
                      prefix + "Time stepping/Time step",
                      std::to_string(dt0),
                      "a step the Newton iteration can take: the step from "
                      "t = "
                        + std::to_string(solver.time())
                        + " did not converge even with dt = "
                        + std::to_string(step_dt)
                        + "; the run stops here (the time series so far is "
                          "kept, and the last accepted state in "
                          "checkpoint.h5)");
          ++step;
          previous.add(-1., solver.owned_solution());
          const double change
            = previous.l2_norm()
              / std::max(1e-300, solver.owned_solution().l2_norm());
          const auto [energy, divergence]
            = solver.kinetic_energy_and_divergence();
          series.add_row({double(step),
                          solver.time(),
                          step_dt,
                          double(result.newton_iterations),
                          double(result.krylov_iterations),
                          energy,
                          divergence,
                          change});
          context.pcout << "step " << step << " t=" << solver.time()
                        << " dt=" << step_dt
                        << " newton=" << result.newton_iterations;
          if (context.print_details)
            context.pcout << " krylov=" << result.krylov_iterations;
          context.pcout << " kinetic_energy=" << energy
                        << " |div u|=" << divergence << " change=" << change
                        << std::endl;
          if (vtu_interval > 0 && convergence.write_vtu
              && step % vtu_interval == 0)
            write_vtu(step);
          if (steady_tolerance > 0 && change < steady_tolerance)
            steady = true;
          else
            dt = std::min(dt * dt_growth, dt_max);
          if (single_run && checkpoint_interval > 0
              && step % checkpoint_interval == 0)
            write_checkpoint();
          if (steady)
            break;
        }
      if (single_run)
        write_checkpoint();
      if (steady_tolerance > 0)
        context.pcout << (steady ? "steady: relative change below " :
                                   "NOT steady: relative change above ")
                      << steady_tolerance << " at step " << step
                      << ", t = " << solver.time() << std::endl;
      if (convergence.write_vtu && (vtu_interval == 0 || step % vtu_interval))
        write_vtu(step);

      if (!line_samples.empty())
        {
          const std::vector<double> natural
            = gather_natural(solver.dofs(), solver.solution());
          for (const auto &sample : line_samples)
            {
              LineSample named = sample;
              if (!single_run)
                named.name += "-" + tag;
              const auto [deviation, integral] = write_line_sample(
                named,
                space,
                natural,
                dim + 1,
                context.output_directory,
                Utilities::MPI::this_mpi_process(context.communicator) == 0);
              if (sample.print_integral)
                context.pcout << named.name << ".csv: integral of "
                              << sample.field_name
                              << " along the line: " << integral << std::endl;
              if (!sample.reference.empty())
                context.pcout << named.name << ".csv: largest deviation of "
                              << sample.field_name << " from "
                              << sample.reference << ": " << deviation
                              << std::endl;
            }
        }

      if (exact_velocity_text.empty())
        return {};
      auto exact_u = parse_function<dim>(exact_velocity_text,
                                         dim,
                                         0,
                                         reynolds_number,
                                         prefix + "Exact velocity");
      exact_u->set_time(solver.time());
      std::shared_ptr<FunctionParser<dim>> exact_p;
      if (!exact_pressure_text.empty())
        {
          exact_p = parse_function<dim>(exact_pressure_text,
                                        1,
                                        0,
                                        reynolds_number,
                                        prefix + "Exact pressure");
          exact_p->set_time(solver.time());
        }
      // The pressure is compared up to a constant: both sides with zero mean.
      const QGauss<1> error_quadrature(p + 3
                                       + convergence.extra_quadrature_points);
      const auto      means = integrate_field<dim>(
        solver.dofs(),
        nullptr,
        error_quadrature,
        0,
        solver.solution(),
        3,
        [&](const SplineCellValues<dim>            &v,
            const unsigned int                      q,
            const std::vector<std::vector<double>> &c,
            std::vector<double>                    &s) {
          s[0] += v.value(c[dim], q) * v.JxW(q);
          s[1] += (exact_p ? exact_p->value(v.quadrature_point(q)) : 0.)
                  * v.JxW(q);
          s[2] += v.JxW(q);
        });
      const double shift  = (means[0] - means[1]) / means[2];
      const auto   errors = integrate_field<dim>(
        solver.dofs(),
        nullptr,
        error_quadrature,
        1,
        solver.solution(),
        3,
        [&](const SplineCellValues<dim>            &v,
            const unsigned int                      q,
            const std::vector<std::vector<double>> &c,
            std::vector<double>                    &s) {
          const Point<dim> &x = v.quadrature_point(q);
          for (unsigned int a = 0; a < dim; ++a)
            {
              s[0] += std::pow(v.value(c[a], q) - exact_u->value(x, a), 2)
                      * v.JxW(q);
              s[1]
                += (v.gradient(c[a], q) - exact_u->gradient(x, a)).norm_square()
                   * v.JxW(q);
            }
          if (exact_p)
            s[2] += std::pow(v.value(c[dim], q) - shift - exact_p->value(x), 2)
                    * v.JxW(q);
        });
      return {std::sqrt(errors[0]), std::sqrt(errors[1]), std::sqrt(errors[2])};
    }


    template <int dim>
    void
    NavierStokesStudy<dim>::run()
    {
      TimerOutput           timer(context.communicator,
                        context.pcout,
                        context.print_details ? TimerOutput::summary :
                                                          TimerOutput::never,
                        TimerOutput::wall_times);
      ConvergenceStudyTable table(dim, {"u_L2", "u_H1", "p_L2"});
      for (const unsigned int p : convergence.degrees)
        for (unsigned int r = 0; r <= convergence.refinements; ++r)
          {
            const auto errors = run_level(p, r, timer);
            if (errors.empty())
              continue;
            const SplineSpace<dim> space
              = box.make_space<dim>(p, convergence.continuity).h_refined(r);
            double h = 0;
            for (unsigned int d = 0; d < dim; ++d)
              h = std::max(h,
                           (box.upper[d] - box.lower[d])
                             / space.knot_vector(d).n_elements());
            table.add_row(
              p, space.n_elements(), space.n_basis() * (dim + 1), h, errors);
          }
      if (exact_velocity_text.empty())
        return;
      table.report(context.pcout,
                   context.communicator,
                   context.output_directory);
    }
  } // namespace


  StudyDescription
  navier_stokes_description()
  {
    return {
      "navier-stokes",
      "Incompressible Navier-Stokes by RBVMS on spline spaces (spec Part H "
      "flow solver): strong, weak and stress-free boundaries, periodic "
      "directions, generalized-alpha, pseudo-time steady states, errors "
      "against an exact solution.",
      [](ParameterHandler &prm) {
        prm.enter_subsection(section);
        BoxSpaceParameters::declare(prm, "0", "1", "8");
        ConvergenceParameters::declare(prm, "2", "0");
        LinearSolverParameters::declare_flow(prm, "fgmres-block", "1e-10");
        prm.declare_entry("Reynolds number",
                          "100",
                          Patterns::Double(),
                          "Re of (H4): the viscous stress is "
                          "(2 mu* / Re) D(u).");
        prm.declare_entry("Viscosity",
                          "1",
                          Patterns::Anything(),
                          "Viscosity field mu*(x, y[, z], t) relative to the "
                          "outer fluid (spec 4.5), a formula.");
        prm.declare_entry("Body force",
                          "0; 0",
                          Patterns::Anything(),
                          "Body force per unit mass, dim formulas separated "
                          "by ';' (in x, y[, z], t; constants pi, Re).");
        prm.declare_entry("Initial velocity",
                          "0; 0",
                          Patterns::Anything(),
                          "u(x, 0), dim formulas separated by ';'.");
        prm.declare_entry("Exact velocity",
                          "",
                          Patterns::Anything(),
                          "If given (dim formulas): L2 and H1 velocity errors "
                          "at the final time, per degree and level, in "
                          "convergence.csv.");
        prm.declare_entry("Exact pressure",
                          "",
                          Patterns::Anything(),
                          "If given: L2 error of the pressure, both sides "
                          "shifted to zero mean.");
        prm.declare_entry("Weak penalty constant",
                          "-1",
                          Patterns::Double(),
                          "C_B of tau_B = C_B (mu* / Re) / h_n (H21); <= 0: "
                          "5 (p + 1).");
        prm.declare_entry("Weak inflow term",
                          "true",
                          Patterns::Bool(),
                          "Include -(w, (u.m)_- (u - u_b)) on the inflow "
                          "part of weakly imposed boundaries (H20).");
        prm.declare_entry(
          "Pressure level",
          "auto",
          Patterns::Selection("auto|mean zero|free"),
          "How the pressure constant is fixed: 'mean zero' pins one control "
          "value and reports the zero-mean pressure; 'free' leaves it to "
          "a stress-free boundary; 'auto': mean zero unless some boundary is "
          "stress-free (type outflow, or a face no condition names).");
        prm.declare_entry("Quadrature points",
                          "0",
                          Patterns::Integer(0),
                          "Gauss points per direction; 0: p + 2 (spec 4.9 "
                          "uses 6).");
        for (unsigned int b = 1; b <= n_boundaries; ++b)
          {
            prm.enter_subsection("Boundary " + std::to_string(b));
            prm.declare_entry(
              "Type",
              "none",
              Patterns::Selection("none|strong|weak|outflow"),
              "strong: u = Velocity through the boundary control values "
              "(spec 4.10, also on parts of a side); weak: Bazilevs-Hughes "
              "(H20)-(H21); outflow: stress-free (natural). Faces that no "
              "boundary names are stress-free.");
            prm.declare_entry(
              "Where",
              "",
              Patterns::Anything(),
              "Boundary pieces: e.g. 'x-min', 'y-max{x:0.5:1}', 'all'.");
            prm.declare_entry("Velocity",
                              "0; 0",
                              Patterns::Anything(),
                              "u_b, dim formulas separated by ';' in x, y[, "
                              "z], t (e.g. '8*y-2*y^2; 0').");
            prm.leave_subsection();
          }
        for (unsigned int l = 1; l <= n_line_samples; ++l)
          {
            prm.enter_subsection("Line sample " + std::to_string(l));
            LineSample::declare(prm, "u|v|w|p");
            prm.leave_subsection();
          }
        prm.enter_subsection("Time stepping");
        prm.declare_entry("Time step", "0.1", Patterns::Double(0), "First dt.");
        prm.declare_entry("Max time step",
                          "0.1",
                          Patterns::Double(0),
                          "Upper bound of dt.");
        prm.declare_entry("Time step growth",
                          "1",
                          Patterns::Double(),
                          "dt is multiplied by this after every step (>= 1; "
                          "pseudo-time stepping to a steady state).");
        prm.declare_entry("End time", "1", Patterns::Double(0), "Final time.");
        prm.declare_entry("Max steps",
                          "100000",
                          Patterns::Integer(1),
                          "Stop after this many steps.");
        prm.declare_entry("Steady tolerance",
                          "0",
                          Patterns::Double(0),
                          "> 0: stop when |U_{n+1} - U_n| / |U_{n+1}| falls "
                          "below this (steady state).");
        prm.declare_entry("rho_inf",
                          "0.5",
                          Patterns::Double(0, 1),
                          "Spectral radius at infinity of generalized-alpha "
                          "(N3).");
        prm.declare_entry("Pressure time level",
                          "t_n+1",
                          Patterns::Selection("t_n+1|t_n+alpha_f"),
                          "Where the pressure is evaluated (spec 4.9).");
        prm.declare_entry("VTU interval",
                          "0",
                          Patterns::Integer(0),
                          "Write velocity, pressure and vorticity every so "
                          "many steps (0: final state only; 'Write VTU' "
                          "switches output off).");
        prm.declare_entry("Checkpoint interval",
                          "10",
                          Patterns::Integer(0),
                          "Write <Output directory>/checkpoint.h5 (velocity, "
                          "pressure, their rates, t, dt, step) every N steps "
                          "of a single run (0: only at the end and when a "
                          "step fails).");
        prm.declare_entry("Restart from",
                          "",
                          Patterns::Anything(),
                          "A checkpoint.h5 of a flow run with the same mesh "
                          "and degree (any number of ranks) to continue "
                          "from; time-series.csv keeps its rows up to the "
                          "checkpoint's step. Empty: start from 'Initial "
                          "velocity'.");
        prm.leave_subsection();
        prm.enter_subsection("Newton");
        prm.declare_entry("Relative tolerance",
                          "1e-8",
                          Patterns::Double(0),
                          "");
        prm.declare_entry("Absolute tolerance",
                          "1e-10",
                          Patterns::Double(0),
                          "Newton stops when |R| <= max(rtol |R_0|, atol).");
        prm.declare_entry("Max iterations", "20", Patterns::Integer(1), "");
        prm.leave_subsection();
        prm.leave_subsection();
      },
      [](ParameterHandler &prm, RunContext &context) -> std::unique_ptr<Study> {
        if (context.dimension == 2)
          return std::make_unique<NavierStokesStudy<2>>(prm, context);
        return std::make_unique<NavierStokesStudy<3>>(prm, context);
      }};
  }
} // namespace vesicle_iga
