// Study "vesicle-hydrodynamics": N vesicles in an RBVMS flow, spec Part H
// (4.1-4.13, studies 6.3) in the mixed-free form of 4.13: initial ellipses
// (H23), velocity boundaries of spec 4.10 (strong, weak, stress-free,
// periodic), the one time loop with checkpoints; time series of the area
// and volume errors, centroids, inclination angles and global multipliers
// of every vesicle and of the kinetic, bending and interaction energies
// (spec 4.12); VTU of u, p, vorticity, phi_i and lambda_i.

#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/fields/natural_numbering.h>
#include <vesicle_iga/io/checked_output.h>
#include <vesicle_iga/io/spline_output.h>
#include <vesicle_iga/models/vesicle_hydrodynamics.h>
#include <vesicle_iga/physics/initial_vesicle.h>
#include <vesicle_iga/postprocess/spline_section.h>
#include <vesicle_iga/postprocess/zero_contour.h>
#include <vesicle_iga/spline/box_space_parameters.h>
#include <vesicle_iga/studies/flow_study_parts.h>
#include <vesicle_iga/studies/study.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <tuple>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    const char        *section      = "Vesicle hydrodynamics";
    const unsigned int n_boundaries = 4;

    /// The entry format of one vesicle in 'Vesicles'.
    std::string
    vesicle_format(const unsigned int dim)
    {
      return dim == 2 ? "'x, y, R_0, chi, angle'" : "'x, y, z, R_0, v, angle'";
    }


    /// Per vesicle: area and volume errors (spec 4.12), centroid,
    /// inclination angle, global multipliers; then the kinetic, bending,
    /// interaction and total energies.
    template <int dim>
    class HydrodynamicsMonitor : public Monitor
    {
    public:
      explicit HydrodynamicsMonitor(const VesicleHydrodynamics<dim> &model)
        : model(model)
      {}
      std::vector<std::string>
      columns() const override
      {
        std::vector<std::string> c;
        for (unsigned int i = 1; i <= model.n_vesicles(); ++i)
          for (const std::string name : {"area_error_",
                                         "volume_error_",
                                         "x_",
                                         "y_",
                                         "z_",
                                         "theta_",
                                         "lambda_g_",
                                         "lambda_v_"})
            if (dim == 3 || name != "z_")
              c.push_back(name + std::to_string(i));
        c.insert(c.end(),
                 {"kinetic_energy",
                  "bending_energy",
                  "interaction_energy",
                  "total_energy"});
        return c;
      }
      void
      measure(const StepInfo &,
              std::vector<double> &row,
              std::ostream        &progress) override
      {
        const auto measures = model.measure();
        double     bending = 0, worst_area = 0, worst_volume = 0;
        for (unsigned int i = 0; i < model.n_vesicles(); ++i)
          {
            const auto  &m = measures[i];
            const double area_error
              = (m.area - model.initial_areas()[i]) / model.initial_areas()[i];
            const double volume_error = (m.volume - model.initial_volumes()[i])
                                        / model.initial_volumes()[i];
            row.insert(row.end(), {area_error, volume_error});
            for (unsigned int d = 0; d < dim; ++d)
              row.push_back(m.centroid[d]);
            row.insert(row.end(),
                       {m.angle,
                        model.area_multipliers()[i],
                        model.volume_multipliers()[i]});
            bending += m.bending_energy;
            worst_area   = std::max(worst_area, std::abs(area_error));
            worst_volume = std::max(worst_volume, std::abs(volume_error));
          }
        const double kinetic
          = model.get_flow().kinetic_energy_and_divergence().first;
        const double interaction = model.interaction_energy();
        row.insert(
          row.end(),
          {kinetic, bending, interaction, kinetic + bending + interaction});
        progress << " E_kin=" << kinetic << " E_B=" << bending
                 << " E_int=" << interaction << " |dA/A|=" << worst_area
                 << " |dV/V|=" << worst_volume;
      }

    private:
      const VesicleHydrodynamics<dim> &model;
    };


    /**
     * Membrane tension and pressure along every vesicle (spec 4.12):
     * lambda_i and p sampled on the zero level set of phi_i, with the arc
     * length s from the rightmost point, counter-clockwise. One CSV with the
     * columns vesicle, piece (0 = the longest piece of the level set; a
     * vesicle pinching off has more), s, x, y, lambda, p. In 3D the samples
     * lie on the section of the membrane by the plane z = z_i through the
     * vesicle's centroid (the shear plane of the study files; the column z
     * follows y): the section of the spline field is itself a 2D spline
     * (section_at_z()), so the points lie on the 3D zero set. A collective
     * call; rank 0 writes.
     */
    template <int dim>
    void
    write_membrane_samples(const VesicleHydrodynamics<dim> &model,
                           const SplineSpace<dim>          &space,
                           const std::string               &filename)
    {
      const auto &dofs = model.get_flow().dofs();
      const auto  natural
        = gather_natural_on_rank_0(dofs, model.get_flow().solution());
      // Collective: every rank measures.
      const std::vector<VesicleMeasures> measures
        = dim == 3 ? model.measure() : std::vector<VesicleMeasures>();
      if (Utilities::MPI::this_mpi_process(dofs.get_mesh().get_communicator())
          != 0)
        return;
      const unsigned int nc = dofs.n_components();
      std::ofstream      out(filename);
      out << (dim == 2 ? "vesicle,piece,s,x,y,lambda,p\n" :
                         "vesicle,piece,s,x,y,z,lambda,p\n")
          << std::setprecision(10);
      for (unsigned int i = 0; i < model.n_vesicles(); ++i)
        {
          std::vector<ZeroContour> contours;
          double                   z = 0;
          if constexpr (dim == 2)
            contours = zero_contours(space, natural, nc, model.phase(i));
          else
            {
              z                  = measures[i].centroid[2];
              const auto section = section_at_z(space, natural, nc, z);
              contours           = zero_contours(section.space,
                                       section.natural,
                                       nc,
                                       model.phase(i));
            }
          for (unsigned int k = 0; k < contours.size(); ++k)
            for (unsigned int j = 0; j < contours[k].points.size(); ++j)
              {
                const auto &v = contours[k].values[j];
                out << i + 1 << ',' << k << ',' << contours[k].arc_length[j]
                    << ',' << contours[k].points[j][0] << ','
                    << contours[k].points[j][1] << ',';
                if (dim == 3)
                  out << z << ',';
                out << v[model.tension(i)] << ',' << v[model.pressure] << '\n';
              }
        }
      check_written(out, filename);
    }


    /// One vesicle of the 'Vesicles' list.
    template <int dim>
    struct VesicleEntry
    {
      Point<dim> centre;
      /// R_0, the reduced area (2D) or volume (3D), the angle in degrees.
      double radius, reduced, angle;
    };


    template <int dim>
    class VesicleHydrodynamicsStudy : public Study
    {
    public:
      VesicleHydrodynamicsStudy(ParameterHandler &prm, RunContext &context);
      void
      run() override;

    private:
      void
      check_vesicles(const SplineSpace<dim> &space) const;
      /// The box and its non-periodic directions (those with walls).
      std::tuple<Point<dim>, Point<dim>, std::array<bool, dim>>
      walls() const;
      /// Notes on rank 0 where phi_0 is not smooth or not compatible with
      /// d phi / dn = 0 enough for its bending energy to converge under
      /// refinement (doc/hydrodynamics.md, "Initial distance").
      void
      note_initial_defects(
        const std::vector<InitialVesicle<dim>> &shapes) const;
      /// Re, the inverse-estimate constant and the time scale of tau_M.
      FlowCoefficients<dim>
      flow_coefficients() const;
      /// phi_0 of each vesicle of @p shapes, mirrored in the walls if
      /// asked for.
      std::vector<std::function<double(const Point<dim> &)>>
      initial_phases(const std::vector<InitialVesicle<dim>> &shapes) const;
      /// The run's size and each vesicle's start on rank 0.
      void
      print_start(const VesicleHydrodynamics<dim>        &model,
                  const SplineSpace<dim>                 &space,
                  const std::vector<InitialVesicle<dim>> &shapes) const;

      RunContext                         &context;
      BoxSpaceParameters                  box;
      unsigned int                        degree;
      int                                 continuity;
      MembraneCoefficients                membrane;
      FlowBoundaryParameters              boundaries;
      IncompressibleFlowParameters        flow_parameters;
      PhaseFieldBlockParameters           phase_field_blocks;
      TimeLoop::Parameters                loop_parameters;
      std::vector<VesicleEntry<dim>>      vesicles;
      InitialVesicleBase::StretchFormula  stretch;
      InitialVesicleBase::DistanceFormula distance;
      bool                                mirrored_phase = false;
      std::string                         initial_velocity;
      bool                                write_vtu, write_tension;
      double                              stabilisation_time_scale = 0;
    };


    /// The entries of 'Vesicles' (@p text: per vesicle the centre, R_0,
    /// the reduced area or volume and the angle, vesicles separated by
    /// ';'), each checked, with errors naming the parameter (@p prefix its
    /// section) and the vesicle.
    template <int dim>
    std::vector<VesicleEntry<dim>>
    parse_vesicle_entries(const std::string &text_list,
                          const std::string &prefix)
    {
      std::vector<VesicleEntry<dim>> entries;
      for (const auto &text : Utilities::split_string_list(text_list, ';'))
        {
          const auto          parts = Utilities::split_string_list(text, ',');
          std::vector<double> v;
          try
            {
              for (const auto &p : parts)
                {
                  std::size_t used = 0;
                  v.push_back(std::stod(p, &used));
                  if (used != p.size() || !std::isfinite(v.back()))
                    v.clear();
                }
            }
          catch (...)
            {
              v.clear();
            }
          check_input(v.size() == dim + 3,
                      prefix + "Vesicles",
                      text,
                      vesicle_format(dim)
                        + " per vesicle (finite numbers; vesicles separated "
                          "by ';')");
          const std::string which
            = " (vesicle " + std::to_string(entries.size() + 1) + ")";
          check_input(v[dim] > 0, prefix + "Vesicles", text, "R_0 > 0" + which);
          check_input(v[dim + 1] > 0 && v[dim + 1] <= 1,
                      prefix + "Vesicles",
                      text,
                      std::string(dim == 2 ? "reduced area chi" :
                                             "reduced volume v")
                        + " in (0, 1]" + which);
          VesicleEntry<dim> entry;
          for (unsigned int d = 0; d < dim; ++d)
            entry.centre[d] = v[d];
          entry.radius  = v[dim];
          entry.reduced = v[dim + 1];
          entry.angle   = v[dim + 2];
          entries.push_back(entry);
        }
      return entries;
    }


    template <int dim>
    VesicleHydrodynamicsStudy<dim>::VesicleHydrodynamicsStudy(
      ParameterHandler &prm,
      RunContext       &context)
      : context(context)
    {
      const std::string prefix = std::string(section) + "/";
      prm.enter_subsection(section);
      box.parse(prm, dim, section);
      degree     = prm.get_integer("Degree");
      continuity = prm.get_integer("Continuity");
      flow_parameters.solver.parse_flow(prm);
      prm.enter_subsection("Linear solver");
      prm.enter_subsection("Block preconditioner");
      phase_field_blocks.parse(prm);
      prm.leave_subsection();
      prm.leave_subsection();
      flow_parameters.newton.parse(prm);
      membrane.reynolds_number    = prm.get_double("Reynolds number");
      membrane.capillary_number   = prm.get_double("Capillary number");
      membrane.interaction_number = prm.get_double("Interaction number");
      membrane.interaction        = prm.get_bool("Interaction");
      {
        using VolumeMultiplier   = MembraneCoefficients::VolumeMultiplier;
        const std::string volume = prm.get("Volume multiplier");
        membrane.volume_multiplier
          = volume == "domain"   ? VolumeMultiplier::domain :
            volume == "membrane" ? VolumeMultiplier::membrane :
                                   VolumeMultiplier::indicator;
      }
      membrane.extrapolated_multipliers
        = prm.get("Global multipliers") == "extrapolated";
      membrane.implicit_multipliers
        = prm.get("Global multipliers") == "implicit";
      membrane.multiplier_tolerance = prm.get_double("Multiplier tolerance");
      membrane.max_multiplier_iterations
        = prm.get_integer("Multiplier iterations");
      membrane.zero_normal_derivative
        = prm.get("Phase field boundary condition") == "zero normal derivative";
      membrane.mobility           = prm.get_double("Mobility");
      membrane.inextensibility_xi = prm.get_double("Inextensibility xi");
      membrane.viscosity_ratio    = prm.get_double("Viscosity ratio");
      membrane.epsilon            = prm.get_double("Epsilon");
      flow_parameters.weak_penalty_constant
        = prm.get_double("Weak penalty constant");
      stabilisation_time_scale         = prm.get_double("RBVMS time scale");
      flow_parameters.weak_inflow_term = prm.get_bool("Weak inflow term");
      const int quadrature             = prm.get_integer("Quadrature points");
      flow_parameters.quadrature_points
        = quadrature > 0 ? quadrature : degree + 2;
      stretch                         = prm.get("Stretch formula") == "exact" ?
                                          InitialVesicleBase::StretchFormula::exact :
                                          InitialVesicleBase::StretchFormula::quadratic_mean;
      const std::string distance_name = prm.get("Initial distance");
      distance                        = distance_name == "radial" ?
                                          InitialVesicleBase::DistanceFormula::radial :
                                        distance_name == "level-set" ?
                                          InitialVesicleBase::DistanceFormula::level_set :
                                          InitialVesicleBase::DistanceFormula::exact;
      mirrored_phase                  = prm.get_bool("Mirrored initial phase");
      initial_velocity                = prm.get("Initial velocity");
      write_vtu                       = prm.get_bool("Write VTU");
      write_tension                   = prm.get_bool("Write membrane samples");
      const std::string vesicle_text  = prm.get("Vesicles");
      boundaries.parse(prm, n_boundaries);
      prm.enter_subsection("Time stepping");
      loop_parameters.parse(prm, prefix + "Time stepping");
      flow_parameters.time_integration.parse(prm);
      prm.leave_subsection();
      prm.leave_subsection();

      // Report bad input before any work.
      for (const auto &[name, value] :
           std::vector<std::pair<std::string, double>>{
             {"Reynolds number", membrane.reynolds_number},
             {"Capillary number", membrane.capillary_number},
             {"Interaction number", membrane.interaction_number},
             {"Mobility", membrane.mobility},
             {"Inextensibility xi", membrane.inextensibility_xi},
             {"Viscosity ratio", membrane.viscosity_ratio},
             {"Epsilon", membrane.epsilon}})
        check_input(std::isfinite(value) && value > 0,
                    prefix + name,
                    value_text(value),
                    "a finite number > 0");
      const int smoothness = continuity < 0 ? int(degree) - 1 : continuity;
      check_input(degree >= 3,
                  prefix + "Degree",
                  std::to_string(degree),
                  ">= 3: the bending force (H25) needs third derivatives of "
                  "phi_i (spec 4.13)");
      check_input(smoothness >= 2,
                  prefix + "Continuity",
                  std::to_string(continuity),
                  "-1 (C^{p-1}) or >= 2: (H24)-(H25) need phi_i in H^2 with "
                  "continuous second derivatives (spec 4.13)");
      vesicles = parse_vesicle_entries<dim>(vesicle_text, prefix);
      check_input(!vesicles.empty(),
                  prefix + "Vesicles",
                  vesicle_text,
                  "at least one vesicle " + vesicle_format(dim));
      check_input(dim == 2
                    || stretch == InitialVesicleBase::StretchFormula::exact,
                  prefix + "Stretch formula",
                  "quadratic-mean",
                  "exact in 3D (the quadratic-mean perimeter of spec 4.11 "
                  "is a 2D formula)");
      const SplineSpace<dim> space = box.make_space<dim>(degree, continuity);
      check_vesicles(space);
      bool level_fixed;
      boundaries.conditions<dim>(prefix,
                                 membrane.reynolds_number,
                                 box.periodic,
                                 level_fixed);
      parse_formula<dim>(initial_velocity,
                         dim,
                         0,
                         membrane.reynolds_number,
                         prefix + "Initial velocity");
    }


    template <int dim>
    void
    VesicleHydrodynamicsStudy<dim>::check_vesicles(
      const SplineSpace<dim> &space) const
    {
      const std::string prefix = std::string(section) + "/Vesicles";
      const double      eps    = membrane.epsilon;
      std::vector<std::vector<Point<dim>>> outlines;
      std::vector<InitialVesicle<dim>>     shapes;
      double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
      for (unsigned int i = 0; i < vesicles.size(); ++i)
        {
          const auto &v = vesicles[i];
          shapes.emplace_back(
            v.centre, v.radius, v.reduced, v.angle, stretch, distance);
          outlines.push_back(shapes.back().outline(dim == 2 ? 720 : 2000));
          const std::string name = "vesicle " + std::to_string(i + 1);
          for (const auto &x : outlines.back())
            for (unsigned int d = 0; d < dim; ++d)
              {
                lo[d] = std::min(lo[d], x[d]);
                hi[d] = std::max(hi[d], x[d]);
                // A membrane closer than 2 eps to a wall (spec 4.10: the
                // natural conditions need phi = -1 near the boundary).
                if (!box.periodic[d])
                  check_input(x[d] - box.lower[d] >= 2 * eps
                                && box.upper[d] - x[d] >= 2 * eps,
                              prefix,
                              name,
                              "a vesicle at least 2 eps = "
                                + value_text(2 * eps) + " from the boundary ("
                                + name + " reaches it)");
              }
        }
      // Overlapping membranes, or closer than 2 eps.
      for (unsigned int i = 0; i < vesicles.size(); ++i)
        for (unsigned int j = 0; j < i; ++j)
          {
            double gap = 1e300;
            for (const auto &a : outlines[i])
              for (const auto &b : outlines[j])
                gap = std::min(gap, a.distance(b));
            if (shapes[i].signed_distance(vesicles[j].centre) < 0
                || shapes[j].signed_distance(vesicles[i].centre) < 0)
              gap = 0;
            check_input(gap >= 2 * eps,
                        prefix,
                        "vesicles " + std::to_string(j + 1) + " and "
                          + std::to_string(i + 1),
                        "membranes at least 2 eps = " + value_text(2 * eps)
                          + (gap == 0 ?
                               " apart (they overlap)" :
                               " apart (they are " + value_text(gap) + ")"));
          }
      // The interface must be resolved where the vesicles are: eps >= h
      // (the spec runs eps = 2 h).
      double h = 0;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const auto &breaks = space.knot_vector(d).breakpoints();
          for (unsigned int k = 0; k + 1 < breaks.size(); ++k)
            if (breaks[k + 1] >= lo[d] - 3 * eps
                && breaks[k] <= hi[d] + 3 * eps)
              h = std::max(h, breaks[k + 1] - breaks[k]);
        }
      check_input(eps >= h,
                  std::string(section) + "/Epsilon",
                  value_text(eps),
                  ">= the element size around the vesicles, h = "
                    + value_text(h) + " (spec 4.9: eps = 2 h)");
    }


    template <int dim>
    std::tuple<Point<dim>, Point<dim>, std::array<bool, dim>>
    VesicleHydrodynamicsStudy<dim>::walls() const
    {
      Point<dim>            lower, upper;
      std::array<bool, dim> mirror;
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d]  = box.lower[d];
          upper[d]  = box.upper[d];
          mirror[d] = !box.periodic[d];
        }
      return {lower, upper, mirror};
    }


    template <int dim>
    void
    VesicleHydrodynamicsStudy<dim>::note_initial_defects(
      const std::vector<InitialVesicle<dim>> &shapes) const
    {
      // Thresholds, scaled from tests/hydrodynamics/initial_distance by the
      // square of the defect (its vesicle: bending energy 0.78): a jump of
      // 5e-3 adds about 5e-3 at 64 per unit (0.5 for 0.052), a slope eps
      // |d phi_0 / dn| of 5e-3 (membrane 4.5 eps from the wall) about 4e-4
      // (0.025 for 0.042), growing like 1 / h^2 and 1 / h.
      const double eps                  = membrane.epsilon;
      const auto [lower, upper, mirror] = walls();
      for (unsigned int i = 0; i < shapes.size(); ++i)
        {
          const std::string name = "vesicle " + std::to_string(i + 1);
          if (shapes[i].centre_jump(eps) > 5e-3)
            context.pcout
              << "  Note: phi_0 of " << name << " jumps by "
              << shapes[i].centre_jump(eps)
              << " at its centre (radial distance of (H23), minor "
                 "semi-axis below about 4 eps): its bending energy grows "
                 "under refinement; 'Initial distance = level-set' is "
                 "smooth."
              << std::endl;
          // 5 %: the slope enters f_0 as |grad d|^2 - 1 (0.1 there).
          if (shapes[i].outline_slope() > 1.05)
            context.pcout
              << "  Note: the radial distance of (H23) has slope up to "
              << shapes[i].outline_slope() << " on the outline of " << name
              << ": phi_0 is steeper there than the equilibrium profile, "
                 "its bending energy grows like 1 / eps^2 and the area "
                 "A(0) that (H13) holds is that of the steep profile; "
                 "'Initial distance = level-set' has unit slope on the "
                 "outline (doc/hydrodynamics.md, \"Initial distance\")."
              << std::endl;
          const double gap = shapes[i].wall_gap(lower, upper, mirror);
          const double slope
            = 1
              / (std::sqrt(2.)
                 * std::pow(std::cosh(gap / (std::sqrt(2.) * eps)), 2));
          if (membrane.zero_normal_derivative && !mirrored_phase
              && slope > 5e-3)
            context.pcout
              << "  Note: the membrane of " << name << " is " << gap / eps
              << " eps from a wall, where eps d phi_0 / dn = " << slope
              << " against d phi / dn = 0: its bending energy grows under "
                 "refinement; 'Mirrored initial phase = true' is "
                 "compatible."
              << std::endl;
        }
    }


    template <int dim>
    void
    VesicleHydrodynamicsStudy<dim>::run()
    {
      const auto             timer_owner = context.make_timer();
      TimerOutput           &timer       = *timer_owner;
      const std::string      prefix      = std::string(section) + "/";
      const SplineSpace<dim> space = box.make_space<dim>(degree, continuity);
      bool                   level_fixed;
      const auto             conditions = boundaries.conditions<dim>(
        prefix, membrane.reynolds_number, box.periodic, level_fixed);
      IncompressibleFlowParameters parameters = flow_parameters;
      parameters.fix_pressure_mean = boundaries.fix_pressure_mean(level_fixed);
      const FlowCoefficients<dim>      coefficients = flow_coefficients();
      VesicleHydrodynamics<dim>        model(context.communicator,
                                      space,
                                      membrane,
                                      coefficients,
                                      conditions,
                                      parameters,
                                      vesicles.size(),
                                      timer,
                                      phase_field_blocks);
      std::vector<InitialVesicle<dim>> shapes;
      for (const auto &v : vesicles)
        shapes.emplace_back(
          v.centre, v.radius, v.reduced, v.angle, stretch, distance);
      const auto phases = initial_phases(shapes);
      {
        TimerOutput::Scope scope(timer, "setup");
        model.set_initial_state(*parse_formula<dim>(initial_velocity,
                                                    dim,
                                                    0,
                                                    membrane.reynolds_number,
                                                    prefix
                                                      + "Initial velocity"),
                                phases);
      }

      TimeLoop                  loop(loop_parameters, context, timer);
      HydrodynamicsMonitor<dim> monitor(model);
      loop.add_checkpointable("vesicles", model);
      loop.add_monitor(monitor);
      SplineFieldWriter<dim>   writer(model.get_flow().dofs(), nullptr);
      std::vector<std::string> names;
      for (unsigned int i = 1; i <= vesicles.size(); ++i)
        names.push_back("phi_" + std::to_string(i));
      for (unsigned int i = 1; i <= vesicles.size(); ++i)
        names.push_back("lambda_" + std::to_string(i));
      add_flow_output_fields(writer, names);
      loop.set_output([&](const unsigned int step) {
        if (write_vtu)
          writer.write(model.get_flow().solution(),
                       context.output_directory,
                       "vesicles-" + Utilities::int_to_string(step, 5));
        if (write_tension)
          write_membrane_samples(model,
                                 space,
                                 context.output_directory + "/tension-"
                                   + Utilities::int_to_string(step, 5)
                                   + ".csv");
      });
      if (loop.restore())
        context.pcout << "restart from " << loop_parameters.restart_file
                      << ": step " << loop.step() << ", t = " << model.time()
                      << ", dt = " << loop.next_dt() << std::endl;
      print_start(model, space, shapes);
      note_initial_defects(shapes);
      loop.run(model);
    }


    template <int dim>
    FlowCoefficients<dim>
    VesicleHydrodynamicsStudy<dim>::flow_coefficients() const
    {
      FlowCoefficients<dim> coefficients;
      coefficients.reynolds_number           = membrane.reynolds_number;
      coefficients.inverse_estimate_constant = 6. * std::pow(degree, 4);
      // Adaptive steps need tau_M independent of dt (doc/hydrodynamics.md).
      coefficients.stabilisation_time_scale
        = stabilisation_time_scale > 0 ?
            stabilisation_time_scale :
            (loop_parameters.step.mode == "adaptive" ?
               loop_parameters.step.initial_dt :
               0.);
      return coefficients;
    }


    template <int dim>
    std::vector<std::function<double(const Point<dim> &)>>
    VesicleHydrodynamicsStudy<dim>::initial_phases(
      const std::vector<InitialVesicle<dim>> &shapes) const
    {
      std::vector<std::function<double(const Point<dim> &)>> phases;
      const auto [lower, upper, mirror] = walls();
      for (const auto &shape : shapes)
        phases.push_back(
          [&shape, lower = lower, upper = upper, mirror = mirror, this](
            const Point<dim> &x) {
            return mirrored_phase ? shape.mirrored_phase_field(
                     x, membrane.epsilon, lower, upper, mirror) :
                                    shape.phase_field(x, membrane.epsilon);
          });
      return phases;
    }


    template <int dim>
    void
    VesicleHydrodynamicsStudy<dim>::print_start(
      const VesicleHydrodynamics<dim>        &model,
      const SplineSpace<dim>                 &space,
      const std::vector<InitialVesicle<dim>> &shapes) const
    {
      context.pcout << "Vesicle hydrodynamics (spec Part H, mixed-free): "
                    << vesicles.size() << " vesicle(s), degree " << degree
                    << ", " << space.n_elements() << " elements, "
                    << model.get_flow().dofs().n_dofs()
                    << " unknowns, Re = " << membrane.reynolds_number
                    << ", Ca = " << membrane.capillary_number
                    << ", eps = " << membrane.epsilon
                    << ", beta_mu = " << membrane.viscosity_ratio << std::endl;
      for (unsigned int i = 0; i < shapes.size(); ++i)
        context.pcout << "  vesicle " << i + 1 << ": centre "
                      << vesicles[i].centre << ", R_0 " << vesicles[i].radius
                      << ", gamma_e " << shapes[i].stretch()
                      << (dim == 2 ? ", reduced area " : ", reduced volume ")
                      << shapes[i].actual_reduced_measure() << ", lambda_g "
                      << model.area_multipliers()[i] << ", lambda_v "
                      << model.volume_multipliers()[i] << std::endl;
    }
  } // namespace


  StudyDescription
  vesicle_hydrodynamics_description()
  {
    return {
      "vesicle-hydrodynamics",
      "N vesicles advected by an RBVMS flow (spec Part H, mixed-free form "
      "4.13): bending, local inextensibility, interaction, global area and "
      "volume multipliers, phase-dependent viscosity; shear, extensional and "
      "channel flows.",
      [](ParameterHandler &prm) {
        prm.enter_subsection(section);
        BoxSpaceParameters::declare(prm, "-2, -2", "2, 2", "32, 32");
        prm.declare_entry("Degree",
                          "3",
                          Patterns::Integer(1, max_spline_degree),
                          "Spline degree of every field (>= 3: (H25) needs "
                          "third derivatives of phi_i).");
        prm.declare_entry("Continuity",
                          "-1",
                          Patterns::Integer(-1),
                          "Continuity at the breakpoints (-1: C^{p-1}; at "
                          "least 2).");
        // The Schwarz ILU smoother on the velocity block: the cubic C^2
        // velocity with the grad-div coefficient tau_C of (H19) at
        // Re = 5e-3 is reduced by it in 2.9x fewer FGMRES iterations
        // than by Chebyshev (doc/hydrodynamics.md, "Linear solver").
        FlowSolverDefaults solver_defaults;
        solver_defaults.reuse             = "across-steps";
        solver_defaults.velocity_smoother = "schwarz-ilu";
        solver_defaults.velocity_sweeps   = "2";
        // The consistent viscous mass + C: its count does not double per
        // refinement (35-47 against 94-138 FGMRES iterations per step of
        // HD3 at 32 per unit; doc/hydrodynamics.md, "Linear solver").
        solver_defaults.schur_approximation = "stabilized-cahouet-chabard";
        LinearSolverParameters::declare_flow(prm, solver_defaults);
        prm.enter_subsection("Linear solver");
        prm.enter_subsection("Block preconditioner");
        PhaseFieldBlockParameters::declare(prm);
        prm.leave_subsection();
        prm.leave_subsection();
        prm.declare_entry("Reynolds number",
                          "5e-3",
                          Patterns::Double(),
                          "Re of (H4) (spec 4.9 default).");
        prm.declare_entry("Capillary number",
                          "1e4",
                          Patterns::Double(),
                          "Bending capillary number Ca: the bending force is "
                          "scaled by 1 / (Re Ca) (H3).");
        prm.declare_entry("Interaction number",
                          "0.5",
                          Patterns::Double(),
                          "IN of (H10): the interaction energy is scaled by "
                          "1 / (Re IN).");
        prm.declare_entry("Interaction",
                          "true",
                          Patterns::Bool(),
                          "Whether the interaction energy (H10) acts "
                          "between the vesicles.");
        prm.declare_entry(
          "Global multipliers",
          "extrapolated",
          Patterns::Selection("extrapolated|lagged|implicit"),
          "The values of lambda_g,i and lambda_v,i a step uses. (H13) "
          "gives them from the state at the start of the step. lagged: "
          "those values (the source); the constraint drift then grows by "
          "about dt times the multipliers' rate of change per step. "
          "extrapolated: those values plus dt times their rate over the "
          "last accepted step (the multipliers at the end of the step), "
          "except a multiplier whose rate changed sign over the last two "
          "steps (a limiter: extrapolating an alternation amplifies it); on "
          "prm/doublet-shear-quick.prm the area error after 30 steps falls "
          "from 0.77 % to 0.11 % (doc/hydrodynamics.md). implicit (not in "
          "the source): the step is solved again with its multipliers "
          "iterated (secant, from the extrapolated values) until it ends on "
          "V_i(0), A_i(0) to 'Multiplier tolerance': no drift and no "
          "relaxation, at about 2-3 solves per step (doc/hydrodynamics.md, "
          "\"Implicit global multipliers\").");
        prm.declare_entry("Multiplier tolerance",
                          "1e-5",
                          Patterns::Double(0),
                          "Global multipliers = implicit: the largest relative "
                          "error of V_i, A_i at the end of a step.");
        prm.declare_entry("Multiplier iterations",
                          "8",
                          Patterns::Integer(1),
                          "Global multipliers = implicit: solves of a step "
                          "before it counts as failed (and is retried at dt / "
                          "4).");
        prm.declare_entry(
          "Volume multiplier",
          "indicator",
          Patterns::Selection("membrane|indicator|domain"),
          "Where the volume multiplier lambda_v of (H1), (H13) acts and which "
          "volume it holds. membrane: -lambda_v delta_eps(phi_i) with "
          "delta_eps of (H12b), V_i = int phi_i (the default until "
          "2026-12-07). indicator (the default): the same weight, V_i = int "
          "chi(phi_i) with the smoothed indicator chi = 15/8 (phi - 2 phi^3 "
          "/ 3 + phi^5 / 5), whose variation is that weight, so that (H13) "
          "is a Gram system, well posed for every shape; with 'membrane' its "
          "determinant changes sign near a circle or sphere and the "
          "multipliers diverge there (doc/hydrodynamics.md, \"A Gram form "
          "of (H13)\"). domain: "
          "-lambda_v everywhere, V_i = int phi_i, the source's (H1); phi_i "
          "then rises off -1 in the whole fluid, by about lambda_v / (4 / (Re "
          "Ca eps^3) + 2 lambda_g / eps), and the volume constraint trades the "
          "vesicle's enclosed area against that far field: "
          "prm/doublet-shear-quick.prm loses 12 % of the area inside its zero "
          "level sets in 30 steps with 'domain', while V_i is held to 1e-3 "
          "(doc/hydrodynamics.md, \"Volume multiplier\").");
        prm.declare_entry(
          "Phase field boundary condition",
          "zero normal derivative",
          Patterns::Selection("zero normal derivative|natural"),
          "Condition of phi_i on the non-periodic sides. zero normal "
          "derivative: d phi_i / dn = 0 strongly, with d f_i / dn = 0 "
          "natural, the pair of the source (spec 4.10). natural: no "
          "condition on phi_i; the primal form (H24) then leaves f_i = d f_i "
          "/ dn = 0, under which phase-field boundary layers cost no bending "
          "energy and grow without bound while lambda_g < 0: "
          "prm/hd4a-doublet-shear.prm at 32 per unit fails at t = 0.015 from "
          "the corners of its open sides (doc/hydrodynamics.md, \"Phase-field "
          "boundary condition\"). Kept to reproduce runs made with it.");
        prm.declare_entry("Mobility",
                          "0.1",
                          Patterns::Double(),
                          "eta_phi of (H1).");
        prm.declare_entry("Inextensibility xi",
                          "1",
                          Patterns::Double(),
                          "xi of (H6): regularisation of the tension "
                          "equation.");
        prm.declare_entry("Viscosity ratio",
                          "1",
                          Patterns::Double(),
                          "beta_mu = mu_in / mu_out of (H12a).");
        prm.declare_entry("Epsilon",
                          "0.125",
                          Patterns::Double(),
                          "Interface width eps of (H0) (spec: eps = 2 h).");
        prm.declare_entry(
          "Vesicles",
          "0, 0, 0.863, 0.84, 90",
          Patterns::Anything(),
          "Initial vesicles (H23), separated by ';': 'x, y, R_0, chi, "
          "angle' with centre (x, y), equal-area radius R_0, reduced area "
          "chi (H22) and the angle of the major axis to the x axis in "
          "degrees (90: vertical, the spec's default). In 3D 'x, y, z, R_0, "
          "v, angle': a prolate spheroid of equal-volume radius R_0 and "
          "reduced volume v = 6 sqrt(pi) V / A^(3/2), its long axis in the "
          "x-y plane at the angle to the x axis.");
        prm.declare_entry("Stretch formula",
                          "exact",
                          Patterns::Selection("exact|quadratic-mean"),
                          "gamma_e of (H23) from chi: exact (the ellipse has "
                          "reduced area chi) or the source's quadratic-mean "
                          "perimeter (spec 4.11; 2D only, 3D is exact).");
        prm.declare_entry(
          "Initial distance",
          "radial",
          Patterns::Selection("radial|level-set|exact"),
          "The signed distance d in phi_0 = tanh(-d / (sqrt2 eps)) of "
          "(H23). radial: the spec's distance along the ray from the "
          "centre; for an ellipse phi_0 jumps at the centre by tanh(c / "
          "(sqrt2 eps)) - tanh(a / (sqrt2 eps)) (semi-axes c > a), "
          "negligible once a > 5 eps but not for smaller vesicles, whose "
          "bending energy and multipliers then grow under refinement. "
          "level-set: d = F / |grad F| for the ellipse's quadratic F, with "
          "the same zero set and unit slope on it, smooth everywhere, but "
          "level sets not parallel to it. exact: the true distance to the "
          "ellipse, unit slope and parallel level sets (the equilibrium "
          "tanh profile of the outline, so that the held A(0), V(0) are "
          "those of the relaxed membrane); kinked on the medial axis, "
          "negligible once the minor semi-axis exceeds about 5 eps "
          "(doc/hydrodynamics.md, \"Initial distance\").");
        prm.declare_entry(
          "Mirrored initial phase",
          "false",
          Patterns::Bool(),
          "Make phi_0 compatible with d phi / dn = 0 on the non-periodic "
          "walls: the indicator (1 + phi_0) / 2 summed over each vesicle "
          "and its mirror images in the walls. Without it a membrane closer "
          "than about 5 eps to a wall has d phi_0 / dn != 0 there, and the "
          "constraint makes a layer whose bending energy grows like 1 / h "
          "(doc/hydrodynamics.md, \"Initial distance\").");
        prm.declare_entry("Initial velocity",
                          "0; 0",
                          Patterns::Anything(),
                          "u(x, 0), dim formulas separated by ';' (spec "
                          "4.11: 0, an impulsive start).");
        prm.declare_entry(
          "RBVMS time scale",
          "0",
          Patterns::Double(0),
          "The dt in the transient term 4 / dt^2 of tau_M (H19). 0: the "
          "step being taken (the source's choice) with fixed steps, the "
          "Initial dt with Step control = adaptive; > 0: this fixed value. "
          "A fixed value keeps the discrete equations independent of dt, "
          "which adaptive steps need (doc/hydrodynamics.md).");
        prm.declare_entry("Weak penalty constant",
                          "-1",
                          Patterns::Double(),
                          "C_B of tau_B (H21); <= 0: 5 (p + 1).");
        prm.declare_entry("Weak inflow term",
                          "true",
                          Patterns::Bool(),
                          "Include the inflow term of (H20).");
        prm.declare_entry("Quadrature points",
                          "0",
                          Patterns::Integer(0),
                          "Gauss points per direction; 0: p + 2.");
        prm.declare_entry("Write VTU",
                          "true",
                          Patterns::Bool(),
                          "VTU of u, p, vorticity, phi_i, lambda_i at the "
                          "VTU interval.");
        prm.declare_entry("Write membrane samples",
                          "true",
                          Patterns::Bool(),
                          "tension-<step>.csv at the VTU interval: lambda_i "
                          "and p along the zero level set of every phi_i, "
                          "with arc length (spec 4.12); in 3D along the "
                          "section of the membrane by the plane z = z_i "
                          "through the vesicle's centroid (column z).");
        FlowBoundaryParameters::declare(prm, n_boundaries);
        // The absolute tolerance sits above the round-off floor of the
        // residual: |R| stalls at 2e-10 for the 48k unknowns of HD2 at a
        // steady state, where a step's first residual is 1e-4 and 1e-6 of
        // it asks for less than the floor (with 1e-10 such steps failed
        // after 20 corrections of noise and were retried with dt / 16,
        // which the dt-dependent relaxation of (H13) turned into a
        // disturbance; doc/hydrodynamics.md, "HD2 and HD5 to T = 1").
        // A Jacobian serves two corrections and the next step's first: the
        // Jacobian assembly is two thirds of a step, and the chord
        // corrections converge as fast at dt = 1e-3 (HD4b's first 30 steps:
        // 37 assemblies instead of 70, 125 s instead of 167 s, the state
        // equal to the Newton tolerance; doc/hydrodynamics.md, "Jacobians
        // kept across corrections and steps").
        NewtonParameters::declare(prm, "20", "1e-8", "1e-9", "2", "true");
        prm.enter_subsection("Time stepping");
        TimeLoop::Parameters::declare(prm, {"fixed", "1e-3", "1e-3", "0.01"});
        GeneralizedAlphaParameters::declare(prm, "0.5");
        prm.leave_subsection();
        prm.leave_subsection();
      },
      [](ParameterHandler &prm, RunContext &context) -> std::unique_ptr<Study> {
        if (context.dimension == 2)
          return std::make_unique<VesicleHydrodynamicsStudy<2>>(prm, context);
        return std::make_unique<VesicleHydrodynamicsStudy<3>>(prm, context);
      }};
  }
} // namespace vesicle_iga
