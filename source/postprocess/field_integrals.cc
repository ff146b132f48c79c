#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <vesicle_iga/postprocess/field_integrals.h>

#include <cmath>

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

  template <int dim>
  std::vector<double>
  scalar_error_norms(const SplineDofHandler<dim>         &dof_handler,
                     const Function<dim>                 &exact,
                     const Quadrature<1>                 &quadrature_1d,
                     const unsigned int                   order,
                     const TrilinosWrappers::MPI::Vector &solution)
  {
    std::vector<double> squares = integrate_field<dim>(
      dof_handler,
      nullptr,
      quadrature_1d,
      order,
      solution,
      order + 1,
      [&](const SplineCellValues<dim>            &v,
          const unsigned int                      q,
          const std::vector<std::vector<double>> &c,
          std::vector<double>                    &sums) {
        const Point<dim> &x = v.quadrature_point(q);
        sums[0] += std::pow(v.value(c[0], q) - exact.value(x), 2) * v.JxW(q);
        sums[1]
          += (v.gradient(c[0], q) - exact.gradient(x)).norm_square() * v.JxW(q);
        if (order >= 2)
          sums[2] += (v.hessian(c[0], q) - Tensor<2, dim>(exact.hessian(x)))
                       .norm_square()
                     * v.JxW(q);
      });
    for (double &s : squares)
      s = std::sqrt(s);
    return squares;
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
                             std::vector<double> &)> &);               \
  template std::vector<double> scalar_error_norms(                     \
    const SplineDofHandler<dim> &,                                     \
    const Function<dim> &,                                             \
    const Quadrature<1> &,                                             \
    const unsigned int,                                                \
    const TrilinosWrappers::MPI::Vector &);
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace vesicle_iga
