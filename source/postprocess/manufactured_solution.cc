#include <deal.II/base/symmetric_tensor.h>

#include <vesicle_iga/postprocess/manufactured_solution.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  double
  ProductSineSolution<dim>::value(const Point<dim> &x, const unsigned int) const
  {
    double u = 1;
    for (unsigned int d = 0; d < dim; ++d)
      u *= std::sin(k[d] * x[d] + phase[d]);
    return u;
  }


  template <int dim>
  Tensor<1, dim>
  ProductSineSolution<dim>::gradient(const Point<dim> &x,
                                     const unsigned int) const
  {
    Tensor<1, dim> g;
    for (unsigned int a = 0; a < dim; ++a)
      {
        g[a] = 1;
        for (unsigned int d = 0; d < dim; ++d)
          g[a] *= (d == a) ? k[d] * std::cos(k[d] * x[d] + phase[d]) :
                             std::sin(k[d] * x[d] + phase[d]);
      }
    return g;
  }


  template <int dim>
  SymmetricTensor<2, dim>
  ProductSineSolution<dim>::hessian(const Point<dim> &x,
                                    const unsigned int) const
  {
    SymmetricTensor<2, dim> H;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = a; b < dim; ++b)
        {
          double h = 1;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double s = std::sin(k[d] * x[d] + phase[d]);
              const double c = k[d] * std::cos(k[d] * x[d] + phase[d]);
              if (d == a && d == b)
                h *= -k[d] * k[d] * s;
              else if (d == a || d == b)
                h *= c;
              else
                h *= s;
            }
          H[a][b] = h;
        }
    return H;
  }

  template class ProductSineSolution<1>;
  template class ProductSineSolution<2>;
  template class ProductSineSolution<3>;
} // namespace vesicle_iga
