// Study "willmore-flow": the vesicle of spec Part E, constrained
// Willmore/Helfrich flow with (optionally) the electric energies and the
// electric potential. The model (fields, terms, step with the modified
// ALM) is models/phase_field_flow; the time loop, checkpoints and restart
// are the engine's (time/time_loop); this file declares the parameters,
// builds the spline space, the clamped boundary (E15) and the initial shape
// (E1)/(E3), and records what is monitored.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/fields/dirichlet_constraints.h>
#include <vesicle_iga/fields/natural_numbering.h>
#include <vesicle_iga/io/vesicle_output.h>
#include <vesicle_iga/models/phase_field_flow.h>
#include <vesicle_iga/physics/vesicle_shape.h>
#include <vesicle_iga/postprocess/level_set_extent.h>
#include <vesicle_iga/postprocess/zero_contour.h>
#include <vesicle_iga/postprocess/zero_set_measures.h>
#include <vesicle_iga/solvers/zero_set_target_control.h>
#include <vesicle_iga/spline/box_space_parameters.h>
#include <vesicle_iga/studies/study.h>
#include <vesicle_iga/time/time_loop.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    const char *section = "Willmore flow";

    /// What the study records after every accepted step: the functionals
    /// (in units of kappa), the constraint errors and multipliers, the
    /// extents of the zero level set, the interface speed and drift, with a
    /// field the energies in eV, the potential's iterations and the
    /// midpoint on the field axis; the largest constraint error and energy
    /// increases for the closing summary; stationarity.
    template <int dim>
    class WillmoreMonitor : public Monitor,
                            public StationarityCriterion,
                            public Checkpointable
    {
    public:
      struct Settings
      {
        double      kappa;
        bool        constrained;
        std::string measure;
        double      tolerance, interface_speed;
        Point<dim>  center;
      };
      /// With `targets`, the monitor hands it the sharp measures after
      /// every step and moves the constraint targets of the model to what
      /// it returns; the reference is the present (initial) state.
      WillmoreMonitor(PhaseFieldFlow<dim>            &model,
                      const ElectromechanicsMaterial &material,
                      const Settings                 &settings,
                      ZeroSetTargetControl           *targets = nullptr)
        : model(model)
        , material(material)
        , s(settings)
        , targets(targets)
      {
        const auto &f      = model.current_functionals();
        previous           = f;
        lagrangian_initial = f.lagrangian;
        monitored_previous = f.lagrangian;
        if (targets)
          {
            const auto m = level_set_measures();
            targets->set_reference({m[dim], m[dim + 1]});
          }
      }

      std::vector<std::string>
      columns() const override;
      void
      measure(const StepInfo      &info,
              std::vector<double> &row,
              std::ostream        &progress) override;
      bool
      stationary(const StepInfo &info) override;
      std::string
      message(const StepInfo &) const override;
      void
      save(Checkpoint &c, const std::string &prefix) const override;
      void
      load(const Checkpoint &c, const std::string &prefix) override;

      std::vector<double>
      extents() const
      {
        const auto m = level_set_measures();
        return std::vector<double>(m.begin(), m.begin() + dim);
      }
      /// The measures of the zero level set of the time series: the extents
      /// through the centre; in 2D the sharp length, area and reduced area;
      /// with a potential the midpoint along the field axis. Each rank
      /// evaluates its own elements; only crossings and segments are
      /// combined (collective; every rank gets the values).
      std::vector<double>
      level_set_measures() const;

      double max_constraint_error = 0, max_energy_increase = 0,
             max_lagrangian_increase = 0;

    private:
      /// |E_B| plus what the flow has released: energies are compared on
      /// the scale of the shape-dependent part (the electrolyte term (E8)
      /// carries a large shape-independent part).
      double
      energy_scale(const typename PhaseFieldFlow<dim>::Functionals &f) const
      {
        return std::abs(f.energies[0])
               + std::abs(lagrangian_initial - f.lagrangian);
      }

      PhaseFieldFlow<dim>                      &model;
      const ElectromechanicsMaterial           &material;
      const Settings                            s;
      typename PhaseFieldFlow<dim>::Functionals previous;
      double                lagrangian_initial = 0, monitored_previous = 0;
      ZeroSetTargetControl *targets;
      double                change = 0, speed = 0;
    };


    template <int dim>
    std::vector<std::string>
    WillmoreMonitor<dim>::columns() const
    {
      std::vector<std::string> c = model.energy_names();
      for (const char *n : {"total_energy",
                            "lagrangian",
                            "area_error",
                            "volume_error",
                            "tension_multiplier",
                            "pressure_multiplier"})
        c.emplace_back(n);
      for (unsigned int d = 0; d < dim; ++d)
        c.push_back(std::string("extent_") + "xyz"[d]);
      if (dim == 2)
        for (const char *n :
             {"contour_length", "contour_area", "contour_reduced_area"})
          c.emplace_back(n);
      else
        for (const char *n : {"zero_surface_area",
                              "zero_surface_volume",
                              "zero_surface_reduced_volume"})
          c.emplace_back(n);
      c.emplace_back("interface_speed");
      for (unsigned int d = 0; d < dim; ++d)
        c.push_back(std::string("drift_velocity_") + "xyz"[d]);
      if (model.potential())
        {
          for (const auto &n : model.energy_names())
            c.push_back(n + "_eV");
          // The change of the total energy over a step, split into the
          // step with psi frozen (what the step minimises: it falls but for
          // the work of the constraint multipliers within the ALM
          // tolerance) and the update of psi that follows (either sign: psi
          // solves (E16) with sigma(phi), which does not make the electric
          // energies (E7), (E8) stationary in psi; issue 16, item 3).
          for (const char *n : {"total_energy_eV",
                                "potential_iterations",
                                "field_axis_midpoint",
                                "frozen_step_energy_change",
                                "potential_update_energy_change"})
            c.emplace_back(n);
        }
      return c;
    }


    template <int dim>
    std::vector<double>
    WillmoreMonitor<dim>::level_set_measures() const
    {
      const auto                   &dofs = model.get_dofs();
      const MPI_Comm                comm = dofs.get_mesh().get_communicator();
      TrilinosWrappers::MPI::Vector phi(dofs.locally_owned_dofs(),
                                        dofs.locally_relevant_dofs(),
                                        comm);
      phi = model.solution();
      std::vector<double> m;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const auto x = zero_crossing_bounds(dofs, phi, 0, s.center, d);
          m.push_back(x.empty() ? 0. : x[1] - x[0]);
        }
      // 2D: the longest closed piece of the zero level set; 3D: the area of
      // the zero surface, the volume of {phi < 0} and the reduced volume
      // 6 sqrt(pi) V / A^(3/2) (the sharp measures that the diffuse (E9)
      // approximate; issue 16, item 1).
      std::array<double, 3> geometry{{0., 0., 0.}};
      if constexpr (dim == 2)
        {
          for (const ZeroContour &piece : zero_contours(dofs, phi, 0, 8))
            if (piece.closed)
              {
                geometry = {{piece.length(),
                             std::abs(piece.enclosed_area()),
                             piece.reduced_area()}};
                break;
              }
          geometry = Utilities::MPI::broadcast(comm, geometry, 0);
        }
      else
        {
          const ZeroSetMeasures z = zero_set_measures(dofs, phi, 0, 4);
          geometry                = {{z.boundary, z.inside, z.reduced(dim)}};
        }
      m.insert(m.end(), geometry.begin(), geometry.end());
      if (model.potential())
        {
          const auto x = zero_crossing_bounds(
            dofs, phi, 0, s.center, material.direction());
          m.push_back(x.empty() ? 0. : 0.5 * (x[0] + x[1]));
        }
      return m;
    }


    template <int dim>
    void
    WillmoreMonitor<dim>::measure(const StepInfo      &info,
                                  std::vector<double> &row,
                                  std::ostream        &progress)
    {
      const auto  &f            = model.current_functionals();
      const auto  &frozen       = model.frozen_functionals();
      const double area_error   = f.area / model.area_target() - 1;
      const double volume_error = f.volume / model.volume_target() - 1;
      if (s.constrained)
        max_constraint_error = std::max(
          {max_constraint_error, std::abs(area_error), std::abs(volume_error)});
      // The step minimises E(phi, psi^n): measured with psi frozen.
      const double frozen_step_change      = frozen.energy - previous.energy;
      const double potential_update_change = f.energy - frozen.energy;
      max_energy_increase
        = std::max(max_energy_increase, frozen_step_change / energy_scale(f));
      max_lagrangian_increase
        = std::max(max_lagrangian_increase,
                   (frozen.lagrangian - previous.lagrangian) / energy_scale(f));
      previous = f;

      for (const double e : f.energies)
        row.push_back(e / s.kappa);
      for (const double v : {f.energy / s.kappa,
                             f.lagrangian / s.kappa,
                             area_error,
                             volume_error,
                             model.area_multiplier(),
                             model.volume_multiplier()})
        row.push_back(v);
      // One gather of the solution for all level-set measures of the step.
      const auto   measures = level_set_measures();
      unsigned int measure  = 0;
      for (; measure < dim + 3; ++measure)
        row.push_back(measures[measure]);
      const auto motion = model.interface_motion(info.dt);
      speed             = motion.speed;
      row.push_back(speed);
      for (unsigned int d = 0; d < dim; ++d)
        row.push_back(motion.drift[d]);
      if (model.potential())
        {
          for (const double e : f.energies)
            row.push_back(material.to_eV(e));
          row.push_back(material.to_eV(f.energy));
          row.push_back(model.take_potential_iterations());
          row.push_back(measures[measure]);
          row.push_back(frozen_step_change / s.kappa);
          row.push_back(potential_update_change / s.kappa);
        }
      progress << " E/kappa=" << f.energy / s.kappa
               << " area_error=" << area_error
               << " volume_error=" << volume_error;
      change = std::abs(f.lagrangian - monitored_previous) / energy_scale(f);
      monitored_previous = f.lagrangian;
      if (targets)
        {
          // Hold the zero level set's measures (ZeroSetTargetControl). The
          // Lagrangian moves with the targets; the next step's changes are
          // measured from the moved value.
          const auto [volume, area]
            = targets->targets({f.area, f.volume},
                               {measures[dim], measures[dim + 1]},
                               {model.area_target(), model.volume_target()});
          model.set_constraint_targets(volume, area);
          previous           = model.current_functionals();
          monitored_previous = previous.lagrangian;
        }
    }


    template <int dim>
    bool
    WillmoreMonitor<dim>::stationary(const StepInfo &info)
    {
      if (!info.dt_at_maximum)
        return false;
      if (s.measure == "lagrangian")
        return change <= s.tolerance;
      return speed <= s.interface_speed;
    }


    template <int dim>
    std::string
    WillmoreMonitor<dim>::message(const StepInfo &) const
    {
      std::ostringstream m;
      if (s.measure == "lagrangian")
        m << "stationary: relative change of the Lagrangian " << change
          << " over the last step";
      else
        m << "stationary: interface speed " << speed << " over the last step";
      return m.str();
    }


    template <int dim>
    void
    WillmoreMonitor<dim>::save(Checkpoint &c, const std::string &prefix) const
    {
      c.scalars[prefix + ".max_constraint_error"]    = max_constraint_error;
      c.scalars[prefix + ".max_energy_increase"]     = max_energy_increase;
      c.scalars[prefix + ".max_lagrangian_increase"] = max_lagrangian_increase;
      c.scalars[prefix + ".lagrangian_initial"]      = lagrangian_initial;
      c.scalars[prefix + ".lagrangian_previous"]     = monitored_previous;
    }


    template <int dim>
    void
    WillmoreMonitor<dim>::load(const Checkpoint &c, const std::string &prefix)
    {
      max_constraint_error    = c.scalar(prefix + ".max_constraint_error");
      max_energy_increase     = c.scalar(prefix + ".max_energy_increase");
      max_lagrangian_increase = c.scalar(prefix + ".max_lagrangian_increase");
      lagrangian_initial      = c.scalar(prefix + ".lagrangian_initial");
      monitored_previous      = c.scalar(prefix + ".lagrangian_previous");
      previous                = model.current_functionals();
    }


    template <int dim>
    class WillmoreFlow : public Study
    {
    public:
      WillmoreFlow(ParameterHandler &prm, RunContext &context);
      void
      run() override;

    private:
      void
      setup();
      void
      write_output(const unsigned int step) const;
      void
      print_summary(const WillmoreMonitor<dim> &monitor,
                    const unsigned int          steps) const;

      RunContext                             &context;
      BoxSpaceParameters                      box;
      unsigned int                            degree;
      int                                     continuity;
      double                                  epsilon_over_h;
      std::string                             epsilon_reference;
      VesicleShape<dim>                       shape;
      bool                                    check_jacobian_first;
      PhaseFieldFlowParameters                model_parameters;
      TimeLoop::Parameters                    loop_parameters;
      typename WillmoreMonitor<dim>::Settings monitor_settings;
      bool                                    zero_set_targets = false;

      std::unique_ptr<TimerOutput>           timer;
      std::unique_ptr<SplineSpace<dim>>      space;
      std::unique_ptr<PatchMesh<dim>>        mesh;
      std::unique_ptr<SplineDofHandler<dim>> dofs;
      AffineConstraints<double>              phi_constraints;
      AffineConstraints<double>              increment_constraints;
      std::unique_ptr<PhaseFieldFlow<dim>>   model;
      double                                 h = 0;
    };


    template <int dim>
    WillmoreFlow<dim>::WillmoreFlow(ParameterHandler &prm, RunContext &context)
      : context(context)
    {
      auto &p = model_parameters;
      prm.enter_subsection(section);
      box.parse(prm, dim, section);
      degree                  = prm.get_integer("Degree");
      continuity              = prm.get_integer("Continuity");
      p.quadrature_points     = prm.get_integer("Quadrature points");
      p.kappa                 = prm.get_double("Bending rigidity");
      p.spontaneous_curvature = prm.get_double("Spontaneous curvature");
      epsilon_over_h          = prm.get_double("Epsilon over h");
      epsilon_reference       = prm.get("Element size for epsilon");
      p.constraint_method     = prm.get("Constraint method");
      p.alm_jacobian          = prm.get("ALM initial Jacobian");
      p.alm_first_update      = prm.get("ALM first update");
      zero_set_targets = prm.get("Constraint targets") == "zero level set";
      p.M1             = prm.get_double("M1");
      p.M2             = prm.get_double("M2");
      p.constraint_tolerance = prm.get_double("Constraint tolerance");
      p.max_alm_iterations   = prm.get_integer("Max ALM iterations");
      check_jacobian_first   = prm.get_bool("Check Jacobian");
      shape.parse(prm);
      p.newton.parse(prm);
      p.solver.parse(prm);
      prm.enter_subsection("Time stepping");
      loop_parameters.parse(prm, std::string(section) + "/Time stepping");
      p.time_integration.parse(prm);
      monitor_settings.measure   = prm.get("Stationarity measure");
      monitor_settings.tolerance = prm.get_double("Stationarity tolerance");
      monitor_settings.interface_speed
        = prm.get_double("Stationary interface speed");
      prm.leave_subsection();
      p.material.parse(prm, dim);
      prm.enter_subsection("Electric field");
      p.potential_solver.parse(prm);
      p.coupling              = prm.get("Coupling");
      p.fixed_point_tolerance = prm.get_double("Fixed-point tolerance");
      p.max_fixed_point_iterations
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
      check_input(p.kappa > 0,
                  "Bending rigidity",
                  value_text(p.kappa),
                  "a positive value");
      check_input(epsilon_over_h >= 1,
                  "Epsilon over h",
                  value_text(epsilon_over_h),
                  ">= 1: the tanh profile (E1) has width ~2.8 eps and must "
                  "span several elements");
      monitor_settings.kappa       = p.kappa;
      monitor_settings.constrained = p.constraint_method != "none";
      monitor_settings.center      = shape.center;
      check_input(!zero_set_targets || monitor_settings.constrained,
                  "Constraint targets",
                  "zero level set",
                  "'diffuse' with 'Constraint method = none' (there are no "
                  "constraints whose targets could move)");
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
      h = epsilon_reference == "largest edge" ? h_long : h_short;
      const double epsilon     = epsilon_over_h * h;
      model_parameters.epsilon = epsilon;
      check_input(epsilon >= h_long * (1 - 1e-12),
                  "Epsilon over h",
                  value_text(epsilon_over_h),
                  "epsilon = " + value_text(epsilon)
                    + " at least the longest edge of the smallest element ("
                    + std::to_string(h_long)
                    + "): the tanh profile (E1) must span several elements");
      shape.check_fits(lower, upper, epsilon, context.pcout);

      timer = context.make_timer();
      mesh  = std::make_unique<PatchMesh<dim>>(context.communicator,
                                              *space,
                                              nullptr);
      dofs  = std::make_unique<SplineDofHandler<dim>>(*mesh, *space, 1);

      // Clamped boundary (E15): the two outer layers of coefficients are 1
      // for phi and 0 for every Newton increment.
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
      model = std::make_unique<PhaseFieldFlow<dim>>(*dofs,
                                                    increment_constraints,
                                                    model_parameters,
                                                    *timer);
    }


    template <int dim>
    void
    WillmoreFlow<dim>::write_output(const unsigned int step) const
    {
      const auto                   *electric = model->potential();
      const auto                   &material = model_parameters.material;
      const std::string             name = Utilities::int_to_string(step, 5);
      TrilinosWrappers::MPI::Vector ghosted(dofs->locally_owned_dofs(),
                                            dofs->locally_relevant_dofs(),
                                            context.communicator);
      ghosted = model->solution();
      write_vesicle_vtu(*dofs,
                        ghosted,
                        electric ? &electric->potential() : nullptr,
                        material,
                        context.output_directory,
                        (electric ? "fields-" : "phi-") + name);
      // Profiles of phi, sigma (and psi, |grad psi|) along the axes, and
      // phi in the plane of the field axis and the first other axis.
      const auto phi_natural
        = gather_natural_on_rank_0(*dofs, model->solution());
      std::vector<double> psi_natural;
      if (electric)
        psi_natural
          = gather_natural_on_rank_0(*dofs, electric->owned_potential());
      if (Utilities::MPI::this_mpi_process(context.communicator) != 0)
        return;
      write_axis_profiles(*space,
                          phi_natural,
                          electric ? &psi_natural : nullptr,
                          material,
                          shape.center,
                          context.output_directory + "/profiles-" + name
                            + ".csv");
      const unsigned int field_axis   = material.direction();
      const unsigned int lateral_axis = field_axis == 0 ? 1 : 0;
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
    WillmoreFlow<dim>::print_summary(const WillmoreMonitor<dim> &monitor,
                                     const unsigned int          steps) const
    {
      const auto &f = model->current_functionals();
      context.pcout << "final: t=" << model->time() << " steps=" << steps
                    << " E_B/kappa=" << f.energies[0] / model_parameters.kappa
                    << " area_error=" << f.area / model->area_target() - 1
                    << " volume_error="
                    << f.volume / model->volume_target() - 1;
      const auto e = monitor.extents();
      for (unsigned int d = 0; d < dim; ++d)
        context.pcout << " extent_"
                      << "xyz"[d] << "=" << e[d];
      context.pcout << std::endl;
      if (steps == 0)
        return;
      const bool alm = model_parameters.constraint_method == "alm";
      const bool staggered
        = model->potential() && model_parameters.coupling != "fixed-point";
      context.pcout << "largest |A/A0-1|, |V/V0-1| over the accepted steps: "
                    << monitor.max_constraint_error
                    << (alm ? (monitor.max_constraint_error
                                   <= model_parameters.constraint_tolerance ?
                                 " (within the ALM tolerance)" :
                                 " (ABOVE the ALM tolerance)") :
                              "")
                    << std::endl
                    << "largest relative increase over an accepted step"
                    << (staggered ? " (psi frozen, as the step minimises)" : "")
                    << ": energy " << std::max(0., monitor.max_energy_increase)
                    << ", Lagrangian "
                    << std::max(0., monitor.max_lagrangian_increase)
                    << std::endl;
    }


    template <int dim>
    void
    WillmoreFlow<dim>::run()
    {
      setup();
      context.pcout << "Willmore flow: " << dim << "D, degree " << degree
                    << ", " << space->n_elements() << " elements, "
                    << dofs->n_dofs() << " unknowns, h = " << h
                    << ", epsilon = " << model_parameters.epsilon << " ("
                    << epsilon_over_h << " h)" << std::endl;
      if (context.print_details)
        context.pcout << "linear solver: " << model->solver_description()
                      << std::endl;

      // Initial condition (E1)/(E3); a restart overwrites it.
      TrilinosWrappers::MPI::Vector phi0(dofs->locally_owned_dofs(),
                                         context.communicator);
      scatter_natural(*dofs,
                      shape.phase_field(*space, model_parameters.epsilon),
                      phi0);
      phi_constraints.distribute(phi0);
      model->set_initial_state(phi0);

      TimeLoop             loop(loop_parameters, context, *timer);
      ZeroSetTargetControl target_control;
      WillmoreMonitor<dim> monitor(*model,
                                   model_parameters.material,
                                   monitor_settings,
                                   zero_set_targets ? &target_control :
                                                      nullptr);
      loop.add_checkpointable("phase_field", *model);
      if (zero_set_targets)
        loop.add_checkpointable("zero_set_targets", target_control);
      loop.add_checkpointable("monitor", monitor);
      loop.add_monitor(monitor);
      loop.add_stationarity_criterion(monitor);
      loop.set_output([this](const unsigned int n) { write_output(n); });
      const bool  restarted = loop.restore();
      const auto &f         = model->current_functionals();
      context.pcout << (restarted ? "restart" : "initial")
                    << " (t = " << model->time() << ", step " << loop.step()
                    << "): bending energy / kappa = "
                    << f.energies[0] / model_parameters.kappa
                    << ", area A0 = " << model->area_target()
                    << ", volume V0 = " << model->volume_target() << std::endl;
      if (check_jacobian_first)
        {
          std::ostringstream report;
          model->check_jacobian(report);
          context.pcout << report.str();
        }
      loop.run(*model);
      print_summary(monitor, loop.step());
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
        // GMRES with one V-cycle of the spline multigrid: robust for the
        // fourth-order Newton matrix at large dt, where ILU and AMG alone
        // need hundreds of iterations (doc/willmore.md). The smoother is
        // ILU(0) with one layer of restricted Schwarz overlap: on one rank
        // the same as ILU(0), and the count stays that of one rank on 2
        // and 4 ranks (doc/performance.md).
        LinearSolverParameters::declare(
          prm, "gmres-mg", "1e-8", "schwarz-ilu", "1");
        // A Jacobian kept across Newton solves (ALM iterations, steps)
        // while dt changes by at most 20 %: the 3D phase-field Jacobian
        // costs 8.5 residuals (doc/performance.md, "Fewer Jacobians").
        NewtonParameters::declare(prm, "12", "1e-8", "1e-10", "20", "true");
        VesicleShape<2>::declare(prm);
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
        prm.declare_entry(
          "ALM first update",
          "predicted drift",
          Patterns::Selection("carried error|predicted drift"),
          "What the first ALM update of a step (Algorithm 1, line 7) "
          "removes. carried error: the constraint errors of phi_n (the "
          "source); one-iteration steps then leave an error proportional "
          "to dt that can swing across the tolerance band from step to "
          "step. predicted drift: the errors predicted at the end of the "
          "step, with the multipliers of the last accepted step and its "
          "rate of change of V and A scaled by the step-size ratio "
          "(doc/validation.md section 5).");
        prm.declare_entry(
          "Constraint targets",
          "diffuse",
          Patterns::Selection("diffuse|zero level set"),
          "What the area and volume constraints hold. diffuse: the diffuse "
          "A and V of (E9) at their initial values (the spec). zero level "
          "set: the area and enclosed volume of the zero level set (in 2D "
          "its length and enclosed area) at their initial values: after "
          "every accepted step the targets of (E9) become the initial sharp "
          "measures plus the present difference between the diffuse and "
          "the sharp ones. The difference is a curvature correction of "
          "order eps^2 that changes with the shape, so with 'diffuse' the "
          "zero level set's reduced volume drifts (0.69 to 0.80 in "
          "prolate-to-dumbbell-3d); doc/validation.md 1d. Needs the ALM or "
          "penalty constraint method; the sharp measures are computed from "
          "the solution gathered on rank 0 after every step.");
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
        prm.declare_entry("Check Jacobian",
                          "false",
                          Patterns::Bool(),
                          "Compare the tangent with central differences of "
                          "the residual before the first step.");
        prm.enter_subsection("Time stepping");
        // Spec section 2.5 / 6.2: dt_0 = 1e-10, dt_max = 1, T = 300.
        TimeLoop::Parameters::declare(prm, {"adaptive", "1e-10", "1", "300"});
        GeneralizedAlphaParameters::declare(prm, "0.5");
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
        prm.declare_entry("Stationary interface speed",
                          "1e-4",
                          Patterns::Double(0),
                          "With 'Stationarity measure = interface-speed': "
                          "stop when the RMS normal speed of the interface "
                          "falls below this (um per unit time in the "
                          "normalised units; 1e-4 moves the interface by "
                          "0.03 um over T = 300).");
        prm.leave_subsection();
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
        prm.leave_subsection();
      },
      [](ParameterHandler &prm, RunContext &context) -> std::unique_ptr<Study> {
        if (context.dimension == 2)
          return std::make_unique<WillmoreFlow<2>>(prm, context);
        return std::make_unique<WillmoreFlow<3>>(prm, context);
      }};
  }
} // namespace vesicle_iga
