#pragma once

#include <vesicle_iga/terms/phase_field_inputs.h>

namespace vesicle_iga
{
  /**
   * Membrane dielectric energy (E7) with psi^n frozen:
   *   E_DM = -3 d_m e_m / (8 sqrt2 eps) int (1 - phi^2)^2 |grad psi|^2;
   * residual (E18) + C ((phi - phi^3) |grad psi|^2, w), Jacobian (E20)
   * + C ((1 - 3 phi^2) |grad psi|^2 dphi, w), C = 3 d_m e_m / (2 sqrt2 eps).
   * As an Integrand: E_DM.
   */
  template <int dim>
  class MembraneDielectricEnergy : public FunctionalTerm<dim>
  {
  public:
    MembraneDielectricEnergy(const unsigned int phi,
                             const unsigned int potential,
                             const double       d_m,
                             const double       e_m,
                             const double       epsilon);
    std::string
    name() const override
    {
      return "membrane_dielectric_energy";
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
    const double          C;
    ResidualHandle        r_value;
    JacobianHandle        k_vv;
  };


  /**
   * Electrolyte dielectric energy (E8) with psi^n frozen:
   *   E_DE = -1/2 int e(phi) |grad psi|^2,
   *   e(phi) = e_in (1 - phi)/2 + e_out (1 + phi)/2;
   * residual (E18) + (e_in - e_out)/4 (|grad psi|^2, w); no Jacobian
   * (linear in phi). With e_in = e_out (the data of spec 3.10) the residual
   * vanishes and the term only shifts the reported energy (spec 7 item 17).
   * As an Integrand: E_DE.
   */
  template <int dim>
  class ElectrolyteDielectricEnergy : public FunctionalTerm<dim>
  {
  public:
    ElectrolyteDielectricEnergy(const unsigned int phi,
                                const unsigned int potential,
                                const double       e_in,
                                const double       e_out);
    std::string
    name() const override
    {
      return "electrolyte_dielectric_energy";
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
    const double          e_in, e_out;
    ResidualHandle        r_value;
  };
} // namespace vesicle_iga
