#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <vesicle_iga/fields/boundary_selection.h>
#include <vesicle_iga/kernel/term.h>

#include <array>
#include <functional>
#include <utility>
#include <vector>

namespace vesicle_iga
{
  /**
   * Isotropic linear elasticity (eps(v), C eps(u)) with the displacement as
   * the dim components starting at @p u (spec Part P, (P3)-(P4) context):
   * residual on the gradient of the test component a, sigma_ak =
   * lambda div u delta_ak + mu (d_k u_a + d_a u_k). In 2D either plane
   * stress (the plate of spec section 5.3: lambda* = 2 lambda mu /
   * (lambda + 2 mu)) or plane strain.
   */
  template <int dim>
  class LinearElasticityTerm : public Term<dim>
  {
  public:
    LinearElasticityTerm(const unsigned int u,
                         const double       young_modulus,
                         const double       poisson_ratio,
                         const bool         plane_stress);
    std::string
    name() const override
    {
      return "linear elasticity";
    }
    void
    declare(TermDeclaration<dim> &d) override;
    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override;

    /// sigma = lambda tr(eps) I + 2 mu eps.
    dealii::SymmetricTensor<2, dim>
    stress(const dealii::SymmetricTensor<2, dim> &strain) const;
    /// eps : C eps, the energy density times two.
    double
    energy_product(const dealii::SymmetricTensor<2, dim> &strain) const
    {
      return stress(strain) * strain;
    }

  private:
    const unsigned int                               u;
    double                                           lambda, mu;
    std::array<std::array<InputHandle, dim>, dim>    gradient;
    std::array<std::array<ResidualHandle, dim>, dim> r_gradient;
    /// The non-zero entries of C: test (a, d_k), trial (c, d_l), value.
    std::vector<std::pair<JacobianHandle, double>> jacobian;
  };


  /// Prescribed traction t(x, n) on the selected boundary: residual
  /// -(v, t) on the components starting at @p u.
  template <int dim>
  class TractionTerm : public Term<dim>
  {
  public:
    using TractionFunction
      = std::function<dealii::Tensor<1, dim>(const dealii::Point<dim> &,
                                             const dealii::Tensor<1, dim> &)>;
    TractionTerm(const unsigned int            u,
                 const BoundarySelection<dim> &selection,
                 TractionFunction              t)
      : u(u)
      , selection(selection)
      , traction(t)
    {}
    std::string
    name() const override
    {
      return "traction";
    }
    typename Term<dim>::Domain
    domain() const override
    {
      return Term<dim>::Domain::boundary;
    }
    bool
    acts_on_face(const unsigned int face) const override
    {
      return selection.touches_face(face);
    }
    void
    declare(TermDeclaration<dim> &d) override
    {
      d.needs_points();
      for (unsigned int a = 0; a < dim; ++a)
        r_value[a] = d.residual(u + a, Derivative<dim>::value);
    }
    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override
    {
      for (unsigned int q = 0; q < in.size(); ++q)
        {
          if (!selection.contains(in.face(), in.point(q)))
            continue;
          const dealii::Tensor<1, dim> t = traction(in.point(q), in.normal(q));
          for (unsigned int a = 0; a < dim; ++a)
            out[r_value[a]][q] -= t[a];
        }
    }

  private:
    const unsigned int              u;
    const BoundarySelection<dim>    selection;
    TractionFunction                traction;
    std::array<ResidualHandle, dim> r_value;
  };
} // namespace vesicle_iga
