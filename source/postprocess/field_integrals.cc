#include <deal.II/base/mpi.h>

#include <vesicle_iga/postprocess/field_integrals.h>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  std::vector<double>
  integrate_field(
    const SplineDofHandler<dim>                      &dof_handler,
    std::shared_ptr<const NurbsGeometry<dim>>         geometry,
    const Quadrature<1>                              &quadrature_1d,
    const unsigned int                                order,
    const TrilinosWrappers::MPI::Vector              &ghosted,
    const unsigned int                                n_sums,
    const std::function<void(const SplineCellValues<dim> &,
                             const unsigned int,
                             const std::vector<std::vector<double>> &,
                             std::vector<double> &)> &integrand)
  {
    SplineCellValues<dim>            values(dof_handler.get_space(),
                                 geometry,
                                 quadrature_1d,
                                 order);
    std::vector<double>              sums(n_sums, 0.);
    std::vector<std::vector<double>> c;
    for (const unsigned int e : dof_handler.get_mesh().locally_owned_elements())
      {
        values.reinit(e);
        get_element_coefficients(dof_handler, ghosted, e, c);
        for (unsigned int q = 0; q < values.n_quadrature_points(); ++q)
          integrand(values, q, c, sums);
      }
    Utilities::MPI::sum(sums, dof_handler.get_mesh().get_communicator(), sums);
    return sums;
  }

#define INSTANTIATE(dim)                                               \
  template std::vector<double> integrate_field(                        \
    const SplineDofHandler<dim> &,                                     \
    std::shared_ptr<const NurbsGeometry<dim>>,                         \
    const Quadrature<1> &,                                             \
    const unsigned int,                                                \
    const TrilinosWrappers::MPI::Vector &,                             \
    const unsigned int,                                                \
    const std::function<void(const SplineCellValues<dim> &,            \
                             const unsigned int,                       \
                             const std::vector<std::vector<double>> &, \
                             std::vector<double> &)> &);
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace vesicle_iga
