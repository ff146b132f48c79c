#pragma once

#include <vesicle_iga/kernel/pointwise_term.h>

namespace vesicle_iga
{
  /**
   * Transport of a Part H phase field by the flow, the first line of (H16):
   *   (r, dphi/dt + u . grad phi).
   * Its momentum partner (the forcing with the chemical potential, (H14)) is
   * part of each chemical-potential term (hydrodynamic_bending,
   * global_constraint_forcing, vesicle_interaction), so that each term keeps
   * its own energy balance.
   */
  template <int dim>
  struct PhaseFieldAdvectionFormula
  {
    static constexpr int max_inputs = 1 + 2 * dim;
    /// @p velocity: flat component of u_1; @p phi: of the phase field.
    PhaseFieldAdvectionFormula(const unsigned int velocity,
                               const unsigned int phi);
    std::string
    name() const
    {
      return "phase_field_advection";
    }
    template <typename T>
    void
    residual(const T *in, T *out) const
    {
      // in: rate of phi, u_a, d_a phi.
      T r = in[0];
      for (unsigned int a = 0; a < dim; ++a)
        r += in[1 + a] * in[1 + dim + a];
      out[0] = r;
    }
    std::vector<FormulaInput>  inputs;
    std::vector<FormulaOutput> outputs;
  };

  template <int dim>
  using PhaseFieldAdvection
    = PointwiseTerm<dim, PhaseFieldAdvectionFormula<dim>>;

  extern template class PointwiseTerm<2, PhaseFieldAdvectionFormula<2>>;
  extern template class PointwiseTerm<3, PhaseFieldAdvectionFormula<3>>;
} // namespace vesicle_iga
