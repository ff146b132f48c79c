#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/io/checked_output.h>
#include <vesicle_iga/postprocess/line_sample.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>

namespace vesicle_iga
{
  using namespace dealii;

  void
  LineSample::declare(ParameterHandler &prm, const std::string &field_names)
  {
    prm.declare_entry("Name",
                      "",
                      Patterns::Anything(),
                      "CSV file name (without .csv) of the samples; empty: "
                      "this line is not sampled.");
    prm.declare_entry("Start", "0, 0", Patterns::Anything(), "First point.");
    prm.declare_entry("End", "1, 0", Patterns::Anything(), "Last point.");
    prm.declare_entry("Points",
                      "101",
                      Patterns::Integer(2),
                      "Number of equidistant points.");
    prm.declare_entry("Coordinate",
                      "y",
                      Patterns::Selection("x|y|z"),
                      "The coordinate written as the first column.");
    prm.declare_entry("Field",
                      "u",
                      Patterns::Selection(field_names),
                      "The field written as the second column.");
    prm.declare_entry("Print integral",
                      "false",
                      Patterns::Bool(),
                      "Print the integral of the field along the line "
                      "(trapezoidal rule on the samples), e.g. the flux "
                      "through an outlet.");
    prm.declare_entry("Reference",
                      "",
                      Patterns::Anything(),
                      "Reference values to compare with (largest deviation "
                      "printed): empty, 'function: <formula in x, y, z>' "
                      "(compared at every sample point) or one of "
                        + reference_line_data_names() + ".");
  }


  void
  LineSample::parse(ParameterHandler               &prm,
                    const std::string              &prefix,
                    const std::vector<std::string> &field_names,
                    const unsigned int              dim)
  {
    name = prm.get("Name");
    // An unnamed slot is unused: its (2D) defaults must not stop a 3D run.
    if (name.empty())
      return;
    for (const auto &[entry, point] :
         {std::make_pair("Start", &start), std::make_pair("End", &end)})
      {
        const std::string         text = prm.get(entry);
        const std::vector<double> v = parse_double_list(text, prefix + entry);
        check_input(v.size() == dim,
                    prefix + entry,
                    text,
                    std::to_string(dim) + " comma-separated coordinates");
        for (unsigned int d = 0; d < dim; ++d)
          (*point)[d] = v[d];
      }
    points          = prm.get_integer("Points");
    coordinate_name = prm.get("Coordinate");
    coordinate      = coordinate_name[0] - 'x';
    check_input(coordinate < dim,
                prefix + "Coordinate",
                coordinate_name,
                "a coordinate of the " + std::to_string(dim) + "D domain");
    // The samples (and the reference data) are written against this
    // coordinate, so it must change along the line.
    check_input(start[coordinate] != end[coordinate],
                prefix + "End",
                prm.get("End"),
                "a point whose " + coordinate_name
                  + " differs from that of Start (the samples are written "
                    "against "
                  + coordinate_name + ")");
    field_name = prm.get("Field");
    component  = std::find(field_names.begin(), field_names.end(), field_name)
                - field_names.begin();
    check_input(component < field_names.size(),
                prefix + "Field",
                field_name,
                "a field of the " + std::to_string(dim) + "D solution");
    print_integral = prm.get_bool("Print integral");
    reference      = prm.get("Reference");
    if (reference.rfind("function:", 0) == 0)
      {
        // Checked by evaluating once.
        FunctionParser<3> f(1);
        try
          {
            f.initialize("x,y,z", reference.substr(9), {{"pi", M_PI}});
            f.value(Point<3>());
          }
        catch (...)
          {
            check_input(false,
                        prefix + "Reference",
                        reference,
                        "'function: <formula in x, y, z>' or a built-in data "
                        "set");
          }
      }
    else if (!reference.empty())
      {
        const auto names
          = Utilities::split_string_list(reference_line_data_names(), '|');
        check_input(std::find(names.begin(), names.end(), reference)
                      != names.end(),
                    prefix + "Reference",
                    reference,
                    "empty, 'function: <formula in x, y, z>' or one of "
                      + reference_line_data_names());
      }
  }


  namespace
  {
    // Ghia, Ghia and Shin (1982), Table I (u on x = 0.5) and Table II (v on
    // y = 0.5), at the 17 points listed there.
    const std::vector<double> ghia_y      = {0.0000,
                                             0.0547,
                                             0.0625,
                                             0.0703,
                                             0.1016,
                                             0.1719,
                                             0.2813,
                                             0.4531,
                                             0.5000,
                                             0.6172,
                                             0.7344,
                                             0.8516,
                                             0.9531,
                                             0.9609,
                                             0.9688,
                                             0.9766,
                                             1.0000};
    const std::vector<double> ghia_x      = {0.0000,
                                             0.0625,
                                             0.0703,
                                             0.0781,
                                             0.0938,
                                             0.1563,
                                             0.2266,
                                             0.2344,
                                             0.5000,
                                             0.8047,
                                             0.8594,
                                             0.9063,
                                             0.9453,
                                             0.9531,
                                             0.9609,
                                             0.9688,
                                             1.0000};
    const std::vector<double> ghia_u_100  = {0.00000,
                                             -0.03717,
                                             -0.04192,
                                             -0.04775,
                                             -0.06434,
                                             -0.10150,
                                             -0.15662,
                                             -0.21090,
                                             -0.20581,
                                             -0.13641,
                                             0.00332,
                                             0.23151,
                                             0.68717,
                                             0.73722,
                                             0.78871,
                                             0.84123,
                                             1.00000};
    const std::vector<double> ghia_u_1000 = {0.00000,
                                             -0.18109,
                                             -0.20196,
                                             -0.22220,
                                             -0.29730,
                                             -0.38289,
                                             -0.27805,
                                             -0.10648,
                                             -0.06080,
                                             0.05702,
                                             0.18719,
                                             0.33304,
                                             0.46604,
                                             0.51117,
                                             0.57492,
                                             0.65928,
                                             1.00000};
    const std::vector<double> ghia_v_100  = {0.00000,
                                             0.09233,
                                             0.10091,
                                             0.10890,
                                             0.12317,
                                             0.16077,
                                             0.17507,
                                             0.17527,
                                             0.05454,
                                             -0.24533,
                                             -0.22445,
                                             -0.16914,
                                             -0.10313,
                                             -0.08864,
                                             -0.07391,
                                             -0.05906,
                                             0.00000};
    const std::vector<double> ghia_v_1000 = {0.00000,
                                             0.27485,
                                             0.29012,
                                             0.30353,
                                             0.32627,
                                             0.37095,
                                             0.33075,
                                             0.32235,
                                             0.02526,
                                             -0.31966,
                                             -0.42665,
                                             -0.51550,
                                             -0.39188,
                                             -0.33714,
                                             -0.27669,
                                             -0.21388,
                                             0.00000};
  } // namespace


  std::string
  reference_line_data_names()
  {
    return "ghia-1982-re100-u|ghia-1982-re100-v|ghia-1982-re1000-u|"
           "ghia-1982-re1000-v";
  }


  std::vector<std::pair<double, double>>
  reference_line_data(const std::string &name)
  {
    const std::vector<double> *x = nullptr, *v = nullptr;
    if (name == "ghia-1982-re100-u")
      x = &ghia_y, v = &ghia_u_100;
    else if (name == "ghia-1982-re1000-u")
      x = &ghia_y, v = &ghia_u_1000;
    else if (name == "ghia-1982-re100-v")
      x = &ghia_x, v = &ghia_v_100;
    else if (name == "ghia-1982-re1000-v")
      x = &ghia_x, v = &ghia_v_1000;
    check_input(x != nullptr,
                "Line sample/Reference",
                name,
                "empty or one of " + reference_line_data_names());
    std::vector<std::pair<double, double>> data;
    for (unsigned int i = 0; i < x->size(); ++i)
      data.emplace_back((*x)[i], (*v)[i]);
    return data;
  }


  template <int dim>
  std::pair<double, double>
  write_line_sample(const LineSample          &sample,
                    const SplineSpace<dim>    &space,
                    const std::vector<double> &natural,
                    const unsigned int         n_components,
                    const std::string         &directory,
                    const bool                 root)
  {
    // The spaces of the studies live on axis-aligned boxes: parametric and
    // physical coordinates agree.
    std::vector<double> values;
    const auto          value_at = [&](const Point<dim> &x) {
      space.evaluate(natural, n_components, x, values);
      return values[sample.component];
    };
    const auto point_on_line = [&](const double s) {
      Point<dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = sample.start[d] + s * (sample.end[d] - sample.start[d]);
      return x;
    };
    if (root)
      {
        const std::string name = directory + "/" + sample.name + ".csv";
        std::ofstream     f(name);
        f << sample.coordinate_name << ',' << sample.field_name << '\n'
          << std::setprecision(10);
        for (unsigned int i = 0; i < sample.points; ++i)
          {
            const Point<dim> x = point_on_line(double(i) / (sample.points - 1));
            f << x[sample.coordinate] << ',' << value_at(x) << '\n';
          }
        check_written(f, name);
      }
    double integral = 0, length = 0;
    for (unsigned int d = 0; d < dim; ++d)
      length += std::pow(sample.end[d] - sample.start[d], 2);
    length = std::sqrt(length);
    for (unsigned int i = 0; i < sample.points; ++i)
      integral += (i == 0 || i + 1 == sample.points ? 0.5 : 1.)
                  * value_at(point_on_line(double(i) / (sample.points - 1)));
    integral *= length / (sample.points - 1);
    if (sample.reference.empty())
      return {std::numeric_limits<double>::quiet_NaN(), integral};
    double deviation = 0;
    if (sample.reference.rfind("function:", 0) == 0)
      {
        FunctionParser<3> f(1);
        f.initialize("x,y,z", sample.reference.substr(9), {{"pi", M_PI}});
        for (unsigned int i = 0; i < sample.points; ++i)
          {
            const Point<dim> x = point_on_line(double(i) / (sample.points - 1));
            Point<3>         x3;
            for (unsigned int d = 0; d < dim; ++d)
              x3[d] = x[d];
            deviation
              = std::max(deviation, std::abs(value_at(x) - f.value(x3)));
          }
        return {deviation, integral};
      }
    // At each reference abscissa: the point of the line with that
    // coordinate.
    const auto a = sample.start[sample.coordinate],
               b = sample.end[sample.coordinate];
    // The reference points also go to name-reference.csv (for
    // tools/plot-line-samples.py).
    if (root)
      {
        const std::string name
          = directory + "/" + sample.name + "-reference.csv";
        std::ofstream f(name);
        f << sample.coordinate_name << ',' << sample.field_name << '\n';
        for (const auto &[c, v] : reference_line_data(sample.reference))
          f << c << ',' << v << '\n';
        check_written(f, name);
      }
    for (const auto &[c, v] : reference_line_data(sample.reference))
      deviation
        = std::max(deviation,
                   std::abs(value_at(point_on_line((c - a) / (b - a))) - v));
    return {deviation, integral};
  }


  template std::pair<double, double>
  write_line_sample(const LineSample &,
                    const SplineSpace<2> &,
                    const std::vector<double> &,
                    const unsigned int,
                    const std::string &,
                    const bool);
  template std::pair<double, double>
  write_line_sample(const LineSample &,
                    const SplineSpace<3> &,
                    const std::vector<double> &,
                    const unsigned int,
                    const std::string &,
                    const bool);
} // namespace vesicle_iga
