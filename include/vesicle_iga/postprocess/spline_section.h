#pragma once

#include <vesicle_iga/spline/spline_space.h>

#include <vector>

namespace vesicle_iga
{
  /**
   * A plane section z = const of a 3D tensor-product spline field, itself a
   * 2D spline: on the plane the third factor of every basis function is a
   * number, N_ijk(x, y, z) = N_i(x) N_j(y) N_k(z), so the section lives on
   * the first two knot vectors with the coefficients
   * c_ij = sum_k c_ijk N_k(z). Exact (no sampling); the 2D tools, such as
   * zero_contours(), then apply to a section of a 3D field. Used for the
   * 3D membrane samples (tension-<step>.csv in the plane of the centroid).
   */
  struct SplineSection
  {
    SplineSpace<2> space;
    /// Natural numbering of @p space, the components of the 3D field
    /// (component fastest).
    std::vector<double> natural;
  };

  /// The section z = @p z of the field with natural coefficients
  /// @p natural (@p n_components per basis function, component fastest) in
  /// @p space. @p z must lie in the third direction's interval.
  SplineSection
  section_at_z(const SplineSpace<3>      &space,
               const std::vector<double> &natural,
               const unsigned int         n_components,
               const double               z);
} // namespace vesicle_iga
