#pragma once

#include <vesicle_iga/terms/phase_field_inputs.h>

namespace vesicle_iga
{
  /**
   * Flexoelectric energy (E6) with the potential psi^n frozen (spec 3.9):
   *   E_F = -C int (eps Delta phi + h(phi)) grad phi . grad psi,
   *   h = phi (1 - phi^2) / eps,
   * with C = 3 c1 d_m / (2 sqrt2) as printed, or the prefactor of the
   * transmembrane form (ElectromechanicsMaterial::flexoelectric_prefactor()).
   * Residual, the second line of (E18):
   *   -C [(h' grad phi.grad psi, w) + (eps grad phi.grad psi, Delta w)
   *       + ((eps Delta phi + h) grad psi, grad w)];
   * Jacobian, the same line of (E20) (symmetric with psi fixed). All
   * coefficients in the normalised units of spec 3.10. As an Integrand: E_F.
   */
  template <int dim>
  class FlexoelectricEnergy : public FunctionalTerm<dim>
  {
  public:
    /// @p potential: the auxiliary field of psi; @p prefactor: C.
    FlexoelectricEnergy(const unsigned int phi,
                        const unsigned int potential,
                        const double       prefactor,
                        const double       epsilon);
    std::string
    name() const override
    {
      return "flexoelectric_energy";
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
    PhaseFieldInputs<dim>           fields;
    const double                    C, eps;
    ResidualHandle                  r_value, r_laplacian;
    std::array<ResidualHandle, dim> r_gradient;
    JacobianHandle                  k_vv;
    std::array<JacobianHandle, dim> k_vg, k_lg, k_gl, k_gv;
  };
} // namespace vesicle_iga
