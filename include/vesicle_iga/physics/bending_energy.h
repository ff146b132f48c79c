#pragma once

#include <vesicle_iga/physics/phase_field_term.h>

namespace vesicle_iga
{
  /**
   * Phase-field Helfrich bending energy (spec (E4)-(E5)):
   *   E_B = 3 kappa / (4 sqrt2 eps) int W^2,  W = eps Delta phi + g(phi),
   *   g = (phi/eps - H_sp/sqrt2)(1 - phi^2).
   * First variation: the bending line of (E18); second: that of (E20).
   */
  template <int dim>
  class BendingEnergy : public PhaseFieldTerm<dim>
  {
  public:
    BendingEnergy(const double kappa,
                  const double epsilon,
                  const double spontaneous_curvature)
      : kappa(kappa)
      , eps(epsilon)
      , H_sp(spontaneous_curvature)
    {}
    std::string
    name() const override
    {
      return "bending_energy";
    }
    /// Energy density 3 kappa W^2 / (4 sqrt2 eps).
    double
    density(const PhaseFieldPoint<dim> &p) const override;
    void
    add_variation(const PhaseFieldPoint<dim> &point,
                  PointForm<dim>             &form) const override;

  private:
    double
    g(const double phi) const;
    double
    g1(const double phi) const;
    double
    g2(const double phi) const;

    const double kappa, eps, H_sp;
  };

  /**
   * The area constraint term Lambda_A dA/dphi of (E18) with the diffuse
   * area (E9), A = 3/(2 sqrt2) int (eps/2 |grad phi|^2 + (phi^2-1)^2/(4 eps));
   * Lambda_A is set per Newton solve (E19: explicit in A(phi_n)).
   */
  template <int dim>
  class AreaConstraint : public PhaseFieldTerm<dim>
  {
  public:
    explicit AreaConstraint(const double epsilon)
      : eps(epsilon)
    {}
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
    /// Density of A (E9).
    double
    density(const PhaseFieldPoint<dim> &p) const override;
    void
    add_variation(const PhaseFieldPoint<dim> &point,
                  PointForm<dim>             &form) const override;

  private:
    const double eps;
    double       Lambda = 0;
  };

  /// The volume constraint term Lambda_V dV/dphi = -Lambda_V/2 of (E18),
  /// V = int (1 - phi)/2 (E9).
  template <int dim>
  class VolumeConstraint : public PhaseFieldTerm<dim>
  {
  public:
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
    double
    density(const PhaseFieldPoint<dim> &p) const override
    {
      return 0.5 * (1 - p.phi);
    }
    void
    add_variation(const PhaseFieldPoint<dim> &,
                  PointForm<dim> &form) const override
    {
      form.r[PointForm<dim>::value] += -0.5 * Lambda;
    }

  private:
    double Lambda = 0;
  };
} // namespace vesicle_iga
