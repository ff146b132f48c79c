#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/physics/electromechanics_material.h>

namespace vesicle_iga
{
  using namespace dealii;

  void
  ElectromechanicsMaterial::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Electric field");
    prm.declare_entry("Field strength",
                      "0",
                      Patterns::Double(0),
                      "Nominal field E0 in V/m (spec 3.6: psi = +-E0 L/2 on "
                      "the two faces normal to the field direction); 0: no "
                      "electric terms (the Willmore flow).");
    prm.declare_entry("Field direction",
                      "y",
                      Patterns::Selection("x|y|z"),
                      "Direction of the applied field (spec: y).");
    prm.declare_entry("Conductivity inside",
                      "0.3",
                      Patterns::Double(0),
                      "sigma_in in S/m (spec 3.10: 0.3).");
    prm.declare_entry("Conductivity outside",
                      "1.2",
                      Patterns::Double(0),
                      "sigma_out in S/m (spec 3.10: 1.2).");
    prm.declare_entry("Membrane conductivity",
                      "3e-7",
                      Patterns::Double(0),
                      "sigma_m in S/m (spec 3.10: 3e-7).");
    prm.declare_entry("Permittivity inside",
                      "6.4e-10",
                      Patterns::Double(0),
                      "e_in in F/m (spec 3.10: 6.4e-10).");
    prm.declare_entry("Permittivity outside",
                      "6.4e-10",
                      Patterns::Double(0),
                      "e_out in F/m (spec 3.10: 6.4e-10).");
    prm.declare_entry("Membrane permittivity",
                      "4.4e-11",
                      Patterns::Double(0),
                      "e_m in F/m (spec 3.10: 4.4e-11).");
    prm.declare_entry("Flexoelectric coefficient",
                      "1e-10",
                      Patterns::Double(0),
                      "c1 in C/m (spec 3.10: 1e-10).");
    prm.declare_entry("Membrane thickness",
                      "5e-9",
                      Patterns::Double(0),
                      "d_m in m (not given by the source; spec 7 item 10: "
                      "5 nm).");
    prm.declare_entry("Flexoelectric energy",
                      "true",
                      Patterns::Bool(),
                      "Include E_F (E6).");
    prm.declare_entry(
      "Flexoelectric form",
      "source",
      Patterns::Selection("source|transmembrane"),
      "The prefactor of (E6). source: 3 c1 d_m / (2 sqrt2) as printed "
      "(Appendix A); with the potential of (E16) the membrane's potential "
      "drop happens over about 0.43 eps, so this E_F sees Delta V / (1.89 "
      "eps) instead of Delta V / d_m and grows as 1 / eps: the results "
      "depend on eps (doc/validation.md, item 2). transmembrane: 2 c1 eps / "
      "rho (rho = 0.98 from sigma(phi) (E10)), whose limit eps -> 0 is the "
      "sharp E_F = -c1 closed-int div(m) Delta V of spec 3.1 (field inside "
      "the membrane), bounded uniformly in eps. The source's E_F at a given "
      "eps is the transmembrane form with c1 replaced by rho d_m c1 / (1.886 "
      "eps).");
    prm.declare_entry("Membrane dielectric energy",
                      "true",
                      Patterns::Bool(),
                      "Include E_DM (E7).");
    prm.declare_entry("Electrolyte dielectric energy",
                      "true",
                      Patterns::Bool(),
                      "Include E_DE (E8).");
    prm.declare_entry("Length unit",
                      "1e-6",
                      Patterns::Double(0),
                      "L* in m: the mesh coordinates are in this unit "
                      "(spec 3.10: 1 um).");
    prm.declare_entry("Energy unit",
                      "1e-19",
                      Patterns::Double(0),
                      "E* in J (spec 3.10: kappa = 1e-19 J).");
    prm.declare_entry("Potential unit",
                      "1",
                      Patterns::Double(0),
                      "V* in V (spec 3.10: 1 V).");
    prm.leave_subsection();
  }


  void
  ElectromechanicsMaterial::parse(ParameterHandler &prm, const unsigned int dim)
  {
    prm.enter_subsection("Electric field");
    field_strength         = prm.get_double("Field strength");
    field_direction        = prm.get("Field direction");
    sigma_in               = prm.get_double("Conductivity inside");
    sigma_out              = prm.get_double("Conductivity outside");
    sigma_m                = prm.get_double("Membrane conductivity");
    e_in                   = prm.get_double("Permittivity inside");
    e_out                  = prm.get_double("Permittivity outside");
    e_m                    = prm.get_double("Membrane permittivity");
    c1                     = prm.get_double("Flexoelectric coefficient");
    d_m                    = prm.get_double("Membrane thickness");
    flexoelectric          = prm.get_bool("Flexoelectric energy");
    flexoelectric_form     = prm.get("Flexoelectric form") == "transmembrane" ?
                               FlexoelectricForm::transmembrane :
                               FlexoelectricForm::source;
    membrane_dielectric    = prm.get_bool("Membrane dielectric energy");
    electrolyte_dielectric = prm.get_bool("Electrolyte dielectric energy");
    length_unit            = prm.get_double("Length unit");
    energy_unit            = prm.get_double("Energy unit");
    potential_unit         = prm.get_double("Potential unit");
    prm.leave_subsection();
    check_input(direction() < dim,
                "Electric field/Field direction",
                field_direction,
                "a direction of the " + std::to_string(dim) + "D domain");
    if (active())
      {
        check_input(sigma_in > 0 && sigma_out > 0 && sigma_m > 0,
                    "Electric field/Membrane conductivity",
                    value_text(sigma_m),
                    "positive conductivities (sigma(phi) of (E10) must stay "
                    "positive for the potential problem (E17))");
        check_input(length_unit > 0 && energy_unit > 0 && potential_unit > 0,
                    "Electric field/Energy unit",
                    value_text(energy_unit),
                    "positive units");
      }
  }


  double
  ElectromechanicsMaterial::flexoelectric_prefactor(const double epsilon) const
  {
    const double c1_normalised = flexoelectric_coefficient();
    if (flexoelectric_form == FlexoelectricForm::source)
      return 3 * c1_normalised * membrane_thickness()
             / (2 * std::sqrt(2.)); // (E6)
    return 2 * c1_normalised * epsilon / transmembrane_drop_fraction();
  }


  double
  ElectromechanicsMaterial::transmembrane_drop_fraction() const
  {
    // In units of eps. At |n| = 12, (1 - phi^2)^2 is 3e-14 and 1 / sigma -
    // 1 / sigma_ref is (phi^-8 - 1) / sigma_ref ~ 1e-6 / sigma_ref, against
    // the membrane's 1.7 / sigma_m: the tails left out are below 1e-12.
    const unsigned int n_points = 240000;
    const double       L = 12, dn = 2 * L / n_points;
    double             seen = 0, drop = 0;
    for (unsigned int i = 0; i < n_points; ++i)
      {
        const double n     = -L + (i + 0.5) * dn;
        const double phi   = std::tanh(n / std::sqrt(2.));
        const double sigma = conductivity(phi);
        const double w     = (1 - phi * phi) * (1 - phi * phi);
        seen += w / sigma * dn;
        drop += (1 / sigma - 1 / (n < 0 ? sigma_in : sigma_out)) * dn;
      }
    return seen / drop;
  }
} // namespace vesicle_iga
