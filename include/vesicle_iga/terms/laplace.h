#pragma once

#include <deal.II/base/function.h>

#include <vesicle_iga/fields/boundary_selection.h>
#include <vesicle_iga/kernel/term.h>

#include <array>
#include <functional>

namespace vesicle_iga
{
  /// The Poisson operator -Delta u = f: residual (grad v, grad u) - (v, f)
  /// on component @p u.
  template <int dim>
  class LaplaceTerm : public Term<dim>
  {
  public:
    LaplaceTerm(const unsigned int u, const dealii::Function<dim> &f)
      : u(u)
      , f(f)
    {}
    std::string
    name() const override
    {
      return "laplace";
    }
    void
    declare(TermDeclaration<dim> &d) override;
    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override;

  private:
    const unsigned int              u;
    const dealii::Function<dim>    &f;
    std::array<InputHandle, dim>    gradient;
    ResidualHandle                  r_value;
    std::array<ResidualHandle, dim> r_gradient;
    std::array<JacobianHandle, dim> j_gradient;
  };


  /**
   * Nitsche's weak Dirichlet condition u = g on the selected boundary
   * (symmetric variant): residual
   *   -(dv/dn, u - g) - (v, du/dn) + (C/h_n) (v, u - g),
   * with h_n the element size normal to the face, 2 / sqrt(n.G n). Coercive
   * for C above the inverse-estimate constant of the space.
   */
  template <int dim>
  class NitscheDirichletTerm : public Term<dim>
  {
  public:
    NitscheDirichletTerm(const unsigned int            u,
                         const BoundarySelection<dim> &selection,
                         const dealii::Function<dim>  &g,
                         const double                  penalty)
      : u(u)
      , selection(selection)
      , g(g)
      , penalty(penalty)
    {}
    std::string
    name() const override
    {
      return "nitsche";
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
    declare(TermDeclaration<dim> &d) override;
    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override;

  private:
    const unsigned int              u;
    const BoundarySelection<dim>    selection;
    const dealii::Function<dim>    &g;
    const double                    penalty;
    InputHandle                     value;
    std::array<InputHandle, dim>    gradient;
    ResidualHandle                  r_value;
    std::array<ResidualHandle, dim> r_gradient;
    JacobianHandle                  j_value;
    std::array<JacobianHandle, dim> j_value_gradient, j_gradient_value;
  };


  /// Natural condition of the Poisson problem: residual -(v, q.n) where
  /// @p where holds, with q a prescribed flux vector (q = grad u for a known
  /// solution).
  template <int dim>
  class NeumannTerm : public Term<dim>
  {
  public:
    NeumannTerm(
      const unsigned int                                                u,
      std::function<bool(unsigned int, const dealii::Point<dim> &)>     where,
      std::function<dealii::Tensor<1, dim>(const dealii::Point<dim> &)> flux)
      : u(u)
      , where(where)
      , flux(flux)
    {}
    std::string
    name() const override
    {
      return "neumann";
    }
    typename Term<dim>::Domain
    domain() const override
    {
      return Term<dim>::Domain::boundary;
    }
    bool
    acts_on_face(const unsigned int) const override
    {
      return true;
    }
    void
    declare(TermDeclaration<dim> &d) override
    {
      d.needs_points();
      r_value = d.residual(u, Derivative<dim>::value);
    }
    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override
    {
      for (unsigned int q = 0; q < in.size(); ++q)
        if (where(in.face(), in.point(q)))
          out[r_value][q] -= flux(in.point(q)) * in.normal(q);
    }

  private:
    const unsigned int                                                u;
    std::function<bool(unsigned int, const dealii::Point<dim> &)>     where;
    std::function<dealii::Tensor<1, dim>(const dealii::Point<dim> &)> flux;
    ResidualHandle                                                    r_value;
  };
} // namespace vesicle_iga
