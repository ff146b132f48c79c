#pragma once

#include <deal.II/base/function.h>

#include <vesicle_iga/fields/boundary_selection.h>
#include <vesicle_iga/kernel/term.h>
#include <vesicle_iga/physics/flow_coefficients.h>

#include <array>

namespace vesicle_iga
{
  /**
   * Velocity u = u_b imposed weakly (Bazilevs and Hughes 2007) on the
   * selected boundary pieces, spec (H20)-(H21): the consistency term
   * -(w, sigma(u,p) m), the adjoint-consistency term
   * -((2 mu* / Re) D(w) m + q m, u - u_b), the penalty (tau_B w, u - u_b)
   * with tau_B = C_B (mu* / Re) / h_n, h_n = (m.G m)^(-1/2), and
   * (switchable) the inflow term -(w, (u.m)_- (u - u_b)) on the part where
   * u.m < 0. A boundary term of the kernel with its exact Jacobian.
   */
  template <int dim>
  class WeakVelocityDirichlet : public Term<dim>
  {
  public:
    /// @p boundary_velocity: dim (+ any) components, its time set by the
    /// caller before each assembly.
    WeakVelocityDirichlet(const unsigned int            velocity,
                          const unsigned int            pressure,
                          const FlowCoefficients<dim>  &coefficients,
                          const BoundarySelection<dim> &selection,
                          const dealii::Function<dim>  &boundary_velocity,
                          const double                  penalty_constant,
                          const bool                    inflow_term);
    std::string
    name() const override
    {
      return "weak velocity condition";
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
    const unsigned int           velocity, pressure;
    const FlowCoefficients<dim> &coefficients;
    const BoundarySelection<dim> selection;
    const dealii::Function<dim> &boundary_velocity;
    const double                 penalty_constant;
    const bool                   inflow_term;

    std::array<InputHandle, dim>                     u;
    std::array<std::array<InputHandle, dim>, dim>    grad_u;
    InputHandle                                      p;
    std::array<ResidualHandle, dim>                  r_value;
    std::array<std::array<ResidualHandle, dim>, dim> r_gradient;
    ResidualHandle                                   r_pressure;
    // [a][c]: value test a, velocity value c; [a][c][l]: value test a,
    // velocity gradient (c, l); [a][k][c]: gradient test (a, k), velocity
    // value c; [a]: value test a, pressure value; [c]: pressure test,
    // velocity value c.
    std::array<std::array<JacobianHandle, dim>, dim>                  j_vv;
    std::array<std::array<std::array<JacobianHandle, dim>, dim>, dim> j_vg;
    std::array<std::array<std::array<JacobianHandle, dim>, dim>, dim> j_gv;
    std::array<JacobianHandle, dim> j_vp, j_pv;
  };
} // namespace vesicle_iga
