#include <vesicle_iga/terms/laplace.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  void
  LaplaceTerm<dim>::declare(TermDeclaration<dim> &d)
  {
    using D = Derivative<dim>;
    d.needs_points();
    r_value = d.residual(u, D::value);
    for (unsigned int k = 0; k < dim; ++k)
      {
        gradient[k]   = d.value(u, D::gradient(k));
        r_gradient[k] = d.residual(u, D::gradient(k));
        j_gradient[k] = d.jacobian(u, D::gradient(k), u, D::gradient(k));
      }
  }


  template <int dim>
  void
  LaplaceTerm<dim>::evaluate(const QuadratureInputs<dim> &in,
                             TermCoefficients            &out) const
  {
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        out[r_value][q] -= f.value(in.point(q));
        for (unsigned int k = 0; k < dim; ++k)
          {
            out[r_gradient[k]][q] += in[gradient[k]][q];
            if (out.matrix())
              out[j_gradient[k]][q] += 1.;
          }
      }
  }


  template <int dim>
  void
  NitscheDirichletTerm<dim>::declare(TermDeclaration<dim> &d)
  {
    using D = Derivative<dim>;
    d.needs_points();
    value   = d.value(u, D::value);
    r_value = d.residual(u, D::value);
    j_value = d.jacobian(u, D::value, u, D::value);
    for (unsigned int k = 0; k < dim; ++k)
      {
        gradient[k]         = d.value(u, D::gradient(k));
        r_gradient[k]       = d.residual(u, D::gradient(k));
        j_value_gradient[k] = d.jacobian(u, D::value, u, D::gradient(k));
        j_gradient_value[k] = d.jacobian(u, D::gradient(k), u, D::value);
      }
  }


  template <int dim>
  void
  NitscheDirichletTerm<dim>::evaluate(const QuadratureInputs<dim> &in,
                                      TermCoefficients            &out) const
  {
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        if (!selection.contains(in.face(), in.point(q)))
          continue;
        const Tensor<1, dim> &n = in.normal(q);
        const double gamma = penalty * std::sqrt(n * (in.metric(q) * n)) / 2;
        const double jump  = in[value][q] - g.value(in.point(q));
        double       du_dn = 0;
        for (unsigned int k = 0; k < dim; ++k)
          du_dn += in[gradient[k]][q] * n[k];
        out[r_value][q] += -du_dn + gamma * jump;
        for (unsigned int k = 0; k < dim; ++k)
          out[r_gradient[k]][q] += -n[k] * jump;
        if (!out.matrix())
          continue;
        out[j_value][q] += gamma;
        for (unsigned int k = 0; k < dim; ++k)
          {
            out[j_value_gradient[k]][q] += -n[k];
            out[j_gradient_value[k]][q] += -n[k];
          }
      }
  }

  template class LaplaceTerm<2>;
  template class LaplaceTerm<3>;
  template class NitscheDirichletTerm<2>;
  template class NitscheDirichletTerm<3>;
} // namespace vesicle_iga
