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
    double         phi;
    Tensor<1, dim> grad_phi;
    double         laplacian_phi;
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
   * One energy term of the phase-field gradient flow (spec section 3.5):
   * its energy density and its first and second variations at a point.
   */
  template <int dim>
  class PhaseFieldTerm
  {
  public:
    virtual ~PhaseFieldTerm() = default;
    virtual std::string
    name() const = 0;
    /// Adds r and K of the term at the point.
    virtual void
    add_variation(const PhaseFieldPoint<dim> &point,
                  PointForm<dim>             &form) const = 0;
  };
} // namespace vesicle_iga
