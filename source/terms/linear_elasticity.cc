#include <vesicle_iga/terms/linear_elasticity.h>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  LinearElasticityTerm<dim>::LinearElasticityTerm(const unsigned int u,
                                                  const double       E,
                                                  const double       nu,
                                                  const bool plane_stress)
    : u(u)
  {
    mu     = E / (2 * (1 + nu));
    lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    if (dim == 2 && plane_stress)
      lambda = 2 * lambda * mu / (lambda + 2 * mu); // = E nu / (1 - nu^2)
  }


  template <int dim>
  SymmetricTensor<2, dim>
  LinearElasticityTerm<dim>::stress(const SymmetricTensor<2, dim> &eps) const
  {
    return lambda * trace(eps) * unit_symmetric_tensor<dim>() + 2 * mu * eps;
  }


  template <int dim>
  void
  LinearElasticityTerm<dim>::declare(TermDeclaration<dim> &d)
  {
    using D = Derivative<dim>;
    jacobian.clear();
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int k = 0; k < dim; ++k)
        {
          gradient[a][k]   = d.value(u + a, D::gradient(k));
          r_gradient[a][k] = d.residual(u + a, D::gradient(k));
          // d sigma_ak / d(d_l u_c) = lambda delta_ak delta_cl
          //                           + mu (delta_ac delta_kl + delta_al
          //                           delta_kc)
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int l = 0; l < dim; ++l)
              {
                const double C = (a == k && c == l ? lambda : 0.)
                                 + (a == c && k == l ? mu : 0.)
                                 + (a == l && k == c ? mu : 0.);
                if (C != 0.)
                  jacobian.emplace_back(
                    d.jacobian(u + a, D::gradient(k), u + c, D::gradient(l)),
                    C);
              }
        }
  }


  template <int dim>
  void
  LinearElasticityTerm<dim>::evaluate(const QuadratureInputs<dim> &in,
                                      TermCoefficients            &out) const
  {
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        double div = 0;
        for (unsigned int a = 0; a < dim; ++a)
          div += in[gradient[a][a]][q];
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int k = 0; k < dim; ++k)
            out[r_gradient[a][k]][q]
              += (a == k ? lambda * div : 0.)
                 + mu * (in[gradient[a][k]][q] + in[gradient[k][a]][q]);
      }
    if (!out.matrix())
      return;
    for (const auto &[handle, C] : jacobian)
      {
        double *j = out[handle];
        for (unsigned int q = 0; q < in.size(); ++q)
          j[q] += C;
      }
  }

  template class LinearElasticityTerm<2>;
  template class LinearElasticityTerm<3>;
} // namespace vesicle_iga
