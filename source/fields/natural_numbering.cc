#include <deal.II/base/index_set.h>

#include <vesicle_iga/fields/natural_numbering.h>

namespace vesicle_iga
{
  using namespace dealii;

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
  std::vector<double>
  gather_natural(const SplineDofHandler<dim>         &dofs,
                 const TrilinosWrappers::MPI::Vector &v)
  {
    TrilinosWrappers::MPI::Vector all(dofs.locally_owned_dofs(),
                                      complete_index_set(dofs.n_dofs()),
                                      dofs.get_mesh().get_communicator());
    // From the owned entries only: @p v may be a ghosted vector, whose
    // overlapping map does not import into another map reliably.
    TrilinosWrappers::MPI::Vector owned(dofs.locally_owned_dofs(),
                                        dofs.get_mesh().get_communicator());
    for (const auto i : dofs.locally_owned_dofs())
      owned[i] = v[i];
    owned.compress(VectorOperation::insert);
    all                    = owned;
    const unsigned int  nc = dofs.n_components();
    std::vector<double> c(dofs.get_space().n_basis() * nc);
    for (unsigned int i = 0; i < c.size(); ++i)
      c[i] = all[dofs.dof_index(i / nc, i % nc)];
    return c;
  }


  template void
  scatter_natural(const SplineDofHandler<2> &,
                  const std::vector<double> &,
                  TrilinosWrappers::MPI::Vector &);
  template void
  scatter_natural(const SplineDofHandler<3> &,
                  const std::vector<double> &,
                  TrilinosWrappers::MPI::Vector &);
  template std::vector<double>
  gather_natural(const SplineDofHandler<2> &,
                 const TrilinosWrappers::MPI::Vector &);
  template std::vector<double>
  gather_natural(const SplineDofHandler<3> &,
                 const TrilinosWrappers::MPI::Vector &);
} // namespace vesicle_iga
