#pragma once

#include <stdexcept>
#include <string>

namespace vesicle_iga
{
  /**
   * The one error of a nonlinear or linear solve that a time step can
   * recover from: Newton did not converge, a residual or an update was not
   * finite, a Krylov method did not converge. The time loop rejects the
   * step and cuts dt; the message says what failed and with which numbers.
   */
  class SolverFailure : public std::runtime_error
  {
  public:
    explicit SolverFailure(const std::string &what)
      : std::runtime_error(what)
    {}
  };
} // namespace vesicle_iga
