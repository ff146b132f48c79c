#pragma once

#include <vesicle_iga/terms/phase_field_inputs.h>

namespace vesicle_iga
{
  /**
   * The area constraint term of (E18), Lambda_A dA/dphi, with the diffuse
   * area (E9)
   *   A = 3/(2 sqrt2) int (eps/2 |grad phi|^2 + (phi^2 - 1)^2 / (4 eps));
   * residual 3 Lambda_A/(2 sqrt2) [(eps grad phi, grad w) + ((phi^3 -
   * phi)/eps, w)], Jacobian its linearisation (E20). Lambda_A is set per
   * Newton solve (E19: explicit in A(phi_n)). As an Integrand: A.
   */
  template <int dim>
  class AreaConstraint : public FunctionalTerm<dim>
  {
  public:
    AreaConstraint(const unsigned int phi, const double epsilon);
    std::string
    name() const override
    {
      return "area";
    }
    void
    set_multiplier(const double Lambda_A)
    {
      Lambda = Lambda_A;
    }
    double
    multiplier() const
    {
      return Lambda;
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
    const double                    eps;
    double                          Lambda = 0;
    ResidualHandle                  r_value;
    std::array<ResidualHandle, dim> r_gradient;
    JacobianHandle                  k_vv;
    std::array<JacobianHandle, dim> k_gg;
  };


  /**
   * The volume constraint term Lambda_V dV/dphi = -Lambda_V/2 of (E18), V =
   * int (1 - phi)/2 (E9). As an Integrand: V.
   */
  template <int dim>
  class VolumeConstraint : public FunctionalTerm<dim>
  {
  public:
    explicit VolumeConstraint(const unsigned int phi)
      : fields(phi)
    {}
    std::string
    name() const override
    {
      return "volume";
    }
    void
    set_multiplier(const double Lambda_V)
    {
      Lambda = Lambda_V;
    }
    double
    multiplier() const
    {
      return Lambda;
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
    double                Lambda = 0;
    ResidualHandle        r_value;
  };
} // namespace vesicle_iga
