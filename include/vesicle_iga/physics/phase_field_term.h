#pragma once

#include <deal.II/base/tensor.h>

#include <string>

namespace vesicle_iga
{
  using namespace dealii;

  /**
   * The phase field at one quadrature point: what every energy term of the
   * Part E residual (E18) may depend on.
   */
  template <int dim>
  struct PhaseFieldPoint
  {
    double         phi = 0;
    Tensor<1, dim> grad_phi;
    double         laplacian_phi = 0;
    /// Gradient of the electric potential psi^n (spec section 3.9: frozen
    /// during the phase-field solve); zero without an applied field.
    Tensor<1, dim> grad_psi;
  };

  /**
   * The contribution of energy terms at one quadrature point, in terms of
   * the "features" of a test function w: its value, gradient and Laplacian,
   * f(w) = [w, dw/dx_1 .. dw/dx_dim, Delta w] (dim + 2 entries):
   *   residual:  R(w)        += sum_k r[k] f_k(w)
   *   tangent:   DR[dphi](w) += sum_kl f_k(w) K[k][l] f_l(dphi).
   * Every term of (E18)/(E20) has this form, so one assembly kernel serves
   * them all and a new energy term is one small class.
   */
  template <int dim>
  struct PointForm
  {
    static constexpr unsigned int n_features = dim + 2;
    static constexpr unsigned int value      = 0;
    static constexpr unsigned int laplacian  = dim + 1;
    static constexpr unsigned int
    gradient(const unsigned int d)
    {
      return 1 + d;
    }

    Tensor<1, dim + 2> r;
    Tensor<2, dim + 2> K;
  };

  /**
   * One term of the phase-field gradient flow (spec section 3.5): the
   * density of its functional and the first and second variations at a
   * point. For an energy (bending, flexoelectric, dielectric) the
   * functional is the energy; for a constraint term it is the constrained
   * quantity (A or V) and the variation is multiplied by the multiplier.
   */
  template <int dim>
  class PhaseFieldTerm
  {
  public:
    virtual ~PhaseFieldTerm() = default;
    /// Short name, used as CSV column (e.g. bending_energy, area).
    virtual std::string
    name() const = 0;
    /// The integrand of the term's functional at a point.
    virtual double
    density(const PhaseFieldPoint<dim> &point) const = 0;
    /// Adds r and K of the term at the point.
    virtual void
    add_variation(const PhaseFieldPoint<dim> &point,
                  PointForm<dim>             &form) const = 0;
  };
} // namespace vesicle_iga
