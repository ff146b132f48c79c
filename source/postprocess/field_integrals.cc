#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <vesicle_iga/kernel/derivative.h>
#include <vesicle_iga/kernel/tensor_product_kernel.h>
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
    // The derivatives at all points of an element by sum factorisation
    // (the spaces are boxes: no geometry), as the assembly evaluates them;
    // full basis tables would cost (p+1)^dim per point and derivative.
    using D = Derivative<dim>;
    std::vector<unsigned int> derivatives{D::value};
    for (unsigned int a = 0; a < dim && order >= 1; ++a)
      derivatives.push_back(D::gradient(a));
    for (unsigned int a = 0; a < dim && order >= 2; ++a)
      for (unsigned int b = a; b < dim; ++b)
        derivatives.push_back(D::hessian(a, b));
    SplineCellValues<dim> values(
      dof_handler.get_space(), nullptr, quadrature_1d, order, false);
    std::vector<double>                          at_points;
    std::vector<double *>                        out(derivatives.size());
    typename TensorProductKernel<dim>::Workspace workspace;
    std::vector<double>                          JxW;
    std::vector<std::vector<double>>             c;
    std::vector<double>                          squares(order + 1, 0.);
    for (const unsigned int e : dof_handler.get_mesh().locally_owned_elements())
      {
        values.reinit(e);
        get_element_coefficients(dof_handler, solution, e, c);
        const auto        &f   = values.tensor_product_factors();
        const unsigned int n_q = f.n_quadrature_points();
        at_points.resize(derivatives.size() * n_q);
        for (unsigned int k = 0; k < derivatives.size(); ++k)
          out[k] = &at_points[k * n_q];
        TensorProductKernel<dim>::evaluate(
          f, c[0].data(), derivatives, out.data(), workspace);
        TensorProductKernel<dim>::weights(f, JxW);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            Point<dim>   x;
            unsigned int r = q;
            for (unsigned int d = 0; d < dim; ++d)
              {
                x[d] = f.points[d][r % f.n_points[d]];
                r /= f.n_points[d];
              }
            squares[0] += std::pow(at_points[q] - exact.value(x), 2) * JxW[q];
            if (order >= 1)
              {
                const Tensor<1, dim> g = exact.gradient(x);
                for (unsigned int a = 0; a < dim; ++a)
                  squares[1] += std::pow(at_points[(1 + a) * n_q + q] - g[a], 2)
                                * JxW[q];
              }
            if (order >= 2)
              {
                const SymmetricTensor<2, dim> H = exact.hessian(x);
                unsigned int                  k = 1 + dim;
                for (unsigned int a = 0; a < dim; ++a)
                  for (unsigned int b = a; b < dim; ++b, ++k)
                    squares[2]
                      += (a == b ? 1. : 2.)
                         * std::pow(at_points[k * n_q + q] - H[a][b], 2)
                         * JxW[q];
              }
          }
      }
    Utilities::MPI::sum(squares,
                        dof_handler.get_mesh().get_communicator(),
                        squares);
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
