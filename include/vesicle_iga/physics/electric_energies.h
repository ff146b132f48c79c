#pragma once

#include <vesicle_iga/physics/phase_field_term.h>

namespace vesicle_iga
{
  /**
   * The three electric energies of spec Part E (section 3.3) as phase-field
   * terms, with the potential psi^n frozen (staggered scheme, spec 3.9).
   * All coefficients are in the normalised units of spec 3.10 (see
   * ElectromechanicsMaterial, which converts the SI input). Each term is
   * the only place where its energy, its first variation (E18) and its
   * second variation (E20) are written.
   */

  /**
   * Flexoelectric energy (E6):
   *   E_F = -C int (eps Delta phi + h(phi)) grad phi . grad psi,
   *   C = 3 c1 d_m / (2 sqrt2),  h = phi (1 - phi^2) / eps.
   * (E18), second line: -C [(h' grad phi.grad psi, w)
   *   + (eps grad phi.grad psi, Delta w) + ((eps Delta phi + h) grad psi,
   *   grad w)]; (E20) the same line linearised (symmetric with psi fixed).
   */
  template <int dim>
  class FlexoelectricEnergy : public PhaseFieldTerm<dim>
  {
  public:
    FlexoelectricEnergy(const double c1, const double d_m, const double eps);
    std::string
    name() const override
    {
      return "flexoelectric_energy";
    }
    double
    density(const PhaseFieldPoint<dim> &p) const override;
    void
    add_variation(const PhaseFieldPoint<dim> &p,
                  PointForm<dim>             &form) const override;

  private:
    const double C, eps;
  };

  /**
   * Membrane dielectric energy (E7):
   *   E_DM = -3 d_m e_m / (8 sqrt2 eps) int (1 - phi^2)^2 |grad psi|^2;
   * (E18): + 3 d_m e_m / (2 sqrt2 eps) ((phi - phi^3) |grad psi|^2, w),
   * (E20): + 3 d_m e_m / (2 sqrt2 eps) ((1 - 3 phi^2) |grad psi|^2 dphi, w).
   */
  template <int dim>
  class MembraneDielectricEnergy : public PhaseFieldTerm<dim>
  {
  public:
    MembraneDielectricEnergy(const double d_m,
                             const double e_m,
                             const double eps);
    std::string
    name() const override
    {
      return "membrane_dielectric_energy";
    }
    double
    density(const PhaseFieldPoint<dim> &p) const override;
    void
    add_variation(const PhaseFieldPoint<dim> &p,
                  PointForm<dim>             &form) const override;

  private:
    const double C;
  };

  /**
   * Electrolyte dielectric energy (E8):
   *   E_DE = -1/2 int e(phi) |grad psi|^2,
   *   e(phi) = e_in (1 - phi)/2 + e_out (1 + phi)/2;
   * (E18): + (e_in - e_out)/4 (|grad psi|^2, w); no tangent (linear in
   * phi). With e_in = e_out (the data of spec 3.10) the variation vanishes
   * and the term only shifts the reported energy (spec 7 item 17).
   */
  template <int dim>
  class ElectrolyteDielectricEnergy : public PhaseFieldTerm<dim>
  {
  public:
    ElectrolyteDielectricEnergy(const double e_in, const double e_out);
    std::string
    name() const override
    {
      return "electrolyte_dielectric_energy";
    }
    double
    density(const PhaseFieldPoint<dim> &p) const override;
    void
    add_variation(const PhaseFieldPoint<dim> &p,
                  PointForm<dim>             &form) const override;

  private:
    const double e_in, e_out;
  };
} // namespace vesicle_iga
