#include <deal.II/base/mpi.h>

#include <vesicle_iga/fields/spline_dof_handler.h>

#include <algorithm>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  SplineDofHandler<dim>::SplineDofHandler(const PatchMesh<dim>   &mesh_,
                                          const FieldLayout<dim> &layout_)
    : mesh(mesh_)
    , layout(layout_)
  {
    setup();
  }


  template <int dim>
  SplineDofHandler<dim>::SplineDofHandler(const PatchMesh<dim>   &mesh_,
                                          const SplineSpace<dim> &space,
                                          const unsigned int      n_comp)
    : mesh(mesh_)
    , layout(space, n_comp)
  {
    setup();
  }


  template <int dim>
  void
  SplineDofHandler<dim>::setup()
  {
    const MPI_Comm     comm    = mesh.get_communicator();
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_s     = layout.n_spaces();

    // Components per space, and the slot of each component on its space.
    spaces.resize(n_s);
    space_of.resize(layout.n_components());
    component_slot.resize(layout.n_components());
    offsets.assign(1, 0);
    for (unsigned int k = 0; k < layout.n_components(); ++k)
      {
        space_of[k]       = layout.space_of_component(k);
        component_slot[k] = spaces[space_of[k]].n_components++;
        offsets.push_back(offsets.back()
                          + layout.space(space_of[k]).n_basis_per_element());
      }

    // Owner of every basis function; unknowns per rank and space.
    std::vector<std::vector<unsigned int>> owner(n_s);
    std::vector<types::global_dof_index>   count(n_ranks * n_s, 0);
    for (unsigned int s = 0; s < n_s; ++s)
      {
        const SplineSpace<dim> &space = layout.space(s);
        owner[s].resize(space.n_basis());
        for (unsigned int i = 0; i < space.n_basis(); ++i)
          {
            owner[s][i]
              = mesh.element_owner(space.find_element(space.greville_point(i)));
            count[owner[s][i] * n_s + s] += spaces[s].n_components;
          }
      }
    // First index of (rank, space), ranks first.
    std::vector<types::global_dof_index> first(n_ranks * n_s + 1, 0);
    for (unsigned int r = 0; r < n_ranks * n_s; ++r)
      first[r + 1] = first[r] + count[r];
    total = first.back();
    for (unsigned int s = 0; s < n_s; ++s)
      {
        const unsigned int n = layout.space(s).n_basis();
        spaces[s].first.resize(n);
        std::vector<types::global_dof_index> next(n_ranks);
        for (unsigned int r = 0; r < n_ranks; ++r)
          next[r] = first[r * n_s + s];
        for (unsigned int i = 0; i < n; ++i)
          {
            spaces[s].first[i] = next[owner[s][i]];
            next[owner[s][i]] += spaces[s].n_components;
          }
      }

    owned.set_size(total);
    owned.add_range(first[rank * n_s], first[(rank + 1) * n_s]);
    owned.compress();

    relevant = owned;
    std::vector<types::global_dof_index> indices;
    for (const unsigned int e : mesh.locally_owned_elements())
      {
        element_dof_indices(e, indices);
        std::sort(indices.begin(), indices.end());
        relevant.add_indices(indices.begin(), indices.end());
      }
    relevant.compress();
  }


  template <int dim>
  void
  SplineDofHandler<dim>::element_dof_indices(
    const unsigned int                    e,
    std::vector<types::global_dof_index> &indices) const
  {
    indices.resize(offsets.back());
    std::vector<unsigned int> natural;
    int                       current_space = -1;
    for (unsigned int k = 0; k < space_of.size(); ++k)
      {
        if (int(space_of[k]) != current_space)
          {
            layout.space(space_of[k]).element_basis_indices(e, natural);
            current_space = space_of[k];
          }
        for (unsigned int j = 0; j < natural.size(); ++j)
          indices[offsets[k] + j] = dof_index(natural[j], k);
      }
  }


  template <int dim>
  void
  SplineDofHandler<dim>::make_sparsity_pattern(
    TrilinosWrappers::SparsityPattern &sp) const
  {
    sp.reinit(owned, owned, relevant, mesh.get_communicator());
    std::vector<types::global_dof_index> indices;
    for (const unsigned int e : mesh.locally_owned_elements())
      {
        element_dof_indices(e, indices);
        for (const auto row : indices)
          sp.add_entries(row, indices.begin(), indices.end());
      }
    sp.compress();
  }

  template <int dim>
  void
  get_element_coefficients(const SplineDofHandler<dim>         &dof_handler,
                           const TrilinosWrappers::MPI::Vector &ghosted,
                           const unsigned int                   element,
                           std::vector<std::vector<double>>    &c)
  {
    std::vector<types::global_dof_index> indices;
    dof_handler.element_dof_indices(element, indices);
    const unsigned int nc = dof_handler.n_components();
    const unsigned int m  = indices.size() / nc;
    c.resize(nc);
    for (unsigned int k = 0; k < nc; ++k)
      {
        c[k].resize(m);
        for (unsigned int j = 0; j < m; ++j)
          c[k][j] = ghosted[indices[k * m + j]];
      }
  }


  template class SplineDofHandler<1>;
  template class SplineDofHandler<2>;
  template class SplineDofHandler<3>;

#define INSTANTIATE(dim)                   \
  template void get_element_coefficients(  \
    const SplineDofHandler<dim> &,         \
    const TrilinosWrappers::MPI::Vector &, \
    const unsigned int,                    \
    std::vector<std::vector<double>> &);
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace vesicle_iga
