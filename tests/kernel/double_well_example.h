// The worked example of doc/engine.md ("a new term in one new file"), kept
// here so that it is compiled and checked (tests/kernel/worked_example).
#pragma once
#include <vesicle_iga/kernel/term.h>

#include <array>

namespace vesicle_iga
{
  template <int dim>
  class DoubleWellTerm : public Term<dim>
  {
  public:
    DoubleWellTerm(const unsigned int phi, const double c, const double eps)
      : phi(phi)
      , c(c)
      , eps(eps)
    {}
    std::string
    name() const override
    {
      return "double well";
    }

    void
    declare(TermDeclaration<dim> &d) override
    {
      using D = Derivative<dim>;
      value   = d.value(phi, D::value);
      r_value = d.residual(phi, D::value);
      j_value = d.jacobian(phi, D::value, phi, D::value);
      for (unsigned int k = 0; k < dim; ++k)
        {
          gradient[k]   = d.value(phi, D::gradient(k));
          r_gradient[k] = d.residual(phi, D::gradient(k));
          j_gradient[k] = d.jacobian(phi, D::gradient(k), phi, D::gradient(k));
        }
    }

    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override
    {
      const double *p = in[value];
      for (unsigned int q = 0; q < in.size(); ++q)
        {
          out[r_value][q] += c * (p[q] * p[q] * p[q] - p[q]) / eps;
          for (unsigned int k = 0; k < dim; ++k)
            out[r_gradient[k]][q] += c * eps * in[gradient[k]][q];
          if (!out.matrix())
            continue;
          out[j_value][q] += c * (3 * p[q] * p[q] - 1) / eps;
          for (unsigned int k = 0; k < dim; ++k)
            out[j_gradient[k]][q] += c * eps;
        }
    }

  private:
    const unsigned int              phi;
    const double                    c, eps;
    InputHandle                     value;
    std::array<InputHandle, dim>    gradient;
    ResidualHandle                  r_value;
    std::array<ResidualHandle, dim> r_gradient;
    JacobianHandle                  j_value;
    std::array<JacobianHandle, dim> j_gradient;
  };
} // namespace vesicle_iga
