#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace vesicle_iga
{
  /**
   * The one exception the program throws for bad user input. It always names
   * the parameter, the value that was given and what would have been allowed,
   * so that the message printed by main() tells the user how to fix the .prm
   * file without reading the source.
   */
  class InputError : public std::runtime_error
  {
  public:
    InputError(const std::string &parameter,
               const std::string &value,
               const std::string &allowed)
      : std::runtime_error("Invalid value of parameter '" + parameter + "': '"
                           + value + "'. Allowed: " + allowed + ".")
    {}
  };

  /// Throw an InputError when @p condition is false.
  inline void
  check_input(const bool         condition,
              const std::string &parameter,
              const std::string &value,
              const std::string &allowed)
  {
    if (!condition)
      throw InputError(parameter, value, allowed);
  }

  /// @p value as the user wrote it in a .prm file (1e-14, not 0.000000), for
  /// the value and limits in InputError messages.
  std::string
  value_text(double value);

  /// A comma-separated list of numbers from a .prm entry; InputError
  /// naming @p parameter otherwise.
  std::vector<double>
  parse_double_list(const std::string &text, const std::string &parameter);
} // namespace vesicle_iga
