#pragma once

#include <vesicle_iga/kernel/term.h>

#include <array>

namespace vesicle_iga
{
  /**
   * The inflow condition of a Part H phase field, spec 4.10: the fluid that
   * enters is outside every vesicle, phi_i = -1. Imposed weakly, as the
   * upwind (Nitsche-type) inflow term of the transport equation:
   *   -(r, (u.m)_- (phi - phi_b))_{boundary},  (u.m)_- = min(u.m, 0),
   * added to (H16). It vanishes on walls (u.m = 0), on outflow and wherever
   * phi = -1 already (a vesicle far from the inflow), so it leaves the
   * solution and the energy law of the studies unchanged; what it changes
   * is the Jacobian. Without it the Galerkin transport term
   * (N_i, u.grad N_i) = 1/2 (u.m N_i^2)_{boundary} (div u = 0) is negative
   * for the functions at an inflow boundary, and at dt = 1e-3 it outweighs
   * their (small) mass: HD3's phase-field blocks had 11 negative diagonal
   * entries once the shear had reached its open ends (t = 0.09), and the
   * Gauss-Seidel and ILU smoothers of their multigrid returned 1e24 from a
   * unit residual (doc/hydrodynamics.md, "Linear solver"). With the term
   * the boundary part of the diagonal is 1/2 |u.m| N_i^2 >= 0.
   */
  template <int dim>
  class PhaseFieldInflow : public Term<dim>
  {
  public:
    /// @p periodic: per direction, whether its faces are a periodic seam
    /// (no boundary there).
    PhaseFieldInflow(const unsigned int           velocity,
                     const unsigned int           phi,
                     const std::array<bool, dim> &periodic,
                     const double                 outside_value = -1.);
    std::string
    name() const override
    {
      return "phase_field_inflow";
    }
    typename Term<dim>::Domain
    domain() const override
    {
      return Term<dim>::Domain::boundary;
    }
    bool
    acts_on_face(const unsigned int face) const override
    {
      return !periodic[face / 2];
    }
    void
    declare(TermDeclaration<dim> &d) override;
    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override;

  private:
    const unsigned int              velocity, phi;
    const std::array<bool, dim>     periodic;
    const double                    outside_value;
    std::array<InputHandle, dim>    u;
    InputHandle                     phi_value;
    ResidualHandle                  r_phi;
    JacobianHandle                  j_phi_phi;
    std::array<JacobianHandle, dim> j_phi_u;
  };
} // namespace vesicle_iga
