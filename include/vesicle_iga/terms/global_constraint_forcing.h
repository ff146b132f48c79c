#pragma once

#include <vesicle_iga/kernel/pointwise_term.h>
#include <vesicle_iga/physics/hydrodynamic_membrane.h>

namespace vesicle_iga
{
  /**
   * The global area and volume multipliers of one vesicle in the flow:
   * the part -lambda_g f - lambda_v beta(phi) of the chemical potential of
   * (H1), with f of (H2), in the phase-field equation (H16) and, with the
   * sign of (H14), in the momentum forcing:
   *   eta_phi (r, -lambda_g f - lambda_v beta)  +  (w, (lambda_g f +
   *   lambda_v beta) grad phi),
   * beta = delta_eps(phi) of (H12b) (membrane volume multiplier, default)
   * or 1 (the source's (H1)); see MembraneCoefficients. The forcing keeps
   * the partner of the advection term, so the energy law of spec 4.3 holds
   * with either.
   * lambda_g, lambda_v are constants within a step, from the (H13) solve
   * after the previous step (set_multipliers).
   */
  template <int dim>
  struct GlobalConstraintForcingFormula
  {
    static constexpr int max_inputs = 2 + dim;
    GlobalConstraintForcingFormula(const unsigned int          velocity,
                                   const unsigned int          phi,
                                   const MembraneCoefficients &coefficients);
    std::string
    name() const
    {
      return "global_constraint_forcing";
    }
    void
    set_multipliers(const double area, const double volume)
    {
      lambda_g = area;
      lambda_v = volume;
    }
    template <typename T>
    void
    residual(const T *in, T *out) const
    {
      // in: phi, Delta phi, d_a phi.
      const T f = membrane::chemical_potential(in[0], in[1], eps);
      const T m
        = -lambda_g * f
          - lambda_v * membrane::volume_multiplier_weight(in[0], eps, local);
      out[0] = eta * m;
      for (unsigned int a = 0; a < dim; ++a)
        out[1 + a] = -m * in[2 + a];
    }

    std::vector<FormulaInput>  inputs;
    std::vector<FormulaOutput> outputs;

  private:
    double eps, eta;
    bool   local;
    /// Nonzero while the pattern of the Jacobian is probed.
    double lambda_g = 1, lambda_v = 1;
  };

  template <int dim>
  using GlobalConstraintForcing
    = PointwiseTerm<dim, GlobalConstraintForcingFormula<dim>>;

  extern template class PointwiseTerm<2, GlobalConstraintForcingFormula<2>>;
  extern template class PointwiseTerm<3, GlobalConstraintForcingFormula<3>>;
} // namespace vesicle_iga
