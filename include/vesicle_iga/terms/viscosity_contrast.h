#pragma once

#include <vesicle_iga/kernel/pointwise_term.h>
#include <vesicle_iga/physics/hydrodynamic_membrane.h>

namespace vesicle_iga
{
  /**
   * The viscous stress of the vesicles' interior beyond that of the outer
   * fluid, for a viscosity ratio beta_mu != 1, (H12a):
   *   (grad w, ((mu*(phi_bar) - 1) / Re) 2 D(u)),
   *   mu* - 1 = (1 + phi_bar) (beta_mu - 1) / 2,
   *   phi_bar = sum_i phi_i + N - 1  (+1 inside any vesicle, -1 outside all;
   *   spec 4.5 for N = 2).
   * The RBVMS term carries the outer viscosity (mu_o = 1 in tau_M, (H19));
   * this term adds the rest, with its dependence on every phi_i.
   */
  template <int dim>
  struct ViscosityContrastFormula
  {
    static constexpr int max_inputs = 24 + dim * dim;
    /// @p phases: flat components of phi_1 .. phi_N.
    ViscosityContrastFormula(const unsigned int               velocity,
                             const std::vector<unsigned int> &phases,
                             const MembraneCoefficients      &coefficients);
    std::string
    name() const
    {
      return "viscosity_contrast";
    }
    template <typename T>
    void
    residual(const T *in, T *out) const
    {
      // in: phi_1 .. phi_N, d_k u_a (a major).
      T phi_bar(n_phases - 1.);
      for (unsigned int i = 0; i < n_phases; ++i)
        phi_bar += in[i];
      const T factor = 0.5 * (1. + phi_bar) * (beta - 1.) / Re;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int k = 0; k < dim; ++k)
          out[a * dim + k]
            = factor
              * (in[n_phases + a * dim + k] + in[n_phases + k * dim + a]);
    }

    std::vector<FormulaInput>  inputs;
    std::vector<FormulaOutput> outputs;

  private:
    unsigned int n_phases;
    double       beta, Re;
  };

  template <int dim>
  using ViscosityContrast = PointwiseTerm<dim, ViscosityContrastFormula<dim>>;

  extern template class PointwiseTerm<2, ViscosityContrastFormula<2>>;
  extern template class PointwiseTerm<3, ViscosityContrastFormula<3>>;
} // namespace vesicle_iga
