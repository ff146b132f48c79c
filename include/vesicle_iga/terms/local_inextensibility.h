#pragma once

#include <vesicle_iga/kernel/pointwise_term.h>
#include <vesicle_iga/physics/hydrodynamic_membrane.h>

namespace vesicle_iga
{
  /**
   * Local inextensibility of one membrane, (H17), and its tension force in
   * the momentum equation, (H14):
   *   -(grad s, xi eps^2 phi^2 grad lambda) + (s, delta_eps(phi) P : grad u)
   *   + (grad w, delta_eps(phi) lambda P),
   * P = I - n (x) n, n = grad phi / sqrt(|grad phi|^2 + eta_n^2),
   * eta_n = 1e-8 / eps (spec 4.5), delta_eps of (H12b). The coupling of
   * u and lambda is one bilinear form in both rows, so the power of the
   * tension force is -xi eps^2 int phi^2 |grad lambda|^2 <= 0 (spec 4.3).
   */
  template <int dim>
  struct LocalInextensibilityFormula
  {
    static constexpr int max_inputs = 2 + 2 * dim + dim * dim;
    LocalInextensibilityFormula(const unsigned int          velocity,
                                const unsigned int          phi,
                                const unsigned int          tension,
                                const MembraneCoefficients &coefficients);
    std::string
    name() const
    {
      return "local_inextensibility";
    }
    template <typename T>
    void
    residual(const T *in, T *out) const
    {
      // in: phi, d_k phi, lambda, d_k lambda, d_k u_a (a major).
      using std::sqrt;
      const T &phi = in[0];
      T        norm2(eta_n * eta_n);
      for (unsigned int k = 0; k < dim; ++k)
        norm2 += in[1 + k] * in[1 + k];
      const T inverse_norm = 1. / sqrt(norm2);
      T       n[dim];
      for (unsigned int k = 0; k < dim; ++k)
        n[k] = in[1 + k] * inverse_norm;
      const T  delta  = membrane::surface_delta(phi, eps);
      const T &lambda = in[1 + dim];
      const T  weight = -xi * eps * eps * phi * phi;
      // -(grad s, xi eps^2 phi^2 grad lambda)
      for (unsigned int k = 0; k < dim; ++k)
        out[k] = weight * in[2 + dim + k];
      // P : grad u and (grad w, delta lambda P)
      T            p_grad_u(0.);
      unsigned int o = dim + 1;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int k = 0; k < dim; ++k)
          {
            T P = -n[a] * n[k];
            if (a == k)
              P += 1.;
            p_grad_u += P * in[2 + 2 * dim + a * dim + k];
            out[o++] = delta * lambda * P;
          }
      out[dim] = delta * p_grad_u;
    }

    std::vector<FormulaInput>  inputs;
    std::vector<FormulaOutput> outputs;

  private:
    double eps, xi, eta_n;
  };

  template <int dim>
  using LocalInextensibility
    = PointwiseTerm<dim, LocalInextensibilityFormula<dim>>;

  extern template class PointwiseTerm<2, LocalInextensibilityFormula<2>>;
  extern template class PointwiseTerm<3, LocalInextensibilityFormula<3>>;
} // namespace vesicle_iga
