#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <vesicle_iga/fields/natural_numbering.h>

#include <Epetra_Import.h>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    /// A vector in the numbering of @p dofs whose entries all live on rank 0.
    template <int dim>
    TrilinosWrappers::MPI::Vector
    vector_on_rank_0(const SplineDofHandler<dim> &dofs)
    {
      const MPI_Comm comm = dofs.get_mesh().get_communicator();
      IndexSet       all(dofs.n_dofs());
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        all.add_range(0, dofs.n_dofs());
      return TrilinosWrappers::MPI::Vector(all, comm);
    }

    /// target = source through Epetra's import between their two maps.
    void
    import(const TrilinosWrappers::MPI::Vector &source,
           TrilinosWrappers::MPI::Vector       &target)
    {
      const Epetra_Import importer(target.trilinos_partitioner(),
                                   source.trilinos_partitioner());
      const int           error
        = target.trilinos_vector().Import(source.trilinos_vector(),
                                          importer,
                                          Insert);
      AssertThrow(error == 0, ExcTrilinosError(error));
    }
  } // namespace


  template <int dim>
  void
  scatter_natural(const SplineDofHandler<dim>   &dofs,
                  const std::vector<double>     &natural,
                  TrilinosWrappers::MPI::Vector &owned)
  {
    // n_components values per basis function, component fastest.
    const unsigned int nc = dofs.n_components();
    for (unsigned int i = 0; i < natural.size(); ++i)
      if (owned.in_local_range(dofs.dof_index(i / nc, i % nc)))
        owned[dofs.dof_index(i / nc, i % nc)] = natural[i];
    owned.compress(VectorOperation::insert);
  }


  template <int dim>
  std::vector<std::pair<std::uint64_t, types::global_dof_index>>
  owned_natural_entries(const SplineDofHandler<dim> &dofs)
  {
    const IndexSet    &owned = dofs.locally_owned_dofs();
    const unsigned int nc    = dofs.n_components();
    std::vector<std::pair<std::uint64_t, types::global_dof_index>> entries;
    entries.reserve(owned.n_elements());
    for (std::uint64_t i = 0; i < dofs.n_dofs(); ++i)
      {
        const types::global_dof_index d = dofs.dof_index(i / nc, i % nc);
        if (owned.is_element(d))
          entries.emplace_back(i, d);
      }
    return entries;
  }


  template <int dim>
  std::vector<double>
  gather_natural_on_rank_0(const SplineDofHandler<dim>         &dofs,
                           const TrilinosWrappers::MPI::Vector &v)
  {
    // From the owned entries only: @p v may be a ghosted vector, whose
    // overlapping map does not import into another map reliably.
    TrilinosWrappers::MPI::Vector owned(dofs.locally_owned_dofs(),
                                        dofs.get_mesh().get_communicator());
    for (const auto i : dofs.locally_owned_dofs())
      owned[i] = v[i];
    owned.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector on_rank_0 = vector_on_rank_0(dofs);
    import(owned, on_rank_0);
    if (on_rank_0.locally_owned_size() == 0)
      return {};
    const unsigned int  nc = dofs.n_components();
    std::vector<double> c(dofs.get_space().n_basis() * nc);
    for (unsigned int i = 0; i < c.size(); ++i)
      c[i] = on_rank_0[dofs.dof_index(i / nc, i % nc)];
    return c;
  }


#define INSTANTIATE(dim)                                                  \
  template void scatter_natural(const SplineDofHandler<dim> &,            \
                                const std::vector<double> &,              \
                                TrilinosWrappers::MPI::Vector &);         \
  template std::vector<std::pair<std::uint64_t, types::global_dof_index>> \
  owned_natural_entries(const SplineDofHandler<dim> &);                   \
  template std::vector<double> gather_natural_on_rank_0(                  \
    const SplineDofHandler<dim> &, const TrilinosWrappers::MPI::Vector &);
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace vesicle_iga
