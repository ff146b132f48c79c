#pragma once

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <string>

namespace vesicle_iga
{

  /**
   * The electric data of spec Part E (section 3.10) and the one place where
   * the SI input is converted to the normalised units of the program:
   * length unit L* (1 um), energy unit E* (kappa = 1e-19 J), potential
   * unit V* (1 V). Then a permittivity e is e L* V*^2 / E* (e_in = 6400,
   * e_m = 440), c1 is c1 L* V* / E* (1000), d_m is d_m / L* (0.005), a
   * field E0 is E0 L* / V* (10 kV/m -> 0.01), and energies convert back to
   * eV by E* / 1.602e-19 J. Conductivities enter only through ratios and
   * stay in S/m. Declared in subsection "Electric field" of a study.
   */
  struct ElectromechanicsMaterial
  {
    // SI input.
    double      field_strength  = 0; // V/m
    std::string field_direction = "y";
    double      sigma_in = 0.3, sigma_out = 1.2, sigma_m = 3e-7; // S/m
    double      e_in = 6.4e-10, e_out = 6.4e-10, e_m = 4.4e-11;  // F/m
    double      c1          = 1e-10;                             // C/m
    double      d_m         = 5e-9;                              // m
    double      length_unit = 1e-6, energy_unit = 1e-19, potential_unit = 1;
    bool        flexoelectric = true, membrane_dielectric = true,
         electrolyte_dielectric = true;
    /// Which prefactor the flexoelectric energy (E6) carries (see
    /// flexoelectric_prefactor()).
    enum class FlexoelectricForm
    {
      source,        ///< (E6) as printed: 3 c1 d_m / (2 sqrt2)
      transmembrane, ///< 2 c1 eps / rho: the sharp E_F of spec 3.1
    };
    FlexoelectricForm flexoelectric_form = FlexoelectricForm::source;

    static void
    declare(dealii::ParameterHandler &prm);
    void
    parse(dealii::ParameterHandler &prm, const unsigned int dim);

    /// Whether any electric term is active (E0 > 0).
    bool
    active() const
    {
      return field_strength > 0;
    }
    unsigned int
    direction() const
    {
      return field_direction[0] - 'x';
    }

    // Normalised values (spec 3.10).
    double
    permittivity(const double e_SI) const
    {
      return e_SI * length_unit * potential_unit * potential_unit / energy_unit;
    }
    double
    flexoelectric_coefficient() const
    {
      return c1 * length_unit * potential_unit / energy_unit;
    }
    double
    membrane_thickness() const
    {
      return d_m / length_unit;
    }
    double
    field() const
    {
      return field_strength * length_unit / potential_unit;
    }
    /**
     * The prefactor C of E_F = -C int (eps Lap phi + h) grad phi.grad psi
     * (E6), normalised units.
     *
     * source: C = 3 c1 d_m / (2 sqrt2), the recast of Appendix A, which
     * treats E.m as one value across the membrane. With the potential of
     * (E16) almost all of the transmembrane potential Delta V drops where
     * sigma (E10) dips, over about 0.43 eps, so E_F of this form sees
     * Delta V / (1.89 eps) instead of Delta V / d_m and grows as 1 / eps
     * (doc/validation.md, 2c): no sharp-interface limit.
     *
     * transmembrane: C = 2 c1 eps / rho. Since (1 - phi^2)^2 div(m)
     * m.grad psi = 2 eps (eps Lap phi + h) grad phi.grad psi (spec 3.2), this
     * is E_F = -(c1 / rho) int (1 - phi^2)^2 div(m) m.grad psi, whose
     * integral across the membrane is rho Delta V / rho = Delta V: the limit
     * is the sharp E_F of spec 3.1 with E the field inside the membrane,
     * -c1 closed-int div(m) Delta V, bounded uniformly in eps (Delta V is).
     * rho = transmembrane_drop_fraction().
     */
    double
    flexoelectric_prefactor(const double epsilon) const;

    /**
     * rho: the fraction of the transmembrane potential that the weight
     * (1 - phi^2)^2 of (E2) sees across a flat membrane phi = tanh(n /
     * (sqrt2 eps)) carrying a uniform current j (sigma psi' = j, (E16) in
     * 1D): int (1 - phi^2)^2 / sigma dn / int (1 / sigma - 1 / sigma_ref) dn,
     * sigma_ref the electrolyte's conductivity on each side. A property of
     * sigma(phi) alone (both integrals scale with eps): 0.9823 for the data
     * of spec 3.10. Computed by a midpoint rule on n / eps in [-12, 12].
     */
    double
    transmembrane_drop_fraction() const;

    /// Normalised energy to eV.
    double
    to_eV(const double energy) const
    {
      return energy * energy_unit / 1.602176634e-19;
    }

    /// sigma(phi) of (E10) (as printed in the source, spec 7 item 16).
    double
    conductivity(const double phi) const
    {
      const double p8 = std::pow(phi, 8);
      return 0.25 * sigma_in * (1 - phi) * (1 - phi) * p8
             + 0.25 * sigma_m * (1 - phi) * (1 - phi) * (1 + phi) * (1 + phi)
             + 0.25 * sigma_out * (1 + phi) * (1 + phi) * p8;
    }
  };
} // namespace vesicle_iga
