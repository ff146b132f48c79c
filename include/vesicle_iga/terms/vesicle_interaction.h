#pragma once

#include <vesicle_iga/kernel/pointwise_term.h>
#include <vesicle_iga/physics/hydrodynamic_membrane.h>

namespace vesicle_iga
{
  /**
   * The short-range repulsion between two vesicles i < j, (H10)-(H11):
   *   E_ij = (1 / (Re IN)) int B(phi_i) w(phi_j) + B(phi_j) w(phi_i),
   *   vs_i = dE_ij / dphi_i = (1 / (Re IN)) [B'(phi_i) w(phi_j)
   *                                          + w'(phi_i) B(phi_j)],
   * in both phase-field equations (H16) and, with the sign of (H14), in the
   * momentum forcing:
   *   eta_phi (r_i, vs_i) + eta_phi (r_j, vs_j)
   *   - (w, vs_i grad phi_i + vs_j grad phi_j).
   * With the numerics of spec 4.4 (clipping, underflow). One term per pair:
   * N vesicles have N (N - 1) / 2 of them.
   */
  template <int dim>
  struct VesicleInteractionFormula
  {
    static constexpr int max_inputs = 2 + 2 * dim;
    VesicleInteractionFormula(const unsigned int          velocity,
                              const unsigned int          phi_i,
                              const unsigned int          phi_j,
                              const MembraneCoefficients &coefficients);
    std::string
    name() const
    {
      return "vesicle_interaction";
    }
    /// vs_i of (H11) from phi_i and phi_j.
    template <typename T>
    T
    potential(const T &phi_i, const T &phi_j) const
    {
      return k
             * (membrane::interaction_b_derivative(phi_i, eps)
                  * membrane::interaction_w(phi_j)
                + membrane::interaction_w_derivative(phi_i)
                    * membrane::interaction_b(phi_j, eps));
    }
    /// The integrand of (H10).
    double
    energy_density(const double phi_i, const double phi_j) const
    {
      return k
             * (membrane::interaction_b(phi_i, eps)
                  * membrane::interaction_w(phi_j)
                + membrane::interaction_b(phi_j, eps)
                    * membrane::interaction_w(phi_i));
    }
    template <typename T>
    void
    residual(const T *in, T *out) const
    {
      // in: phi_i, phi_j, d_a phi_i, d_a phi_j.
      const T vs_i = potential(in[0], in[1]);
      const T vs_j = potential(in[1], in[0]);
      out[0]       = eta * vs_i;
      out[1]       = eta * vs_j;
      for (unsigned int a = 0; a < dim; ++a)
        out[2 + a] = -(vs_i * in[2 + a] + vs_j * in[2 + dim + a]);
    }

    std::vector<FormulaInput>  inputs;
    std::vector<FormulaOutput> outputs;

  private:
    double eps, eta, k;
  };

  template <int dim>
  using VesicleInteraction = PointwiseTerm<dim, VesicleInteractionFormula<dim>>;

  extern template class PointwiseTerm<2, VesicleInteractionFormula<2>>;
  extern template class PointwiseTerm<3, VesicleInteractionFormula<3>>;


  /// E_ij of (H10) for one pair.
  template <int dim>
  class InteractionEnergy : public Integrand<dim>
  {
  public:
    InteractionEnergy(const unsigned int                    phi_i,
                      const unsigned int                    phi_j,
                      const VesicleInteractionFormula<dim> &formula)
      : phi_i(phi_i)
      , phi_j(phi_j)
      , formula(formula)
    {}
    unsigned int
    n_values() const override
    {
      return 1;
    }
    void
    declare(TermDeclaration<dim> &d) override
    {
      value_i = d.value(phi_i, Derivative<dim>::value);
      value_j = d.value(phi_j, Derivative<dim>::value);
    }
    void
    integrate(const QuadratureInputs<dim> &in,
              const double                *JxW,
              double                      *sums) const override
    {
      for (unsigned int q = 0; q < in.size(); ++q)
        sums[0]
          += formula.energy_density(in[value_i][q], in[value_j][q]) * JxW[q];
    }

  private:
    const unsigned int                    phi_i, phi_j;
    const VesicleInteractionFormula<dim> &formula;
    InputHandle                           value_i, value_j;
  };
} // namespace vesicle_iga
