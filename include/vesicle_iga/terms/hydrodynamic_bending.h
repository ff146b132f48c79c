#pragma once

#include <vesicle_iga/kernel/pointwise_term.h>
#include <vesicle_iga/physics/hydrodynamic_membrane.h>

namespace vesicle_iga
{
  /**
   * The bending force of a vesicle in the flow, mixed-free (spec 4.13): the
   * chemical potential g = (1 / (Re Ca)) (Delta f - (3 phi^2 - 1) f /
   * eps^2) of (H3), with f = f(phi) of (H2) evaluated from the spline
   * Hessian, enters the phase-field equation (H16) and the momentum forcing
   * of (H14) through one bilinear pairing
   *   b(f; v) = (1 / (Re Ca)) [(f, Delta v) - ((3 phi^2 - 1) f / eps^2, v)],
   * (H24) with v = r (phase-field test, times eta_phi) and (H25) with
   * v = w . grad phi (momentum test, with the sign of (H14)):
   *   eta_phi b(f; r)  -  b(f; w . grad phi),
   * Delta(w . grad phi) = Delta w . grad phi + 2 grad w : grad grad phi
   *                       + w . grad Delta phi.
   * The same pairing in both places makes the advection power and the
   * forcing power cancel (the discrete energy law). Needs third
   * derivatives of phi: cubic C^2 splines.
   */
  template <int dim>
  struct HydrodynamicBendingFormula
  {
    static constexpr int n_hessian  = dim * (dim + 1) / 2;
    static constexpr int max_inputs = 1 + dim + n_hessian + dim;
    HydrodynamicBendingFormula(const unsigned int          velocity,
                               const unsigned int          phi,
                               const MembraneCoefficients &coefficients);
    std::string
    name() const
    {
      return "hydrodynamic_bending";
    }
    template <typename T>
    void
    residual(const T *in, T *out) const;

    std::vector<FormulaInput>  inputs;
    std::vector<FormulaOutput> outputs;

  private:
    /// Position of the Hessian entry (k, l) in the inputs.
    static unsigned int
           hessian(const unsigned int k, const unsigned int l);
    double eps, eta, c;
  };

  template <int dim>
  using HydrodynamicBending
    = PointwiseTerm<dim, HydrodynamicBendingFormula<dim>>;

  extern template class PointwiseTerm<2, HydrodynamicBendingFormula<2>>;
  extern template class PointwiseTerm<3, HydrodynamicBendingFormula<3>>;


  /// The bending energy of one vesicle, (1 / (2 eps Re Ca)) int f^2, whose
  /// first variation is (r, g) of (H24).
  template <int dim>
  class HydrodynamicBendingEnergy : public Integrand<dim>
  {
  public:
    HydrodynamicBendingEnergy(const unsigned int          phi,
                              const MembraneCoefficients &coefficients)
      : phi(phi)
      , coefficients(coefficients)
    {}
    unsigned int
    n_values() const override
    {
      return 1;
    }
    void
    declare(TermDeclaration<dim> &d) override;
    void
    integrate(const QuadratureInputs<dim> &in,
              const double                *JxW,
              double                      *sums) const override;

  private:
    const unsigned int         phi;
    const MembraneCoefficients coefficients;
    InputHandle                value, laplacian;
  };
} // namespace vesicle_iga
