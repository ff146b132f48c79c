#pragma once

#include <deal.II/base/parameter_handler.h>

#include <vesicle_iga/spline/spline_space.h>

#include <string>
#include <vector>

namespace vesicle_iga
{
  /**
   * The spline space of an axis-aligned box (subsection "Mesh" of a study):
   * the domain, the breakpoints per direction (uniform, geometrically
   * graded, uniform in a core box and graded outside it, or given
   * explicitly) and the periodic directions. Degree and
   * continuity are chosen by the study. On a box the breakpoints are in
   * physical units: the geometry map is the identity.
   */
  struct BoxSpaceParameters
  {
    std::vector<double>              lower, upper;
    std::vector<unsigned int>        elements;
    std::vector<double>              grading;
    std::vector<std::vector<double>> breakpoints;
    /// Refined core box (empty: none).
    std::vector<double> core_lower, core_upper;
    std::vector<bool>   periodic;
    /// "<study section>/Mesh/": the prefix of the entries in messages.
    std::string message_path = "Mesh/";

    static void
    declare(dealii::ParameterHandler &prm,
            const std::string        &default_lower,
            const std::string        &default_upper,
            const std::string        &default_elements);
    /// Reads and checks the entries of the subsection "Mesh" of the current
    /// subsection, named @p section in the messages (InputError naming the
    /// parameter by its full path).
    void
    parse(dealii::ParameterHandler &prm,
          const unsigned int        dim,
          const std::string        &section);

    template <int dim>
    SplineSpace<dim>
    make_space(const unsigned int degree, const int continuity) const;
  };
} // namespace vesicle_iga
