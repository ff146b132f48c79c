#pragma once

#include <deal.II/distributed/shared_tria.h>

#include <vesicle_iga/spline/nurbs_geometry.h>
#include <vesicle_iga/spline/spline_space.h>

#include <memory>
#include <vector>

namespace vesicle_iga
{
  /**
   * The deal.II mesh of a spline patch: one active cell per spline element
   * (the cell's user index is the element index), vertices at the physical
   * images of the element corners. It exists for three things: METIS
   * partitioning of the elements among the MPI ranks (a
   * parallel::shared::Triangulation with partition_metis, no p4est), DataOut
   * output, and deal.II's cell-based tools. Assembly does not go through
   * deal.II's FEValues but through SplineCellValues on the element.
   */
  template <int dim>
  class PatchMesh
  {
  public:
    PatchMesh(const MPI_Comm                            communicator,
              const SplineSpace<dim>                   &space,
              std::shared_ptr<const NurbsGeometry<dim>> geometry);

    const dealii::parallel::shared::Triangulation<dim> &
    triangulation() const
    {
      return tria;
    }
    MPI_Comm
    get_communicator() const
    {
      return tria.get_communicator();
    }
    /// The MPI rank that owns element e.
    dealii::types::subdomain_id
    element_owner(const unsigned int e) const
    {
      return owner[e];
    }
    /// The elements this rank assembles, in increasing order.
    const std::vector<unsigned int> &
    locally_owned_elements() const
    {
      return owned_elements;
    }
    /// Largest element diameter (physical, measured on the straight-sided
    /// cells: exact for boxes, the chord for curved NURBS elements).
    double
    max_cell_diameter() const;

  private:
    dealii::parallel::shared::Triangulation<dim> tria;
    std::vector<dealii::types::subdomain_id>     owner;
    std::vector<unsigned int>                    owned_elements;
  };
} // namespace vesicle_iga
