#pragma once

#include <vesicle_iga/kernel/term.h>
#include <vesicle_iga/physics/flow_coefficients.h>

#include <array>
#include <vector>

namespace vesicle_iga
{
  /**
   * The incompressible Navier-Stokes equations (H4)-(H5) without vesicle
   * forces, stabilised by residual-based variational multiscale (RBVMS), in
   * the weak form (H14) with the fine scales (H18a)
   *   u' = -tau_M r_M,   p' = -tau_C r_C,
   *   r_M = du/dt + (u.grad)u + grad p - (1/Re) div(2 mu* D(u)) - f,
   *   r_C = div u,
   * tau_M, tau_C from the element metric tensor G (N1) as in (H19), and all
   * terms of (H14): Galerkin, SUPG/PSPG ((u.grad)w + grad q, tau_M r_M),
   * grad-div (div w, tau_C r_C), the cross term -(w, (tau_M r_M . grad) u)
   * and the Reynolds-stress term -(grad w, tau_M r_M (x) tau_M r_M).
   *
   * Residual coefficients: on the velocity test w = N e_a the value
   * coefficient V_a and the gradient coefficients S_ak,
   *   V = du/dt + grad_u u - f - grad_u s,
   *   S = (mu* / Re) 2 D(u) + s (x) u - s (x) s + (-p + tau_C r_C) I,
   * with s = tau_M r_M; on the pressure test q = N the value r_C and the
   * gradient s. The Jacobian is the exact derivative of these with respect
   * to every input (velocity values, gradients, second derivatives and
   * rates, pressure value and gradient), including the dependence of tau_M
   * and tau_C on u (checked by tests/kernel/jacobian_check_terms).
   */
  template <int dim>
  class NavierStokesRBVMS : public Term<dim>
  {
  public:
    /// @p velocity: flat component of u_1 (the dim components follow);
    /// @p pressure: flat component of p.
    NavierStokesRBVMS(const unsigned int           velocity,
                      const unsigned int           pressure,
                      const FlowCoefficients<dim> &coefficients);

    std::string
    name() const override
    {
      return "rbvms";
    }
    void
    declare(TermDeclaration<dim> &d) override;
    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override;

    /// tau_M of (H19).
    static double
    tau_momentum(const dealii::Tensor<2, dim> &G,
                 const dealii::Tensor<1, dim> &u,
                 const double                  dt,
                 const double                  kinematic_viscosity,
                 const double                  C_I);

  private:
    /// What a unit variation of one input (an "atom") is: a velocity value,
    /// gradient, second derivative or rate, a pressure value or gradient.
    struct Atom
    {
      enum Kind
      {
        u_value,
        u_gradient,
        u_hessian,
        u_rate,
        p_value,
        p_gradient
      } kind;
      unsigned int c, l, m;
    };
    /// The flow at one point.
    struct FlowPoint;
    FlowPoint
    point(const QuadratureInputs<dim>  &in,
          const unsigned int            q,
          const double                  mu,
          const dealii::Tensor<1, dim> &grad_mu,
          const dealii::Tensor<1, dim> &force) const;
    void
    write_jacobian(const FlowPoint   &f,
                   const unsigned int q,
                   TermCoefficients  &out) const;

    const unsigned int           velocity, pressure;
    const FlowCoefficients<dim> &coefficients;
    std::vector<Atom>            atoms;

    std::array<InputHandle, dim>                  u, u_rate;
    std::array<std::array<InputHandle, dim>, dim> grad_u;
    std::array<std::array<InputHandle, dim * dim>, dim>
                                    hessian_u; // [c][l dim + m]
    InputHandle                     p;
    std::array<InputHandle, dim>    grad_p;
    std::array<ResidualHandle, dim> r_value;
    std::array<std::array<ResidualHandle, dim>, dim> r_gradient;
    ResidualHandle                                   r_continuity;
    std::array<ResidualHandle, dim>                  r_fine_scale;
    /// Jacobian handles: [test slot][atom].
    std::vector<std::vector<JacobianHandle>> j_velocity;   // (a, 1 + dim)
    std::vector<JacobianHandle>              j_continuity; // per atom or none
    std::vector<std::vector<JacobianHandle>> j_fine_scale; // (k)
  };
} // namespace vesicle_iga
