#pragma once

#include <deal.II/base/point.h>

#include <vesicle_iga/spline/spline_space.h>

#include <vector>

namespace vesicle_iga
{
  /**
   * A single-patch NURBS geometry map x(xi) = sum_i R_i(xi) P_i with
   * R_i = w_i N_i / sum_j w_j N_j (spec section 2.1, diss. eqs. 3.6-3.8).
   * Analysis is isoparametric: the SplineCellValues of a space use the
   * geometry only if it is defined on the same space, so a study first
   * brings the geometry onto its (refined) analysis space with refined_to(),
   * which is exact because the refined space contains the coarse one.
   */
  template <int dim>
  class NurbsGeometry
  {
  public:
    NurbsGeometry(const SplineSpace<dim>                &space,
                  const std::vector<dealii::Point<dim>> &control_points,
                  const std::vector<double>             &weights);

    const SplineSpace<dim> &
    space() const
    {
      return spline_space;
    }
    const dealii::Point<dim> &
    control_point(const unsigned int i) const
    {
      return points[i];
    }
    double
    weight(const unsigned int i) const
    {
      return weights_[i];
    }
    const std::vector<double> &
    weights() const
    {
      return weights_;
    }

    /// x(xi) by Cox-de Boor evaluation of the homogeneous coordinates.
    dealii::Point<dim>
    point(const dealii::Point<dim> &xi) const;

    /**
     * The same geometry on a finer space (knot insertion, degree elevation
     * or both): the homogeneous control points (w P, w) are the Greville
     * interpolant of the old homogeneous map, which lies in the new space.
     * Throws if the new space does not contain the old one (checked by
     * evaluating both maps at the new Greville points).
     */
    NurbsGeometry<dim>
    refined_to(const SplineSpace<dim> &finer) const;

  private:
    SplineSpace<dim>                spline_space;
    std::vector<dealii::Point<dim>> points;
    std::vector<double>             weights_;
    /// (w P, w) per basis function, computed once: point() is called per
    /// mesh vertex and per boundary interpolation point.
    std::vector<double> homogeneous;
  };
} // namespace vesicle_iga
