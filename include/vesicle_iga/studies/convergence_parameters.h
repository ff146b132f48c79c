#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace vesicle_iga
{

  /// Degrees, continuity and refinement levels of a convergence study.
  struct ConvergenceParameters
  {
    std::vector<unsigned int> degrees;
    int                       continuity;
    unsigned int              min_continuity;
    unsigned int              refinements;
    unsigned int              extra_quadrature_points;
    bool                      write_vtu;

    /// @p default_extra_points: Gauss points beyond p+1 by default (0 on
    /// boxes, where p+1 keeps the rates; NURBS integrands are rational).
    static void
    declare(dealii::ParameterHandler &prm,
            const std::string        &default_degrees,
            const std::string        &default_refinements,
            const std::string        &default_extra_points = "0");
    /// @p min_continuity: the smoothness the equation needs (1 for
    /// fourth-order problems in primal form).
    void
    parse(dealii::ParameterHandler &prm, const unsigned int min_continuity);
  };
} // namespace vesicle_iga
