#pragma once

#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/dofs/dof_handler.h>

#include <vesicle_iga/fields/spline_dof_handler.h>
#include <vesicle_iga/spline/spline_cell_values.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vesicle_iga
{
  /// A scalar quantity computed from a spline field at one point of an
  /// element (the field's local coefficients, one vector per component).
  template <int dim>
  using PointEvaluator
    = std::function<double(const SplineCellValues<dim> &,
                           const unsigned int,
                           const std::vector<std::vector<double>> &)>;

  /**
   * Conversion of spline quantities into a deal.II FE_Q field on the patch
   * mesh (FESystem of FE_Q(p) with one component per quantity, p the largest
   * spline degree): the FE field takes the value of the quantity at the FE
   * support points of every cell. For a polynomial quantity of degree <= p
   * on an axis-aligned box (a B-spline field itself) this reproduces the
   * spline field exactly: FE_Q(p) interpolation is exact on Q_p, and the
   * restriction of the spline to an element lies in Q_p. For NURBS patches
   * it is the nodal interpolant. DataOut, FEValues and all of deal.II's
   * postprocessing then work on the result.
   */
  template <int dim>
  void
  interpolate_to_fe_field(
    const SplineDofHandler<dim>                        &spline_dofs,
    std::shared_ptr<const NurbsGeometry<dim>>           geometry,
    const dealii::TrilinosWrappers::MPI::Vector        &ghosted_solution,
    const std::vector<PointEvaluator<dim>>             &quantities,
    const unsigned int                                  derivative_order,
    const dealii::DoFHandler<dim>                      &fe_dofs,
    dealii::LinearAlgebra::distributed::Vector<double> &result);

  /**
   * Writes named quantities of a spline field as VTU/PVTU (one .vtu per
   * rank with its owned elements, higher-order Lagrange cells of degree p:
   * the quantities at the (p+1)^d equidistant points of every element,
   * curved on NURBS patches through the physical points, plus the owning
   * rank as "subdomain"). The patches are built from the spline directly,
   * without an FE space on the mesh: the output costs (p+1)^d values per
   * quantity and owned element.
   */
  template <int dim>
  class SplineFieldWriter
  {
  public:
    SplineFieldWriter(const SplineDofHandler<dim>              &spline_dofs,
                      std::shared_ptr<const NurbsGeometry<dim>> geometry);

    void
    add_quantity(const std::string         &name,
                 const PointEvaluator<dim> &evaluator,
                 const unsigned int         derivative_order = 0);

    /// The spline field's components as quantities named @p names.
    void
    add_components(const std::vector<std::string> &names);

    /// Writes directory/basename.pvtu and the per-rank .vtu files; returns
    /// the name of the .pvtu record.
    std::string
    write(const dealii::TrilinosWrappers::MPI::Vector &ghosted_solution,
          const std::string                           &directory,
          const std::string                           &basename) const;

  private:
    const SplineDofHandler<dim>              &spline_dofs;
    std::shared_ptr<const NurbsGeometry<dim>> geometry;
    std::vector<std::string>                  names;
    std::vector<PointEvaluator<dim>>          quantities;
    unsigned int                              order = 0;
  };
} // namespace vesicle_iga
