#pragma once

#include <string>
#include <vector>

namespace vesicle_iga
{
  /**
   * The whole program behind main(): command line, parameter file, choice
   * of study and dimension, errors turned into one clear message and a
   * non-zero exit code. Returns the exit code.
   */
  int
  run_program(const std::vector<std::string> &arguments);
} // namespace vesicle_iga
