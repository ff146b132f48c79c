#pragma once

#include <deal.II/base/function.h>

#include <array>

namespace vesicle_iga
{

  /**
   * u(x) = prod_d sin(k_d x_d + phi_d): smooth, non-zero on every face,
   * with every derivative in closed form, Delta u = -|k|^2 u and
   * Delta^2 u = |k|^4 u. The manufactured solution of the Poisson and
   * biharmonic verification studies.
   */
  template <int dim>
  class ProductSineSolution : public dealii::Function<dim>
  {
  public:
    ProductSineSolution(const std::array<double, dim> &k,
                        const std::array<double, dim> &phase)
      : k(k)
      , phase(phase)
    {}

    double
    value(const dealii::Point<dim> &x, const unsigned int = 0) const override;
    dealii::Tensor<1, dim>
    gradient(const dealii::Point<dim> &x,
             const unsigned int = 0) const override;
    dealii::SymmetricTensor<2, dim>
    hessian(const dealii::Point<dim> &x, const unsigned int = 0) const override;

    double
    laplacian(const dealii::Point<dim> &x,
              const unsigned int = 0) const override
    {
      return -k_squared() * value(x);
    }
    double
    bilaplacian(const dealii::Point<dim> &x) const
    {
      return k_squared() * k_squared() * value(x);
    }
    double
    k_squared() const
    {
      double s = 0;
      for (const double kd : k)
        s += kd * kd;
      return s;
    }

  private:
    std::array<double, dim> k, phase;
  };
} // namespace vesicle_iga
