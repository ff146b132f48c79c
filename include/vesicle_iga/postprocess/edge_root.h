#pragma once

#include <cmath>

namespace vesicle_iga
{
  /**
   * The zero of a function along an edge, t in [0, 1], from its values f0
   * at t = 0 and f1 at t = 1 of opposite signs, by the Illinois variant of
   * regula falsi: @p f(t) is evaluated until |f| <= @p tolerance or the
   * bracket is below 1e-15. Used to place level-set crossings on the
   * spline itself rather than on a linear interpolant (zero_contours(),
   * zero_set_measures()).
   */
  template <typename Function>
  double
  edge_root(const Function &f, double f0, double f1, const double tolerance)
  {
    double t0 = 0, t1 = 1, t = 0.5;
    int    side = 0;
    for (unsigned int it = 0; it < 60; ++it)
      {
        t               = (t0 * f1 - t1 * f0) / (f1 - f0);
        const double ft = f(t);
        if (std::abs(ft) <= tolerance || t1 - t0 < 1e-15)
          break;
        if ((ft >= 0) == (f0 >= 0))
          {
            t0 = t;
            f0 = ft;
            if (side == -1)
              f1 /= 2;
            side = -1;
          }
        else
          {
            t1 = t;
            f1 = ft;
            if (side == 1)
              f0 /= 2;
            side = 1;
          }
      }
    return t;
  }
} // namespace vesicle_iga
