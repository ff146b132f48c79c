#pragma once

namespace vesicle_iga
{
  /**
   * Parameters of the first-order generalized-alpha method
   * (Jansen-Whiting-Hulbert), spec (N2)-(N3): second order for any
   * rho_inf in [0,1], unconditionally stable for linear problems.
   */
  struct GeneralizedAlpha
  {
    explicit GeneralizedAlpha(const double rho_inf)
      : rho_inf(rho_inf)
      , alpha_m(0.5 * (3 - rho_inf) / (1 + rho_inf))
      , alpha_f(1 / (1 + rho_inf))
      , gamma(0.5 + alpha_m - alpha_f)
    {}
    double rho_inf, alpha_m, alpha_f, gamma;
  };
} // namespace vesicle_iga
