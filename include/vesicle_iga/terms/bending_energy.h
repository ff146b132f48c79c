#pragma once

#include <vesicle_iga/terms/phase_field_inputs.h>

namespace vesicle_iga
{
  /**
   * Phase-field Helfrich bending energy, spec (E4)-(E5):
   *   E_B = 3 kappa / (4 sqrt2 eps) int W^2,  W = eps Delta phi + g(phi),
   *   g = (phi/eps - H_sp/sqrt2)(1 - phi^2).
   * Residual: the bending line of (E18),
   *   c (W, eps Delta w + g'(phi) w),  c = 3 kappa / (2 sqrt2 eps);
   * Jacobian: the bending line of (E20),
   *   c [(eps Delta dphi + g' dphi, eps Delta w + g' w) + (W g'' dphi, w)].
   * As an Integrand: E_B.
   */
  template <int dim>
  class BendingEnergy : public FunctionalTerm<dim>
  {
  public:
    BendingEnergy(const unsigned int phi,
                  const double       kappa,
                  const double       epsilon,
                  const double       spontaneous_curvature);

    std::string
    name() const override
    {
      return "bending_energy";
    }
    void
    declare(TermDeclaration<dim> &d) override;
    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override;

    void
    integrate(const QuadratureInputs<dim> &in,
              const double                *JxW,
              double                      *sums) const override;

  private:
    PhaseFieldInputs<dim> fields;
    const double          kappa, eps, H_sp;
    ResidualHandle        r_value, r_laplacian;
    JacobianHandle        k_vv, k_vl, k_lv, k_ll;
  };
} // namespace vesicle_iga
