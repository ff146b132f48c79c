#pragma once

#include <deal.II/distributed/fully_distributed_tria.h>

#include <vesicle_iga/spline/nurbs_geometry.h>
#include <vesicle_iga/spline/spline_space.h>

#include <memory>
#include <vector>

namespace vesicle_iga
{
  /**
   * The deal.II mesh of a spline patch: one cell per spline element (the
   * cell's user index is the element index), vertices at the physical
   * images of the element corners. It exists for three things: the METIS
   * partition of the elements among the MPI ranks (no p4est), DataOut
   * output, and deal.II's cell-based tools. Assembly does not go through
   * deal.II's FEValues but through SplineCellValues on the element.
   *
   * The mesh is distributed (parallel::fullydistributed::Triangulation):
   * a rank holds only its own elements and one layer of ghost elements
   * around them (those sharing a vertex), built directly from the
   * tensor-product structure of the patch, so that its memory shrinks with
   * the number of ranks. The one global object is the owner of every
   * element (4 bytes per element): the partition is computed by METIS on
   * every rank from the face graph of the elements, the same graph and
   * call as deal.II's partition_triangulation(), so the partition is that
   * of a parallel::shared::Triangulation with partition_metis.
   */
  template <int dim>
  class PatchMesh
  {
  public:
    PatchMesh(const MPI_Comm                            communicator,
              const SplineSpace<dim>                   &space,
              std::shared_ptr<const NurbsGeometry<dim>> geometry);

    /// This rank's elements and its ghost layer; DataOut and DoFHandler
    /// work on it as on any distributed triangulation.
    const dealii::parallel::fullydistributed::Triangulation<dim> &
    triangulation() const
    {
      return tria;
    }
    MPI_Comm
    get_communicator() const
    {
      return tria.get_communicator();
    }
    /// The MPI rank that owns element e (any element of the patch).
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
    /// Largest element diameter of the whole patch (physical, measured on
    /// the straight-sided cells: exact for boxes, the chord for curved
    /// NURBS elements).
    double
    max_cell_diameter() const
    {
      return max_diameter;
    }

  private:
    dealii::parallel::fullydistributed::Triangulation<dim> tria;
    std::vector<dealii::types::subdomain_id>               owner;
    std::vector<unsigned int>                              owned_elements;
    double                                                 max_diameter = 0;
  };
} // namespace vesicle_iga
