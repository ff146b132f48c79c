#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vesicle_iga/parallel/patch_mesh.h>
#include <vesicle_iga/spline/spline_space.h>

#include <vector>

namespace vesicle_iga
{
  /**
   * The unknowns of a (possibly vector-valued) field on a spline space:
   * exactly one unknown per basis function and component, (n+p)^d per
   * component for C^{p-1} on n^d elements.
   *
   * Ownership: basis function i belongs to the rank that owns the element
   * containing its Greville point, so each rank owns the unknowns "under"
   * its METIS partition. The unknowns are renumbered so that every rank owns
   * a contiguous range (rank 0 first, natural order within a rank), with the
   * components of one basis function next to each other. The locally
   * relevant unknowns are those of all basis functions supported on locally
   * owned elements: exactly what assembly touches.
   */
  template <int dim>
  class SplineDofHandler
  {
  public:
    SplineDofHandler(const PatchMesh<dim>   &mesh,
                     const SplineSpace<dim> &space,
                     const unsigned int      n_components = 1);

    const SplineSpace<dim> &
    get_space() const
    {
      return space;
    }
    const PatchMesh<dim> &
    get_mesh() const
    {
      return mesh;
    }
    unsigned int
    n_components() const
    {
      return nc;
    }
    types::global_dof_index
    n_dofs() const
    {
      return types::global_dof_index(space.n_basis()) * nc;
    }
    const IndexSet &
    locally_owned_dofs() const
    {
      return owned;
    }
    const IndexSet &
    locally_relevant_dofs() const
    {
      return relevant;
    }

    /// Global index of component c of basis function i (natural index).
    types::global_dof_index
    dof_index(const unsigned int i, const unsigned int c = 0) const
    {
      return types::global_dof_index(new_index[i]) * nc + c;
    }
    /// Unknowns of element e; local index c * n_basis_per_element + j for
    /// component c of the j-th local basis function.
    void
    element_dof_indices(const unsigned int                    e,
                        std::vector<types::global_dof_index> &indices) const;

    /// The coupling of two unknowns whose supports share an element.
    void
    make_sparsity_pattern(TrilinosWrappers::SparsityPattern &sp) const;

  private:
    const PatchMesh<dim>     &mesh;
    const SplineSpace<dim>   &space;
    const unsigned int        nc;
    std::vector<unsigned int> new_index;
    IndexSet                  owned, relevant;
  };
} // namespace vesicle_iga
