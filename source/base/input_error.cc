#include <deal.II/base/utilities.h>

#include <vesicle_iga/base/input_error.h>

#include <cmath>
#include <sstream>

namespace vesicle_iga
{
  using namespace dealii;

  std::string
  value_text(const double value)
  {
    std::ostringstream text;
    text << value;
    return text.str();
  }


  std::vector<double>
  parse_double_list(const std::string &text, const std::string &parameter)
  {
    std::vector<double> values;
    try
      {
        values = dealii::Utilities::string_to_double(
          dealii::Utilities::split_string_list(text, ','));
      }
    catch (...)
      {
        throw InputError(parameter, text, "a comma-separated list of numbers");
      }
    for (const double v : values)
      check_input(std::isfinite(v),
                  parameter,
                  text,
                  "a comma-separated list of finite numbers (no nan or inf)");
    return values;
  }
} // namespace vesicle_iga
