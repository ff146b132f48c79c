#pragma once

#include <deal.II/base/point.h>

#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/spline_dof_handler.h>
#include <vesicle_iga/spline/spline_space.h>

#include <string>
#include <vector>

namespace vesicle_iga
{
  /**
   * A piece of the zero level set of a 2D spline field: its points in
   * order (counter-clockwise for a closed curve, whose first point is
   * repeated at the end), their arc length from the first point, and the
   * values of all components of the field at each point.
   */
  struct ZeroContour
  {
    std::vector<dealii::Point<2>>    points;
    std::vector<double>              arc_length;
    std::vector<std::vector<double>> values;
    bool                             closed = false;

    double
    length() const
    {
      return arc_length.empty() ? 0. : arc_length.back();
    }
    /// Area enclosed by a closed curve (shoelace over its points, positive
    /// counter-clockwise); 0 for an open one.
    double
    enclosed_area() const;
    /// 4 pi A / L^2 of a closed curve (1 for a circle); 0 for an open one.
    double
    reduced_area() const;
  };


  /**
   * The zero level set of component @p component of a 2D spline field
   * (natural coefficients, @p n_components per basis function, component
   * fastest): marching squares on a grid of @p samples_per_element cells per
   * element and direction, every crossing placed on its grid edge by regula
   * falsi on the spline itself (so the points lie on the spline's zero set to
   * 1e-12 of the field's range, not on a linear interpolant), the saddle
   * cells resolved by the cell-centre value, and the segments chained into
   * curves (closed, or open where the set leaves the domain). Only elements
   * whose coefficients change sign are sampled: a B-spline lies in the
   * convex hull of its coefficients, so no other element holds a crossing. Used
   * for the membrane samples of spec 4.12 (lambda_i and p along phi_i = 0).
   * Longest piece first.
   */
  std::vector<ZeroContour>
  zero_contours(const SplineSpace<2>      &space,
                const std::vector<double> &natural,
                const unsigned int         n_components,
                const unsigned int         component,
                const unsigned int         samples_per_element = 4);

  /**
   * The same pieces for component @p component of a distributed field
   * (@p ghosted: locally relevant coefficients in the numbering of
   * @p dofs): each rank runs the marching squares on its own elements with
   * their own coefficients, and only the segments and their crossing
   * points are gathered and chained on rank 0, which returns the pieces
   * without values (the other ranks return none). Collective; no rank
   * holds the whole field.
   */
  std::vector<ZeroContour>
  zero_contours(const SplineDofHandler<2>                   &dofs,
                const dealii::TrilinosWrappers::MPI::Vector &ghosted,
                const unsigned int                           component,
                const unsigned int samples_per_element = 4);
} // namespace vesicle_iga
