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

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/fields/natural_numbering.h>
#include <vesicle_iga/io/spline_output.h>
#include <vesicle_iga/models/incompressible_flow.h>
#include <vesicle_iga/postprocess/convergence_study_table.h>
#include <vesicle_iga/postprocess/field_integrals.h>
#include <vesicle_iga/postprocess/line_sample.h>
#include <vesicle_iga/spline/box_space_parameters.h>
#include <vesicle_iga/studies/convergence_parameters.h>
#include <vesicle_iga/studies/flow_study_parts.h>
#include <vesicle_iga/studies/study.h>

#include <cmath>
#include <iomanip>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    const char        *section        = "Navier-Stokes";
    const unsigned int n_boundaries   = 8;
    const unsigned int n_line_samples = 2;

    /// A viscosity or body force written as numbers needs no formula.
    bool
    is_constant(const std::string &text, std::vector<double> &values)
    {
      values.clear();
      try
        {
          for (const auto &part : Utilities::split_string_list(text, ';'))
            {
              std::size_t  used = 0;
              const double v    = std::stod(part, &used);
              if (used != part.size())
                return false;
              values.push_back(v);
            }
        }
      catch (...)
        {
          return false;
        }
      return true;
    }


    /// Kinetic energy, |div u| and the relative change of the state per
    /// step; the steady state (change below 'Steady tolerance').
    template <int dim>
    class FlowMonitor : public Monitor, public StationarityCriterion
    {
    public:
      FlowMonitor(const IncompressibleFlow<dim> &flow, const double tolerance)
        : flow(flow)
        , tolerance(tolerance)
      {}
      std::vector<std::string>
      columns() const override
      {
        return {"kinetic_energy", "divergence_l2", "relative_change"};
      }
      void
      measure(const StepInfo &,
              std::vector<double> &row,
              std::ostream        &progress) override
      {
        TrilinosWrappers::MPI::Vector difference(flow.previous_solution());
        difference.add(-1., flow.owned_solution());
        change = difference.l2_norm()
                 / std::max(1e-300, flow.owned_solution().l2_norm());
        const auto [energy, divergence] = flow.kinetic_energy_and_divergence();
        row.insert(row.end(), {energy, divergence, change});
        progress << " kinetic_energy=" << energy << " |div u|=" << divergence
                 << " change=" << change;
      }
      bool
      stationary(const StepInfo &) override
      {
        return tolerance > 0 && change < tolerance;
      }
      std::string
      message(const StepInfo &info) const override
      {
        std::ostringstream m;
        m << "steady: relative change below " << tolerance << " at step "
          << info.step << ", t = " << info.time;
        return m.str();
      }
      std::string
      not_reached_message(const StepInfo &info) const override
      {
        if (tolerance <= 0)
          return "";
        std::ostringstream m;
        m << "NOT steady: relative change above " << tolerance << " at step "
          << info.step << ", t = " << info.time;
        return m.str();
      }

    private:
      const IncompressibleFlow<dim> &flow;
      const double                   tolerance;
      double                         change = 0;
    };


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
      FlowCoefficients<dim>
      coefficients(const unsigned int p) const;
      std::vector<VelocityCondition<dim>>
      conditions(bool &level_fixed) const;
      void
      write_line_samples(const IncompressibleFlow<dim> &flow,
                         const SplineSpace<dim>        &space,
                         const std::string             &tag,
                         const bool                     single_run) const;
      std::vector<double>
      errors(const IncompressibleFlow<dim> &flow, const unsigned int p) const;

      RunContext                  &context;
      BoxSpaceParameters           box;
      ConvergenceParameters        convergence;
      IncompressibleFlowParameters flow_parameters;
      TimeLoop::Parameters         loop_parameters;

      double                  reynolds_number;
      std::string             viscosity_text, force_text, initial_text;
      std::string             exact_velocity_text, exact_pressure_text;
      FlowBoundaryParameters  boundaries;
      std::vector<LineSample> line_samples;
      double                  steady_tolerance;
      unsigned int            quadrature_points;
    };


    template <int dim>
    NavierStokesStudy<dim>::NavierStokesStudy(ParameterHandler &prm,
                                              RunContext       &context)
      : context(context)
    {
      const std::string prefix = std::string(section) + "/";
      prm.enter_subsection(section);
      box.parse(prm, dim, section);
      convergence.parse(prm, 0);
      flow_parameters.solver.parse_flow(prm);
      flow_parameters.newton.parse(prm);
      reynolds_number     = prm.get_double("Reynolds number");
      viscosity_text      = prm.get("Viscosity");
      force_text          = prm.get("Body force");
      initial_text        = prm.get("Initial velocity");
      exact_velocity_text = prm.get("Exact velocity");
      exact_pressure_text = prm.get("Exact pressure");
      flow_parameters.weak_penalty_constant
        = prm.get_double("Weak penalty constant");
      flow_parameters.weak_inflow_term = prm.get_bool("Weak inflow term");
      quadrature_points                = prm.get_integer("Quadrature points");
      boundaries.parse(prm, n_boundaries);
      std::vector<std::string> field_names{"u", "v"};
      if (dim == 3)
        field_names.push_back("w");
      field_names.push_back("p");
      for (unsigned int l = 1; l <= n_line_samples; ++l)
        {
          const std::string name = "Line sample " + std::to_string(l);
          prm.enter_subsection(name);
          LineSample sample;
          sample.parse(prm, prefix + name + "/", field_names, dim);
          if (!sample.name.empty())
            {
              // Outside the box the spline would be extrapolated.
              const auto corner = [](const std::vector<double> &x) {
                std::string text;
                for (const double v : x)
                  text += (text.empty() ? "" : ", ") + value_text(v);
                return text;
              };
              for (const auto &[entry, point] :
                   {std::make_pair("Start", &sample.start),
                    std::make_pair("End", &sample.end)})
                for (unsigned int d = 0; d < dim; ++d)
                  check_input((*point)[d] >= box.lower[d]
                                && (*point)[d] <= box.upper[d],
                              prefix + name + "/" + entry,
                              prm.get(entry),
                              "a point of the domain (lower corner "
                                + corner(box.lower) + ", upper corner "
                                + corner(box.upper) + ")");
              line_samples.push_back(sample);
            }
          prm.leave_subsection();
        }
      prm.enter_subsection("Time stepping");
      loop_parameters.parse(prm, prefix + "Time stepping");
      flow_parameters.time_integration.parse(prm);
      steady_tolerance = prm.get_double("Steady tolerance");
      prm.leave_subsection();
      prm.leave_subsection();

      // Report bad input before any work.
      check_input(reynolds_number > 0,
                  prefix + "Reynolds number",
                  value_text(reynolds_number),
                  "> 0");
      check_input(loop_parameters.restart_file.empty()
                    || (convergence.degrees.size() == 1
                        && convergence.refinements == 0),
                  prefix + "Time stepping/Restart from",
                  loop_parameters.restart_file,
                  "empty for a convergence study (several degrees or "
                  "refinements); a restart continues a single run");
      for (const unsigned int p : convergence.degrees)
        box.make_space<dim>(p, convergence.continuity);
      bool level_fixed;
      conditions(level_fixed);
      coefficients(2);
      parse_formula<dim>(
        initial_text, dim, 1, reynolds_number, prefix + "Initial velocity");
      if (!exact_velocity_text.empty())
        parse_formula<dim>(exact_velocity_text,
                           dim,
                           0,
                           reynolds_number,
                           prefix + "Exact velocity");
      if (!exact_pressure_text.empty())
        parse_formula<dim>(exact_pressure_text,
                           1,
                           0,
                           reynolds_number,
                           prefix + "Exact pressure");
    }


    template <int dim>
    FlowCoefficients<dim>
    NavierStokesStudy<dim>::coefficients(const unsigned int p) const
    {
      const std::string     prefix = std::string(section) + "/";
      FlowCoefficients<dim> c;
      c.reynolds_number           = reynolds_number;
      c.inverse_estimate_constant = 6. * std::pow(p, 4);
      // muparser only where the user writes a formula.
      std::vector<double> values;
      if (is_constant(viscosity_text, values) && values.size() == 1)
        c.viscosity = std::make_shared<ConstantViscosity<dim>>(values[0]);
      else
        c.viscosity
          = std::make_shared<FormulaViscosity<dim>>(parse_formula<dim>(
            viscosity_text, 1, 0, reynolds_number, prefix + "Viscosity"));
      if (is_constant(force_text, values) && values.size() == dim)
        {
          if (std::any_of(values.begin(), values.end(), [](double v) {
                return v != 0;
              }))
            c.body_force = BodyForce<dim>(
              std::make_shared<Functions::ConstantFunction<dim>>(values));
        }
      else
        c.body_force = BodyForce<dim>(parse_formula<dim>(
          force_text, dim, 0, reynolds_number, prefix + "Body force"));
      return c;
    }


    template <int dim>
    std::vector<VelocityCondition<dim>>
    NavierStokesStudy<dim>::conditions(bool &level_fixed) const
    {
      return boundaries.conditions<dim>(std::string(section) + "/",
                                        reynolds_number,
                                        box.periodic,
                                        level_fixed);
    }


    template <int dim>
    std::vector<double>
    NavierStokesStudy<dim>::run_level(const unsigned int p,
                                      const unsigned int r,
                                      TimerOutput       &timer)
    {
      const SplineSpace<dim> space
        = box.make_space<dim>(p, convergence.continuity).h_refined(r);
      const FlowCoefficients<dim>  coefficients = this->coefficients(p);
      bool                         level_fixed;
      const auto                   conditions = this->conditions(level_fixed);
      IncompressibleFlowParameters parameters = flow_parameters;
      parameters.fix_pressure_mean = boundaries.fix_pressure_mean(level_fixed);
      parameters.quadrature_points
        = quadrature_points > 0 ? quadrature_points : p + 2;
      IncompressibleFlow<dim> flow(context.communicator,
                                   space,
                                   coefficients,
                                   conditions,
                                   parameters,
                                   timer);
      flow.set_initial_state(*parse_formula<dim>(initial_text,
                                                 dim,
                                                 1,
                                                 reynolds_number,
                                                 std::string(section)
                                                   + "/Initial velocity"),
                             0.);

      const std::string tag
        = "p" + std::to_string(p) + "-level" + std::to_string(r);
      const bool single_run
        = convergence.degrees.size() == 1 && convergence.refinements == 0;
      TimeLoop         loop(loop_parameters, context, timer);
      FlowMonitor<dim> monitor(flow, steady_tolerance);
      loop.add_checkpointable("flow", flow);
      loop.add_monitor(monitor);
      loop.add_stationarity_criterion(monitor);
      loop.enable_checkpoints(single_run);
      loop.set_time_series_name(single_run ? "time-series.csv" :
                                             "time-series-" + tag + ".csv");
      SplineFieldWriter<dim> writer(flow.dofs(), nullptr);
      add_flow_output_fields(writer);
      if (convergence.write_vtu)
        loop.set_output([&](const unsigned int step) {
          writer.write(flow.solution(),
                       context.output_directory,
                       "flow-" + (single_run ? "" : tag + "-")
                         + Utilities::int_to_string(step, 5));
        });
      if (loop.restore())
        context.pcout << "restart from " << loop_parameters.restart_file
                      << ": step " << loop.step() << ", t = " << flow.time()
                      << ", dt = " << loop.next_dt() << std::endl;
      context.pcout
        << "Navier-Stokes (RBVMS): " << dim << "D, degree " << p << ", C^"
        << (convergence.continuity < 0 ? int(p) - 1 : convergence.continuity)
        << ", " << space.n_elements() << " elements, " << flow.dofs().n_dofs()
        << " unknowns, Re = " << reynolds_number << ", pressure level "
        << (parameters.fix_pressure_mean ? "zero mean" : "set by the boundary")
        << std::endl;
      loop.run(flow);
      write_line_samples(flow, space, tag, single_run);
      return errors(flow, p);
    }


    template <int dim>
    void
    NavierStokesStudy<dim>::write_line_samples(
      const IncompressibleFlow<dim> &flow,
      const SplineSpace<dim>        &space,
      const std::string             &tag,
      const bool                     single_run) const
    {
      if (line_samples.empty())
        return;
      // Rank 0 samples and writes; only it prints.
      const std::vector<double> natural
        = gather_natural_on_rank_0(flow.dofs(), flow.solution());
      if (natural.empty())
        return;
      for (const auto &sample : line_samples)
        {
          LineSample named = sample;
          if (!single_run)
            named.name += "-" + tag;
          const auto [deviation, integral] = write_line_sample(
            named, space, natural, dim + 1, context.output_directory, true);
          if (sample.print_integral)
            context.pcout << named.name << ".csv: integral of "
                          << sample.field_name
                          << " along the line: " << integral << std::endl;
          if (!sample.reference.empty())
            context.pcout << named.name << ".csv: largest deviation of "
                          << sample.field_name << " from " << sample.reference
                          << ": " << deviation << std::endl;
        }
    }


    template <int dim>
    std::vector<double>
    NavierStokesStudy<dim>::errors(const IncompressibleFlow<dim> &flow,
                                   const unsigned int             p) const
    {
      if (exact_velocity_text.empty())
        return {};
      const std::string prefix  = std::string(section) + "/";
      auto              exact_u = parse_formula<dim>(exact_velocity_text,
                                        dim,
                                        0,
                                        reynolds_number,
                                        prefix + "Exact velocity");
      exact_u->set_time(flow.time());
      std::shared_ptr<FunctionParser<dim>> exact_p;
      if (!exact_pressure_text.empty())
        {
          exact_p = parse_formula<dim>(exact_pressure_text,
                                       1,
                                       0,
                                       reynolds_number,
                                       prefix + "Exact pressure");
          exact_p->set_time(flow.time());
        }
      // The pressure is compared up to a constant: both sides with zero mean.
      const QGauss<1> error_quadrature(p + 3
                                       + convergence.extra_quadrature_points);
      const auto      means = integrate_field<dim>(
        flow.dofs(),
        nullptr,
        error_quadrature,
        0,
        flow.solution(),
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
        flow.dofs(),
        nullptr,
        error_quadrature,
        1,
        flow.solution(),
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
      const auto            timer_owner = context.make_timer();
      TimerOutput          &timer       = *timer_owner;
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
        ConvergenceParameters::declare(prm, "2", "0", "1");
        FlowSolverDefaults solver_defaults;
        solver_defaults.tolerance = "1e-10";
        LinearSolverParameters::declare_flow(prm, solver_defaults);
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
        prm.declare_entry("Quadrature points",
                          "0",
                          Patterns::Integer(0),
                          "Gauss points per direction; 0: p + 2 (spec 4.9 "
                          "uses 6).");
        FlowBoundaryParameters::declare(prm, n_boundaries);
        for (unsigned int l = 1; l <= n_line_samples; ++l)
          {
            prm.enter_subsection("Line sample " + std::to_string(l));
            LineSample::declare(prm, "u|v|w|p");
            prm.leave_subsection();
          }
        NewtonParameters::declare(prm, "20", "1e-8", "1e-10");
        prm.enter_subsection("Time stepping");
        TimeLoop::Parameters::declare(prm, {"fixed", "0.1", "0.1", "1"});
        GeneralizedAlphaParameters::declare(prm, "0.5");
        prm.declare_entry("Steady tolerance",
                          "0",
                          Patterns::Double(0),
                          "> 0: stop when |U_{n+1} - U_n| / |U_{n+1}| falls "
                          "below this (steady state).");
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
