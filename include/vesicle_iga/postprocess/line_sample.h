#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace vesicle_iga
{

  /**
   * One field of a computed solution sampled at equidistant points of a
   * straight line and written as a two-column CSV (coordinate, value), e.g.
   * the cavity centre lines centerline-u.csv (y, u on x = 0.5). Optionally
   * compared with reference values: the largest deviation at the reference
   * abscissae (solution evaluated there) is reported.
   */
  struct LineSample
  {
    std::string      name;       // file name without .csv; empty: none
    dealii::Point<3> start, end; // only the first dim coordinates are used
    unsigned int     points     = 101;
    unsigned int     coordinate = 1; // the abscissa written: 0 x, 1 y, 2 z
    unsigned int     component  = 0; // of the solution
    std::string      coordinate_name, field_name;
    std::string      reference;  // "" or the name of built-in data
    bool print_integral = false; // print the integral along the line

    static void
    declare(dealii::ParameterHandler &prm, const std::string &field_names);
    /// Reads one "Line sample" subsection; @p dim for the checks.
    void
    parse(dealii::ParameterHandler       &prm,
          const std::string              &parameter_prefix,
          const std::vector<std::string> &field_names,
          const unsigned int              dim);
  };

  /**
   * Reference points (abscissa, value) of built-in data sets:
   * "ghia-1982-re100-u", "ghia-1982-re100-v", "ghia-1982-re1000-u",
   * "ghia-1982-re1000-v": the lid-driven cavity centre-line velocities of
   * Ghia, Ghia and Shin, J. Comput. Phys. 48 (1982), Tables I and II
   * (u on x = 0.5 against y, v on y = 0.5 against x, lid velocity 1).
   */
  std::vector<std::pair<double, double>>
  reference_line_data(const std::string &name);

  /// The names reference_line_data() knows, separated by '|'.
  std::string
  reference_line_data_names();
} // namespace vesicle_iga

#include <vesicle_iga/spline/spline_space.h>

namespace vesicle_iga
{
  /**
   * Samples @p sample of the field with natural coefficients @p natural
   * (n_components per function) on @p space, writes directory/name.csv on
   * rank 0 and returns the largest deviation from the reference data (NaN
   * without reference) and the integral of the field along the line
   * (trapezoidal rule on the samples).
   */
  template <int dim>
  std::pair<double, double>
  write_line_sample(const LineSample          &sample,
                    const SplineSpace<dim>    &space,
                    const std::vector<double> &natural,
                    const unsigned int         n_components,
                    const std::string         &directory,
                    const bool                 root);
} // namespace vesicle_iga
