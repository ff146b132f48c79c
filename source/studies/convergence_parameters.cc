#include <deal.II/base/utilities.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/spline/knot_vector.h>
#include <vesicle_iga/studies/convergence_parameters.h>

namespace vesicle_iga
{
  using namespace dealii;

  void
  ConvergenceParameters::declare(ParameterHandler  &prm,
                                 const std::string &default_degrees,
                                 const std::string &default_refinements,
                                 const std::string &default_extra_points)
  {
    prm.declare_entry("Degrees",
                      default_degrees,
                      Patterns::List(Patterns::Integer(1, max_spline_degree)),
                      "Spline degrees p to study, comma-separated.");
    prm.declare_entry("Continuity",
                      "-1",
                      Patterns::Integer(-1),
                      "Continuity C^k at the interior breakpoints, "
                      "0 <= k <= p-1; -1 means k = p-1 (maximal smoothness) "
                      "for every degree.");
    prm.declare_entry("Refinements",
                      default_refinements,
                      Patterns::Integer(0, 12),
                      "Number of uniform h-refinements (knot insertion at "
                      "element midpoints) after the coarsest mesh.");
    prm.declare_entry("Extra quadrature points",
                      default_extra_points,
                      Patterns::Integer(0, 6),
                      "Gauss points per direction beyond p+1 (assembly; on "
                      "boxes p+1 keeps the rates, doc/verification.md); the "
                      "error norms use two more than that.");
    prm.declare_entry("Write VTU",
                      "true",
                      Patterns::Bool(),
                      "Write the solution on the finest mesh of every degree "
                      "as VTU/PVTU.");
  }


  void
  ConvergenceParameters::parse(ParameterHandler &prm, const unsigned int min_k)
  {
    degrees.clear();
    for (const auto &s : Utilities::split_string_list(prm.get("Degrees")))
      degrees.push_back(Utilities::string_to_int(s));
    continuity              = prm.get_integer("Continuity");
    min_continuity          = min_k;
    refinements             = prm.get_integer("Refinements");
    extra_quadrature_points = prm.get_integer("Extra quadrature points");
    write_vtu               = prm.get_bool("Write VTU");
    check_input(!degrees.empty(), "Degrees", "", "at least one degree");
    for (const unsigned int p : degrees)
      {
        const int k = continuity < 0 ? int(p) - 1 : continuity;
        check_input(k <= int(p) - 1,
                    "Continuity",
                    std::to_string(continuity),
                    "a continuity below every degree (k <= p-1 = "
                      + std::to_string(int(p) - 1) + " for p = "
                      + std::to_string(p) + "), or -1 for k = p-1");
        check_input(k >= int(min_k),
                    min_k > 0 && continuity < 0 ? "Degrees" : "Continuity",
                    min_k > 0 && continuity < 0 ? std::to_string(p) :
                                                  std::to_string(continuity),
                    "a space of at least C^" + std::to_string(min_k)
                      + " for this equation (primal form of a fourth-order "
                        "problem needs H^2-conforming splines): degree p >= "
                      + std::to_string(min_k + 1)
                      + " and continuity k >= " + std::to_string(min_k));
      }
  }
} // namespace vesicle_iga
