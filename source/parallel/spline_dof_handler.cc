#include <deal.II/base/mpi.h>

#include <vesicle_iga/parallel/spline_dof_handler.h>

namespace vesicle_iga
{
  template <int dim>
  SplineDofHandler<dim>::SplineDofHandler(const PatchMesh<dim>   &mesh_,
                                          const SplineSpace<dim> &space_,
                                          const unsigned int      n_comp)
    : mesh(mesh_)
    , space(space_)
    , nc(n_comp)
  {
    const MPI_Comm     comm    = mesh.get_communicator();
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n       = space.n_basis();

    std::vector<unsigned int> basis_owner(n);
    std::vector<unsigned int> count(n_ranks, 0);
    for (unsigned int i = 0; i < n; ++i)
      {
        basis_owner[i]
          = mesh.element_owner(space.find_element(space.greville_point(i)));
        ++count[basis_owner[i]];
      }
    std::vector<unsigned int> first(n_ranks + 1, 0);
    for (unsigned int r = 0; r < n_ranks; ++r)
      first[r + 1] = first[r] + count[r];
    new_index.resize(n);
    std::vector<unsigned int> next(first.begin(), first.end() - 1);
    for (unsigned int i = 0; i < n; ++i)
      new_index[i] = next[basis_owner[i]]++;

    owned.set_size(n_dofs());
    owned.add_range(types::global_dof_index(first[rank]) * nc,
                    types::global_dof_index(first[rank + 1]) * nc);
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
    std::vector<unsigned int> natural;
    space.element_basis_indices(e, natural);
    const unsigned int m = natural.size();
    indices.resize(m * nc);
    for (unsigned int c = 0; c < nc; ++c)
      for (unsigned int j = 0; j < m; ++j)
        indices[c * m + j] = dof_index(natural[j], c);
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

  template class SplineDofHandler<1>;
  template class SplineDofHandler<2>;
  template class SplineDofHandler<3>;
} // namespace vesicle_iga
