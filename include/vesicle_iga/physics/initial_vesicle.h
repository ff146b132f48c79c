#pragma once

#include <deal.II/base/point.h>

#include <array>
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

    /// The signed distance d in phi_0 = tanh(-d / (sqrt2 eps)):
    /// - radial: (H23), the distance to the surface along the ray from the
    ///   centre. Exact for a circle, but for an ellipse d tends to -R_0 r /
    ///   rho at the centre, which depends on the direction: phi_0 jumps
    ///   there by centre_jump(), and its bending energy grows like 1 / h^2
    ///   under refinement once that jump is resolved (doc/hydrodynamics.md,
    ///   "Initial distance").
    /// - level_set: d = F / |grad F| with F = sum_k (x'_k / a_k)^2 - 1 in
    ///   the axes' coordinates: zero on the same ellipse (ellipsoid), |grad
    ///   d| = 1 on it, smooth everywhere, and d -> -infinity at the centre
    ///   (phi_0 -> 1 with all its derivatives). Away from the surface it is
    ///   the distance to first order only: d = (r^2 - R^2) / (2 r) for a
    ///   circle.
    /// - exact: the true signed distance to the ellipse (spheroid), with
    ///   unit slope and parallel level sets, so that phi_0 is the
    ///   equilibrium tanh profile of the outline; its kink on the medial
    ///   axis (the segment between the centres of curvature of the tips)
    ///   enters phi_0 with the weight sech^2(l / (sqrt2 eps)), l the
    ///   distance of the axis from the outline, and gives a bending energy
    ///   that grows like 1 / h once resolved: measured negligible for
    ///   minor semi-axes of 5 eps and more, not for 2.5 eps
    ///   (doc/hydrodynamics.md, "Initial distance").
    enum class DistanceFormula
    {
      radial,
      level_set,
      exact
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
                   const StretchFormula      formula = StretchFormula::exact,
                   const DistanceFormula distance    = DistanceFormula::radial);

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
    /// The signed distance d of the DistanceFormula chosen (negative
    /// inside; -infinity at the centre for the level-set distance).
    double
    signed_distance(const dealii::Point<dim> &x) const;
    /// How much phi_0 of the radial distance (H23) jumps at the centre:
    /// tanh(c / (sqrt2 eps)) - tanh(a / (sqrt2 eps)) with c, a the major
    /// and minor semi-axes (0 for the level-set distance and for a circle).
    double
    centre_jump(const double eps) const;
    /// The largest |grad d| on the outline (central differences at 401
    /// points of a meridian): 1 for the level-set distance, sqrt(1 +
    /// (rho' / rho)^2) for the radial one (rho(theta) the outline's
    /// radius; 1.25 for chi = 0.84, 1.87 for chi = 0.6). Above 1, phi_0 is
    /// steeper there than the equilibrium profile: its bending energy
    /// grows like 1 / eps^2 at a fixed shape, and the diffuse area A_i(0)
    /// that (H13) holds is larger than the relaxed membrane's
    /// (doc/hydrodynamics.md, "Initial distance").
    double
    outline_slope() const;
    /// phi_0 of (H23).
    double
    phase_field(const dealii::Point<dim> &x, const double eps) const;
    /// phi_0 made compatible with d phi / dn = 0 on the walls of the box
    /// [lower, upper] normal to the directions of @p mirror: the indicator
    /// (1 + phi_0) / 2 summed over the vesicle and its mirror images in
    /// those walls (corner images included), so that its normal derivative
    /// vanishes on each wall up to the image of the opposite wall's image,
    /// exp(-2 L / (sqrt2 eps)) for a box of width L. Without it, a membrane
    /// a few eps from a wall has d phi_0 / dn != 0 there; the constraint
    /// cuts that slope in a layer of width h, whose bending energy grows
    /// like 1 / h (doc/hydrodynamics.md, "Initial distance").
    double
    mirrored_phase_field(const dealii::Point<dim>    &x,
                         const double                 eps,
                         const dealii::Point<dim>    &lower,
                         const dealii::Point<dim>    &upper,
                         const std::array<bool, dim> &mirror) const;
    /// The smallest distance from the outline to a wall of the box normal
    /// to the directions of @p mirror (infinity if there are none).
    double
    wall_gap(const dealii::Point<dim>    &lower,
             const dealii::Point<dim>    &upper,
             const std::array<bool, dim> &mirror) const;
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

    double
    radial_distance(const dealii::Point<dim> &x) const;
    double
    level_set_distance(const dealii::Point<dim> &x) const;
    double
    exact_distance(const dealii::Point<dim> &x) const;

    dealii::Point<dim> centre;
    double             radius, gamma, angle;
    DistanceFormula    distance;
  };
} // namespace vesicle_iga
