// Shared by the circle and ellipse relaxation tests: the outcome checks of
// a short constrained Willmore flow, stated so that round-off (which moves
// the adaptive steps and the iteration counts with the CPU) cannot change
// them; no step count, dt or last digit is printed.
#pragma once

#include <cmath>
#include <ostream>
#include <string>

#include "../time_series_comparison.h"

/// The number after @p key in @p line (NaN if absent).
inline double
number_after(const std::string &line, const std::string &key)
{
  const auto pos = line.find(key);
  return pos == std::string::npos ? std::nan("") :
                                    std::stod(line.substr(pos + key.size()));
}

/// Checks common to both flows: every accepted step keeps area and volume
/// within the ALM tolerance 1e-4 (spec 3.8); the run is a gradient flow of
/// the Lagrangian, which never rises between accepted steps (relative 1e-8,
/// the Newton tolerance; the study prints the largest increase), and the
/// bending energy ends below its start.
inline void
check_gradient_flow(std::ostream          &out,
                    const StudyRun        &run,
                    const NamedTimeSeries &series,
                    const unsigned int     steps)
{
  bool constraints = series.rows.size() == steps;
  for (unsigned int i = 0; i < series.rows.size(); ++i)
    constraints = constraints && std::abs(series.value("area_error", i)) <= 1e-4
                  && std::abs(series.value("volume_error", i)) <= 1e-4;
  const std::string increase   = run.line_starting_with("largest relative");
  const double      energy     = number_after(increase, "energy ");
  const double      lagrangian = number_after(increase, "Lagrangian ");
  out << "exit code " << run.exit_code << ", " << steps
      << " accepted steps, |A/A0 - 1| and |V/V0 - 1| within 1e-4 at each: "
      << (constraints ? "yes" : "NO") << '\n'
      << "largest relative increase of the energy and of the Lagrangian over "
         "a step below 1e-8: "
      << (energy <= 1e-8 && lagrangian <= 1e-8 ? "yes" : "NO") << '\n'
      << "E_B at the end below E_B at the first step: "
      << (series.value("bending_energy") < series.value("bending_energy", 0) ?
            "yes" :
            "NO")
      << '\n';
}
