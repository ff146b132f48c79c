#include <deal.II/base/utilities.h>

#include <vesicle_iga/base/input_error.h>

namespace vesicle_iga
{
  using namespace dealii;

  std::vector<double>
  parse_double_list(const std::string &text, const std::string &parameter)
  {
    try
      {
        return dealii::Utilities::string_to_double(
          dealii::Utilities::split_string_list(text, ','));
      }
    catch (...)
      {
        throw InputError(parameter, text, "a comma-separated list of numbers");
      }
  }
} // namespace vesicle_iga
