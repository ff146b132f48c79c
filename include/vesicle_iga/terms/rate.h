#pragma once

#include <vesicle_iga/kernel/term.h>

#include <vector>

namespace vesicle_iga
{
  /**
   * The rate term (w, du/dt) of an evolution equation, for each of the
   * given components: the first term of (E18) for the phase field. Its
   * Jacobian is the mass matrix with respect to the rate; the time
   * integrator scales it by alpha_m (N4).
   */
  template <int dim>
  class RateTerm : public Term<dim>
  {
  public:
    explicit RateTerm(const std::vector<unsigned int> &components)
      : components(components)
    {}
    std::string
    name() const override
    {
      return "rate";
    }
    void
    declare(TermDeclaration<dim> &d) override
    {
      using D = Derivative<dim>;
      rates.clear();
      residuals.clear();
      jacobians.clear();
      for (const unsigned int c : components)
        {
          rates.push_back(d.rate(c, D::value));
          residuals.push_back(d.residual(c, D::value));
          jacobians.push_back(
            d.jacobian(c, D::value, c, D::value, FieldSource::rate));
        }
    }
    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override
    {
      for (unsigned int k = 0; k < components.size(); ++k)
        {
          const double *rate = in[rates[k]];
          double       *r    = out[residuals[k]];
          for (unsigned int q = 0; q < in.size(); ++q)
            r[q] += rate[q];
          if (!out.matrix())
            continue;
          double *j = out[jacobians[k]];
          for (unsigned int q = 0; q < in.size(); ++q)
            j[q] += 1.;
        }
    }

  private:
    const std::vector<unsigned int> components;
    std::vector<InputHandle>        rates;
    std::vector<ResidualHandle>     residuals;
    std::vector<JacobianHandle>     jacobians;
  };
} // namespace vesicle_iga
