#pragma once

#include <deal.II/base/function.h>

#include <vesicle_iga/fields/boundary_selection.h>
#include <vesicle_iga/kernel/term.h>

#include <array>

namespace vesicle_iga
{
  /**
   * Primal H^2 form of the biharmonic equation Delta^2 u = f on a C^1 (or
   * smoother) spline space: residual (Delta v, Delta u) - (v, f). No mixed
   * variable: the second derivatives come straight from the spline space.
   */
  template <int dim>
  class BiharmonicTerm : public Term<dim>
  {
  public:
    BiharmonicTerm(const unsigned int u, const dealii::Function<dim> &f)
      : u(u)
      , f(f)
    {}
    std::string
    name() const override
    {
      return "biharmonic";
    }
    void
    declare(TermDeclaration<dim> &d) override
    {
      using D = Derivative<dim>;
      d.needs_points();
      laplacian   = d.value(u, D::laplacian);
      r_value     = d.residual(u, D::value);
      r_laplacian = d.residual(u, D::laplacian);
      j_laplacian = d.jacobian(u, D::laplacian, u, D::laplacian);
    }
    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override
    {
      for (unsigned int q = 0; q < in.size(); ++q)
        {
          out[r_value][q] -= f.value(in.point(q));
          out[r_laplacian][q] += in[laplacian][q];
          if (out.matrix())
            out[j_laplacian][q] += 1.;
        }
    }

  private:
    const unsigned int           u;
    const dealii::Function<dim> &f;
    InputHandle                  laplacian;
    ResidualHandle               r_value, r_laplacian;
    JacobianHandle               j_laplacian;
  };


  /**
   * Simply supported edge: u = g strongly, Delta u = m naturally.
   * Integrating (Delta^2 u, v) by parts twice with v = 0 on the edge leaves
   * the boundary term (Delta u, dv/dn), so the residual gains -(m, dv/dn).
   */
  template <int dim>
  class BoundaryLaplacianTerm : public Term<dim>
  {
  public:
    BoundaryLaplacianTerm(const unsigned int            u,
                          const BoundarySelection<dim> &selection,
                          const dealii::Function<dim>  &m)
      : u(u)
      , selection(selection)
      , m(m)
    {}
    std::string
    name() const override
    {
      return "boundary laplacian";
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
      for (unsigned int k = 0; k < dim; ++k)
        r_gradient[k] = d.residual(u, Derivative<dim>::gradient(k));
    }
    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override
    {
      for (unsigned int q = 0; q < in.size(); ++q)
        {
          if (!selection.contains(in.face(), in.point(q)))
            continue;
          const double mq = m.value(in.point(q));
          for (unsigned int k = 0; k < dim; ++k)
            out[r_gradient[k]][q] -= mq * in.normal(q)[k];
        }
    }

  private:
    const unsigned int              u;
    const BoundarySelection<dim>    selection;
    const dealii::Function<dim>    &m;
    std::array<ResidualHandle, dim> r_gradient;
  };
} // namespace vesicle_iga
