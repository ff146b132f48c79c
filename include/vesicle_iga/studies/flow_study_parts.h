#pragma once

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <vesicle_iga/io/spline_output.h>
#include <vesicle_iga/models/incompressible_flow.h>

#include <memory>
#include <string>
#include <vector>

namespace vesicle_iga
{
  /**
   * A vector-valued formula of a .prm ("expr_1; expr_2[; expr_3]" in x, y,
   * z and t, constants pi and Re) with @p extra trailing zero components;
   * errors name the parameter. Derivatives by fourth-order differences.
   */
  template <int dim>
  std::shared_ptr<dealii::FunctionParser<dim>>
  parse_formula(const std::string &text,
                const unsigned int n_components,
                const unsigned int extra,
                const double       reynolds_number,
                const std::string &parameter);


  /**
   * The velocity boundaries of a flow study (spec 4.10): subsections
   * "Boundary 1" .. "Boundary n", each with Type (none, strong, weak,
   * outflow), Where (a BoundarySelection) and Velocity (formulas), and the
   * Pressure level. Used by every study with a flow.
   */
  struct FlowBoundaryParameters
  {
    static void
    declare(dealii::ParameterHandler &prm, const unsigned int n_boundaries);
    void
    parse(dealii::ParameterHandler &prm, const unsigned int n_boundaries);

    /// The conditions (errors name @p prefix "Boundary k/..."); @p
    /// level_fixed: whether a stress-free boundary fixes the pressure level
    /// (a boundary of type outflow, or an open face no boundary names).
    template <int dim>
    std::vector<VelocityCondition<dim>>
    conditions(const std::string       &prefix,
               const double             reynolds_number,
               const std::vector<bool> &periodic,
               bool                    &level_fixed) const;
    /// Whether the pressure gets zero mean ('Pressure level').
    bool
    fix_pressure_mean(const bool level_fixed) const
    {
      return pressure_level == "mean zero"
             || (pressure_level == "auto" && !level_fixed);
    }

    struct Entry
    {
      std::string type, where, velocity;
    };
    std::vector<Entry> entries;
    std::string        pressure_level;
  };


  /// Velocity components, pressure and vorticity (2D: the scalar; 3D: its
  /// magnitude) in the VTU output; the velocity is components 0..dim-1 and
  /// the pressure component dim of the solution; @p more: names of the
  /// components after the pressure.
  template <int dim>
  void
  add_flow_output_fields(SplineFieldWriter<dim>         &writer,
                         const std::vector<std::string> &more = {});
} // namespace vesicle_iga
