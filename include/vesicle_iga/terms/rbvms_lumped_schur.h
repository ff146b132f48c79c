#pragma once

#include <vesicle_iga/kernel/term.h>
#include <vesicle_iga/physics/flow_coefficients.h>

#include <array>

namespace vesicle_iga
{
  /// 1 / (nu + tau_C) at a point, tau_C of (H19) for the velocity @p u: the
  /// inverse viscosity of the Stokes Schur complement augmented by the
  /// grad-div term, the weight of the lumped viscous Schur operators.
  template <int dim>
  double
  inverse_schur_viscosity(const dealii::Tensor<2, dim> &G,
                          const dealii::Tensor<1, dim> &u,
                          const double                  time_step,
                          const double                  nu,
                          const double inverse_estimate_constant);

  /**
   * The lumped operators of the Cahouet-Chabard Schur-complement
   * approximation of the flow's block preconditioner
   * (FlowBlockPreconditioner, doc/flow.md), at the state of the step,
   * assembled as a residual: on the velocity rows the lumped transient mass
   * k_m int N_i (k_m = alpha_m, the factor of the velocity rate in the
   * tangent), on the pressure rows the lumped viscous pressure mass
   * k_p int N_i / (mu* / Re + tau_C), the inverse viscosity of the Stokes
   * Schur complement augmented by the grad-div coefficient tau_C of (H19).
   */
  template <int dim>
  class RBVMSLumpedSchurOperators : public Term<dim>
  {
  public:
    RBVMSLumpedSchurOperators(const unsigned int           velocity,
                              const unsigned int           pressure,
                              const FlowCoefficients<dim> &coefficients)
      : velocity(velocity)
      , pressure(pressure)
      , coefficients(coefficients)
    {}
    std::string
    name() const override
    {
      return "lumped Schur operators";
    }
    /// k_m and k_p of the coming assembly (the tangent's factors of the
    /// velocity rate and of the pressure).
    void
    set_factors(const double rate_factor, const double pressure_factor)
    {
      k_m = rate_factor;
      k_p = pressure_factor;
    }
    void
    declare(TermDeclaration<dim> &d) override;
    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override;

  private:
    const unsigned int              velocity, pressure;
    const FlowCoefficients<dim>    &coefficients;
    double                          k_m = 1, k_p = 1;
    std::array<InputHandle, dim>    u;
    std::array<ResidualHandle, dim> r_velocity;
    ResidualHandle                  r_pressure;
  };
} // namespace vesicle_iga
