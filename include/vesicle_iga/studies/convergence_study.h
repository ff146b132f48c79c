#pragma once

#include <vesicle_iga/base/run_context.h>
#include <vesicle_iga/solvers/linear_solver.h>
#include <vesicle_iga/studies/convergence_parameters.h>

#include <functional>
#include <string>
#include <vector>

namespace vesicle_iga
{
  /// What one level (degree p, refinement r) of a convergence study
  /// reports.
  struct ConvergenceLevel
  {
    unsigned int        elements;
    unsigned long long  dofs;
    double              h;
    std::vector<double> errors;
    LinearSolveResult   solve;
  };


  /**
   * The loop of every convergence study (Poisson, biharmonic, the plate
   * with a hole): for each degree of @p convergence and refinement level
   * 0..refinements, @p solve_level builds, solves and measures one
   * discretisation (and writes its VTU when it wants to); this function
   * adds the row, prints the progress line and ends with the table and
   * convergence.csv (ConvergenceStudyTable::report), so that a study holds
   * only its own problem. @p legend, if not empty, is printed before the
   * table (what the norms are).
   */
  void
  run_convergence_study(
    const RunContext               &context,
    const unsigned int              dim,
    const ConvergenceParameters    &convergence,
    const std::vector<std::string> &norm_names,
    const std::function<ConvergenceLevel(unsigned int, unsigned int)>
                      &solve_level,
    const std::string &legend = "");
} // namespace vesicle_iga
