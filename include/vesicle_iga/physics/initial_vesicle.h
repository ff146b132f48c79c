#pragma once

#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace vesicle_iga
{
  /**
   * An initial 2D vesicle of spec (H23): an ellipse of equal-area radius
   * R_0 and reduced area chi (H22) centred at x_c, its major axis at an
   * angle to the x axis (90 degrees: vertical, the spec's default), as the
   * phase field phi_0 = tanh(-d / (sqrt2 eps)) with d the signed radial
   * distance to the ellipse along the ray from the centre.
   */
  class InitialVesicle
  {
  public:
    /// How the stretch factor gamma_e follows from chi (spec 4.11):
    /// exact (the ellipse has reduced area chi) or the source's
    /// quadratic-mean approximation of the perimeter.
    enum class StretchFormula
    {
      exact,
      quadratic_mean
    };

    InitialVesicle(const dealii::Point<2> &centre,
                   const double            radius,
                   const double            reduced_area,
                   const double            angle_degrees,
                   const StretchFormula    formula = StretchFormula::exact);

    /// gamma_e: semi-axes R_0 / gamma_e (minor) and gamma_e R_0 (major).
    double
    stretch() const
    {
      return gamma;
    }
    /// The reduced area (H22) of the ellipse actually built.
    double
    actual_reduced_area() const;
    /// The signed radial distance d of (H23) (negative inside).
    double
    signed_distance(const dealii::Point<2> &x) const;
    /// phi_0 of (H23).
    double
    phase_field(const dealii::Point<2> &x, const double eps) const;
    /// n points on the zero level set (for the overlap and boundary
    /// checks and for plots).
    std::vector<dealii::Point<2>>
    outline(const unsigned int n) const;

    /// The perimeter of an ellipse with semi-axes a, b (Gauss-Legendre on
    /// the quarter arc, relative accuracy 1e-14).
    static double
    ellipse_perimeter(const double a, const double b);
    /// gamma_e for reduced area chi.
    static double
    stretch_for(const double chi, const StretchFormula formula);

  private:
    dealii::Point<2> centre;
    double           radius, gamma, angle;
  };
} // namespace vesicle_iga
