#pragma once

#include <vesicle_iga/physics/hydrodynamic_membrane.h>

namespace vesicle_iga
{
  /**
   * Linear stability of the bulk phases phi = +-1 of a Part H phase field
   * under (H1) with the bending term (H24) and the global area multiplier
   * lambda_g of (H13). A perturbation of wave number k has f = -s dphi with
   * s = eps k^2 + W''(+-1) / eps = eps k^2 + 2 / eps, and grows at
   *
   *   sigma(k) = eta_phi s (-lambda_g - B s / eps),   B = 1 / (Re Ca):
   *
   * the bending term damps it (eta B s^2 / eps), a negative lambda_g (a
   * negative tension) drives it. So the bulk is unstable once lambda_g <
   * -2 B / eps^2 (doc/hydrodynamics.md, "What is missing"); nothing in
   * (H13) prevents that, and the initial data of (H23) can give it for the
   * first steps (doc/hydrodynamics.md, "Initial distance").
   */
  class BulkStability
  {
  public:
    explicit BulkStability(const MembraneCoefficients &membrane);

    /// The largest growth rate max_{k >= 0} sigma(k) of a bulk perturbation
    /// under @p lambda_g; <= 0 when the bulk is stable.
    double
    growth_rate(const double lambda_g) const;

  private:
    double eta, bending, eps;
  };
} // namespace vesicle_iga
