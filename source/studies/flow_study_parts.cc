// Parameter pieces shared by the studies with a flow: formulas, velocity
// boundaries (spec 4.10), the flow's VTU fields.

#include <deal.II/base/utilities.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/studies/flow_study_parts.h>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  std::shared_ptr<FunctionParser<dim>>
  parse_formula(const std::string &text,
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


  void
  FlowBoundaryParameters::declare(ParameterHandler  &prm,
                                  const unsigned int n_boundaries)
  {
    prm.declare_entry(
      "Pressure level",
      "auto",
      Patterns::Selection("auto|mean zero|free"),
      "How the pressure constant is fixed: 'mean zero' pins one control "
      "value and reports the zero-mean pressure; 'free' leaves it to "
      "a stress-free boundary; 'auto': mean zero unless some boundary is "
      "stress-free (type outflow, or a face no condition names).");
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
  }


  void
  FlowBoundaryParameters::parse(ParameterHandler  &prm,
                                const unsigned int n_boundaries)
  {
    pressure_level = prm.get("Pressure level");
    entries.clear();
    for (unsigned int b = 1; b <= n_boundaries; ++b)
      {
        prm.enter_subsection("Boundary " + std::to_string(b));
        entries.push_back(
          {prm.get("Type"), prm.get("Where"), prm.get("Velocity")});
        prm.leave_subsection();
      }
  }


  template <int dim>
  std::vector<VelocityCondition<dim>>
  FlowBoundaryParameters::conditions(const std::string       &prefix,
                                     const double             reynolds_number,
                                     const std::vector<bool> &periodic,
                                     bool                    &level_fixed) const
  {
    std::vector<VelocityCondition<dim>> result;
    std::array<bool, 2 * dim>           face_touched{};
    level_fixed = false;
    for (unsigned int b = 0; b < entries.size(); ++b)
      {
        const auto       &e    = entries[b];
        const std::string name = prefix + "Boundary " + std::to_string(b + 1);
        const BoundarySelection<dim> where(e.where, name + "/Where");
        for (unsigned int f = 0; f < 2 * dim; ++f)
          face_touched[f] = face_touched[f] || where.touches_face(f);
        if (e.type == "outflow")
          level_fixed = true;
        else if (e.type == "strong" || e.type == "weak")
          result.push_back(
            {where,
             parse_formula<dim>(
               e.velocity, dim, 1, reynolds_number, name + "/Velocity"),
             e.type == "weak"});
      }
    // A face of an open direction that no condition names is stress-free.
    for (unsigned int f = 0; f < 2 * dim; ++f)
      if (!periodic[f / 2] && !face_touched[f])
        level_fixed = true;
    return result;
  }


  template <int dim>
  void
  add_flow_output_fields(SplineFieldWriter<dim>         &writer,
                         const std::vector<std::string> &more)
  {
    std::vector<std::string> names;
    for (unsigned int a = 0; a < dim; ++a)
      names.push_back(std::string("u_") + "xyz"[a]);
    names.push_back("p");
    names.insert(names.end(), more.begin(), more.end());
    writer.add_components(names);
    writer.add_quantity(
      "vorticity",
      [](const SplineCellValues<dim>            &v,
         const unsigned int                      q,
         const std::vector<std::vector<double>> &c) {
        const Tensor<1, dim> gu = v.gradient(c[0], q), gv = v.gradient(c[1], q);
        if (dim == 2)
          return gv[0] - gu[1];
        const Tensor<1, dim> gw = v.gradient(c[2], q);
        return std::sqrt(std::pow(gw[1] - gv[2], 2) + std::pow(gu[2] - gw[0], 2)
                         + std::pow(gv[0] - gu[1], 2));
      },
      1);
  }

  template std::shared_ptr<FunctionParser<2>>
  parse_formula<2>(const std::string &,
                   const unsigned int,
                   const unsigned int,
                   const double,
                   const std::string &);
  template std::shared_ptr<FunctionParser<3>>
  parse_formula<3>(const std::string &,
                   const unsigned int,
                   const unsigned int,
                   const double,
                   const std::string &);
  template std::vector<VelocityCondition<2>>
  FlowBoundaryParameters::conditions<2>(const std::string &,
                                        const double,
                                        const std::vector<bool> &,
                                        bool &) const;
  template std::vector<VelocityCondition<3>>
  FlowBoundaryParameters::conditions<3>(const std::string &,
                                        const double,
                                        const std::vector<bool> &,
                                        bool &) const;
  template void
  add_flow_output_fields<2>(SplineFieldWriter<2> &,
                            const std::vector<std::string> &);
  template void
  add_flow_output_fields<3>(SplineFieldWriter<3> &,
                            const std::vector<std::string> &);
} // namespace vesicle_iga
