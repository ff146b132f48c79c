#pragma once

#include <deal.II/base/function.h>

#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/assembly/assembly_term.h>
#include <vesicle_iga/assembly/boundary_selection.h>
#include <vesicle_iga/parallel/spline_dof_handler.h>

namespace vesicle_iga
{
  /**
   * The time levels and Newton factors of one generalized-alpha Newton
   * iteration of the flow (spec (N2)-(N4)): the state vectors (ghosted,
   * components u_1..u_dim, p of one SplineDofHandler) and the derivatives
   * of the evaluated fields with respect to the unknown rates dU/dt_{n+1}.
   */
  struct FlowState
  {
    /// Velocity at t_{n+alpha_f}.
    const TrilinosWrappers::MPI::Vector *velocity = nullptr;
    /// Velocity rate at t_{n+alpha_m}.
    const TrilinosWrappers::MPI::Vector *velocity_rate = nullptr;
    /// Pressure: at t_{n+1} (spec 4.9) or at t_{n+alpha_f}.
    const TrilinosWrappers::MPI::Vector *pressure = nullptr;
    /// d(rate)/d(rate_{n+1}) = alpha_m, d(u_{n+alpha_f})/d(rate_{n+1}) =
    /// alpha_f gamma dt and d(p)/d(rate_{n+1}) (gamma dt at t_{n+1}).
    double rate_factor = 1, velocity_factor = 1, pressure_factor = 1;
    /// Time step in tau_M (H19); 0 for a steady problem.
    double dt = 0;
    /// Whether the tangent is wanted (false: residual only).
    bool with_matrix = true;
  };

  /**
   * Material and forcing of the flow: Reynolds number, viscosity field
   * mu*(x) (scaled by 1/Re in the viscous stress, spec (H4)) and body force
   * per unit mass f(x, t) (dim components).
   */
  template <int dim>
  struct FlowCoefficients
  {
    double               reynolds_number = 1;
    const Function<dim> *viscosity       = nullptr; // scalar, default 1
    const Function<dim> *body_force      = nullptr; // dim components or null
    /// C_I of tau_M (H19); spec: 6 p^4 (read of the source's "6P4").
    double inverse_estimate_constant = 96;

    double
    viscosity_at(const Point<dim> &x) const
    {
      return viscosity ? viscosity->value(x) : 1.;
    }
    Tensor<1, dim>
    viscosity_gradient_at(const Point<dim> &x) const;
  };

  /**
   * What every term of the flow residual shares: the unknowns' numbering,
   * the coefficients and the state of the step (levels and factors),
   * which the solver sets before each assembly.
   */
  template <int dim>
  class FlowTerm : public AssemblyTerm<dim>
  {
  public:
    FlowTerm(const SplineDofHandler<dim> &dofs,
             const FlowCoefficients<dim> &coefficients)
      : dofs(dofs)
      , coefficients(coefficients)
    {}

    void
    set_state(const FlowState &state)
    {
      this->state = state;
    }

  protected:
    const SplineDofHandler<dim> &dofs;
    const FlowCoefficients<dim> &coefficients;
    FlowState                    state;
  };

  /**
   * The incompressible Navier-Stokes equations (H4)-(H5) without vesicle
   * forces, stabilised by residual-based variational multiscale (RBVMS),
   * in the weak form (H14) with the fine scales (H18a)
   *   u' = -tau_M r_M,   p' = -tau_C r_C,
   *   r_M = du/dt + (u.grad)u + grad p - (1/Re) div(2 mu* D(u)) - f,
   *   r_C = div u,
   * tau_M, tau_C from the element metric tensor G (N1) as in (H19), and all
   * terms of (H14): Galerkin, SUPG/PSPG ((u.grad)w + grad q, tau_M r_M),
   * grad-div (div w, tau_C r_C), the cross term -(w, (tau_M r_M . grad) u)
   * and the Reynolds-stress term -(grad w, tau_M r_M (x) tau_M r_M).
   * The tangent is the exact derivative of this residual, including the
   * dependence of tau_M and tau_C on u (checked against finite differences
   * in tests/flow/jacobian_check). Vesicle forces of Part H are further
   * terms on the same system: they add to r_M through forcing_residual()
   * and to the test-function side in their own AssemblyTerm.
   *
   * As an AssemblyTerm it adds the tangent K to the matrix and -R to the
   * right-hand side, so Newton solves K d(rate) = -R.
   */
  template <int dim>
  class NavierStokesRBVMS : public FlowTerm<dim>
  {
  public:
    using FlowTerm<dim>::FlowTerm;

    unsigned int
    derivative_order() const override
    {
      return 2;
    }
    void
    assemble_cell(const SplineCellValues<dim> &values,
                  FullMatrix<double>          &matrix,
                  Vector<double>              &rhs) const override;


  private:
    using FlowTerm<dim>::dofs;
    using FlowTerm<dim>::coefficients;
    using FlowTerm<dim>::state;
  };

  /**
   * The lumped operators of the Cahouet-Chabard Schur-complement
   * approximation of the block preconditioner (FlowBlockPreconditioner,
   * doc/flow.md), at the state of the step: on the velocity rows the
   * lumped transient mass  k_m int N_i  (k_m = alpha_m, the factor of the
   * velocity rate in the tangent), on the pressure rows the lumped
   * viscous pressure mass  k_p int N_i / (mu* / Re + tau_C), the inverse
   * viscosity of the Stokes Schur complement augmented by the grad-div
   * coefficient tau_C of (H19). Written to the right-hand side only.
   */
  template <int dim>
  class RBVMSLumpedSchurOperators : public FlowTerm<dim>
  {
  public:
    using FlowTerm<dim>::FlowTerm;
    unsigned int
    derivative_order() const override
    {
      return 1;
    }
    void
    assemble_cell(const SplineCellValues<dim> &values,
                  FullMatrix<double>          &matrix,
                  Vector<double>              &rhs) const override;


  private:
    using FlowTerm<dim>::dofs;
    using FlowTerm<dim>::coefficients;
    using FlowTerm<dim>::state;
  };

  /**
   * Velocity u = u_b imposed weakly (Bazilevs and Hughes 2007) on the
   * selected boundary pieces, spec (H20)-(H21): the consistency term
   * -(w, sigma(u,p) m), the adjoint-consistency term
   * -((2 mu* / Re) D(w) m + q m, u - u_b), the penalty (tau_B w, u - u_b) with
   * tau_B = C_B (mu* / Re) / h_n, h_n = (m.G m)^(-1/2), and (switchable) the
   * inflow term -(w, (u.m)_- (u - u_b)) on the part where u.m < 0.
   */
  template <int dim>
  class WeakVelocityDirichlet : public FlowTerm<dim>
  {
  public:
    WeakVelocityDirichlet(const SplineDofHandler<dim>  &dofs,
                          const FlowCoefficients<dim>  &coefficients,
                          const BoundarySelection<dim> &selection,
                          const Function<dim>          &boundary_velocity,
                          const double                  penalty_constant,
                          const bool                    inflow_term);

    unsigned int
    derivative_order() const override
    {
      return 1;
    }
    bool
    needs_shape_tables() const override
    {
      return true;
    }
    bool
    acts_on_face(const unsigned int face) const override
    {
      return selection.touches_face(face);
    }
    void
    assemble_face(const unsigned int           face,
                  const SplineCellValues<dim> &values,
                  FullMatrix<double>          &matrix,
                  Vector<double>              &rhs) const override;

  private:
    using FlowTerm<dim>::dofs;
    using FlowTerm<dim>::coefficients;
    using FlowTerm<dim>::state;
    const BoundarySelection<dim> &selection;
    const Function<dim>          &boundary_velocity;
    const double                  penalty_constant;
    const bool                    inflow_term;
  };
} // namespace vesicle_iga
