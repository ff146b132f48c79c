#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/field_layout.h>
#include <vesicle_iga/parallel/patch_mesh.h>
#include <vesicle_iga/spline/spline_space.h>

#include <vector>

namespace vesicle_iga
{
  /**
   * The unknowns of the fields of a FieldLayout: exactly one unknown per
   * basis function and scalar component, (n+p)^d per component for C^{p-1}
   * on n^d elements.
   *
   * Ownership: basis function i of a space belongs to the rank that owns
   * the element containing its Greville point, so each rank owns the
   * unknowns "under" its METIS partition. Every rank owns a contiguous
   * range (rank 0 first); within it the spaces follow in layout order, the
   * basis functions of a space in natural order, and the components that
   * live on one space (all components of its fields, flat order) are next to
   * each other. With one space this is the numbering of a vector-valued
   * field with interleaved components (u_1, .., u_dim, p per function).
   * The locally relevant unknowns are those of all basis functions supported
   * on locally owned elements: exactly what assembly touches.
   */
  template <int dim>
  class SplineDofHandler
  {
  public:
    SplineDofHandler(const PatchMesh<dim>   &mesh,
                     const FieldLayout<dim> &layout);
    /// One field of @p n_components components on @p space.
    SplineDofHandler(const PatchMesh<dim>   &mesh,
                     const SplineSpace<dim> &space,
                     const unsigned int      n_components = 1);

    const FieldLayout<dim> &
    get_layout() const
    {
      return layout;
    }
    /// The space of the first component (the only one for one space).
    const SplineSpace<dim> &
    get_space() const
    {
      return layout.space(0);
    }
    const SplineSpace<dim> &
    component_space(const unsigned int k) const
    {
      return layout.space(layout.space_of_component(k));
    }
    const PatchMesh<dim> &
    get_mesh() const
    {
      return mesh;
    }
    /// Number of scalar components (all fields).
    unsigned int
    n_components() const
    {
      return layout.n_components();
    }
    dealii::types::global_dof_index
    n_dofs() const
    {
      return total;
    }
    const dealii::IndexSet &
    locally_owned_dofs() const
    {
      return owned;
    }
    const dealii::IndexSet &
    locally_relevant_dofs() const
    {
      return relevant;
    }

    /// Global index of component k (flat) at the basis function i (natural
    /// index in the component's space).
    dealii::types::global_dof_index
    dof_index(const unsigned int i, const unsigned int k = 0) const
    {
      const auto &s = spaces[space_of[k]];
      return s.first[i] + component_slot[k];
    }
    /// Unknowns of element e; local index offset(k) + j for component k of
    /// the j-th local basis function of its space.
    void
    element_dof_indices(
      const unsigned int                            e,
      std::vector<dealii::types::global_dof_index> &indices) const;
    /// Local offset of component k in element_dof_indices().
    unsigned int
    local_offset(const unsigned int k) const
    {
      return offsets[k];
    }
    /// Number of unknowns of one element.
    unsigned int
    n_element_dofs() const
    {
      return offsets.back();
    }

    /// The coupling of two unknowns whose supports share an element.
    void
    make_sparsity_pattern(dealii::TrilinosWrappers::SparsityPattern &sp) const;

  private:
    void
    setup();

    const PatchMesh<dim>  &mesh;
    const FieldLayout<dim> layout;
    struct SpaceNumbering
    {
      /// Global index of component slot 0 of each basis function.
      std::vector<dealii::types::global_dof_index> first;
      unsigned int                                 n_components = 0;
    };
    std::vector<SpaceNumbering>     spaces;
    std::vector<unsigned int>       space_of, component_slot, offsets;
    dealii::types::global_dof_index total = 0;
    dealii::IndexSet                owned, relevant;
  };


  /// Local coefficients of an element, one vector per component.
  template <int dim>
  void
  get_element_coefficients(const SplineDofHandler<dim> &dof_handler,
                           const dealii::TrilinosWrappers::MPI::Vector &ghosted,
                           const unsigned int                           element,
                           std::vector<std::vector<double>> &coefficients);
} // namespace vesicle_iga
