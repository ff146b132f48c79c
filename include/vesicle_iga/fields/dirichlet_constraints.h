#pragma once

#include <deal.II/base/function.h>

#include <deal.II/lac/affine_constraints.h>

#include <vesicle_iga/fields/boundary_selection.h>
#include <vesicle_iga/fields/spline_dof_handler.h>

#include <functional>
#include <memory>
#include <vector>

namespace vesicle_iga
{
  /**
   * Strong Dirichlet conditions u_c = g_c on the selected boundary pieces,
   * for the components with @p components[c] == true. With open knot
   * vectors only the first layer of basis functions has a non-zero trace on
   * a face, and that trace is a spline space of dimension dim-1: its
   * coefficients are set to the Greville interpolant of g on the face
   * (of g W for a NURBS geometry with weight function W), exact for data in
   * the trace space and of optimal order otherwise. On a piece cut by
   * coordinate ranges (boxes only; the range ends must be breakpoints) every
   * function whose trace does not vanish on the piece is constrained, so
   * that the trial traces equal the interpolant on the piece and the test
   * functions vanish on it: a conforming imposition, with the optimal rates
   * of a whole face (measured in tests/studies/poisson_partial_faces).
   * Constraints are only added for locally relevant unknowns and never
   * twice (the first condition on a corner wins).
   */
  template <int dim>
  void
  add_strong_dirichlet_constraints(
    const SplineDofHandler<dim>              &dof_handler,
    std::shared_ptr<const NurbsGeometry<dim>> geometry,
    const BoundarySelection<dim>             &selection,
    const dealii::Function<dim>              &g,
    const std::vector<bool>                  &components,
    dealii::AffineConstraints<double>        &constraints);

  /**
   * Clamped condition of fourth-order problems: u = g and du/dn = g_n,
   * imposed strongly on an axis-aligned box (no NURBS geometry) through the
   * first two layers of coefficients. At an open end the normal derivative
   * is (p/Delta)(c_1 - c_0) with Delta the distance to the (p+1)-th knot, so
   * the second layer is c_1 = c_0 - (Delta/p) g_n (outward normal).
   */
  template <int dim>
  void
  add_clamped_constraints(
    const SplineDofHandler<dim>  &dof_handler,
    const BoundarySelection<dim> &selection,
    const dealii::Function<dim>  &g,
    const std::function<double(const dealii::Point<dim> &,
                               const dealii::Tensor<1, dim> &)>
                                      &normal_derivative,
    dealii::AffineConstraints<double> &constraints);

  /**
   * Homogeneous Neumann condition du/dn = 0 on every non-periodic side of a
   * box, strongly, for the components with @p components[c] == true. At an
   * open end du/dn = (p/Delta)(c_1 - c_0), so the condition ties each
   * coefficient of the first layer to its neighbour of the second layer;
   * at edges and corners the coefficient is tied to the nearest one off
   * every side (c_00 = c_11), which satisfies the conditions of all sides
   * at once. Lines are added for locally relevant unknowns that are not
   * constrained yet.
   */
  template <int dim>
  void
  add_zero_normal_derivative_constraints(
    const SplineDofHandler<dim>       &dof_handler,
    const std::vector<bool>           &components,
    dealii::AffineConstraints<double> &constraints);
} // namespace vesicle_iga
