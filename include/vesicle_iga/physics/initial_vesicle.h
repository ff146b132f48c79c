#pragma once

#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace vesicle_iga
{
  /// What the initial vesicles of any dimension share: how the stretch
  /// factor follows from the reduced area or volume, and the geometry of
  /// ellipses and prolate spheroids it needs.
  struct InitialVesicleBase
  {
    /// How the stretch factor gamma_e follows from chi (spec 4.11):
    /// exact (the ellipse has reduced area chi) or the source's
    /// quadratic-mean approximation of the perimeter (2D only).
    enum class StretchFormula
    {
      exact,
      quadratic_mean
    };

    /// The perimeter of an ellipse with semi-axes a, b (Gauss-Legendre on
    /// the quarter arc, relative accuracy 1e-14).
    static double
    ellipse_perimeter(const double a, const double b);
    /// The area of a prolate spheroid with polar semi-axis c >= equatorial
    /// semi-axis a (closed form).
    static double
    prolate_spheroid_area(const double c, const double a);
  };


  /**
   * An initial vesicle of spec (H23), built as the phase field phi_0 =
   * tanh(-d / (sqrt2 eps)) with d the signed radial distance to the
   * surface along the ray from the centre x_c.
   *
   * - 2D: an ellipse of equal-area radius R_0 and reduced area chi (H22),
   *   semi-axes R_0 / gamma_e (minor) and gamma_e R_0 (major), its major
   *   axis at an angle to the x axis (90 degrees: vertical, the spec's
   *   default).
   * - 3D (spec Part H is written dimension-independently; its studies are
   *   2D): a prolate spheroid of equal-volume radius R_0 and reduced volume
   *   v = 6 sqrt(pi) V / A^{3/2}, polar semi-axis gamma_e^2 R_0 along the
   *   direction at the angle to the x axis in the x-y plane (the shear
   *   plane of the studies), equatorial semi-axes R_0 / gamma_e.
   */
  template <int dim>
  class InitialVesicle : public InitialVesicleBase
  {
  public:
    /// @p reduced is chi (2D) or v (3D), in (0, 1].
    InitialVesicle(const dealii::Point<dim> &centre,
                   const double              radius,
                   const double              reduced,
                   const double              angle_degrees,
                   const StretchFormula      formula = StretchFormula::exact);

    /// gamma_e (see the class description).
    double
    stretch() const
    {
      return gamma;
    }
    /// The reduced area (2D) or reduced volume (3D) of the shape actually
    /// built.
    double
    actual_reduced_measure() const;
    /// The signed radial distance d of (H23) (negative inside).
    double
    signed_distance(const dealii::Point<dim> &x) const;
    /// phi_0 of (H23).
    double
    phase_field(const dealii::Point<dim> &x, const double eps) const;
    /// About n points on the zero level set (for the overlap and boundary
    /// checks and for plots): equally spaced in the parameter angle in 2D,
    /// a latitude-longitude grid in 3D.
    std::vector<dealii::Point<dim>>
    outline(const unsigned int n) const;

    /// gamma_e for reduced area (2D) or volume (3D) @p reduced; the
    /// quadratic-mean formula exists in 2D only.
    static double
    stretch_for(const double reduced, const StretchFormula formula);

  private:
    /// The unit vectors along the major axis and the minor axes.
    dealii::Tensor<1, dim>
    major_axis() const;
    dealii::Tensor<1, dim>
    minor_axis(const unsigned int k) const;
    /// The semi-axes: major, minor.
    double
    major_semi_axis() const;
    double
    minor_semi_axis() const;

    dealii::Point<dim> centre;
    double             radius, gamma, angle;
  };
} // namespace vesicle_iga
