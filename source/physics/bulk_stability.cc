// Linear stability of the bulk phases of Part H under (H1), (H13), (H24).
#include <vesicle_iga/physics/bulk_stability.h>

#include <algorithm>

namespace vesicle_iga
{
  BulkStability::BulkStability(const MembraneCoefficients &membrane)
    : eta(membrane.mobility)
    , bending(membrane.bending_factor())
    , eps(membrane.epsilon)
  {}


  double
  BulkStability::growth_rate(const double lambda_g) const
  {
    // sigma(s) = eta s (-lambda_g - B s / eps) is a parabola in s with its
    // vertex at s* = -lambda_g eps / (2 B); s >= 2 / eps (k = 0) bounds it.
    const double s_min = 2 / eps;
    const double s     = std::max(-lambda_g * eps / (2 * bending), s_min);
    return eta * s * (-lambda_g - bending * s / eps);
  }
} // namespace vesicle_iga
