#pragma once

#include <vesicle_iga/kernel/term.h>
#include <vesicle_iga/physics/flow_coefficients.h>
#include <vesicle_iga/physics/hydrodynamic_membrane.h>

#include <array>

namespace vesicle_iga
{
  /**
   * The lumped viscous operator of the tension Schur complement of the
   * vesicle block preconditioner (VesicleBlockPreconditioner,
   * doc/hydrodynamics.md), assembled as a residual on the rows of
   * lambda_i: k_lambda int delta_eps(phi_i)^2 N / (mu* / Re + tau_C). The
   * inextensibility rows of (H17) act on the velocity through
   * (s, delta_eps P : grad u); a Stokes solve answers a surface divergence
   * with the inverse viscosity of the pressure Schur complement, so
   * E F^-1 E^T ~ delta_eps^2 / (mu* / Re + tau_C) in the viscous limit
   * (k_lambda: the tangent's factor of the tension).
   */
  template <int dim>
  class TensionLumpedSchur : public Term<dim>
  {
  public:
    TensionLumpedSchur(const unsigned int           velocity,
                       const unsigned int           phi,
                       const unsigned int           tension,
                       const FlowCoefficients<dim> &flow,
                       const MembraneCoefficients  &membrane)
      : velocity(velocity)
      , phi(phi)
      , tension(tension)
      , flow(flow)
      , eps(membrane.epsilon)
    {}
    std::string
    name() const override
    {
      return "lumped tension Schur operator";
    }
    void
    set_factor(const double tension_factor)
    {
      k_lambda = tension_factor;
    }
    void
    declare(TermDeclaration<dim> &d) override;
    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override;

  private:
    const unsigned int           velocity, phi, tension;
    const FlowCoefficients<dim> &flow;
    const double                 eps;
    double                       k_lambda = 1;
    std::array<InputHandle, dim> u;
    InputHandle                  phase;
    ResidualHandle               r_tension;
  };
} // namespace vesicle_iga
