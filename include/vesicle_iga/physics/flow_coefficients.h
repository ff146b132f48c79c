#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/tensor.h>

#include <vesicle_iga/kernel/term.h>

#include <memory>
#include <vector>

namespace vesicle_iga
{
  /**
   * The viscosity mu* of the flow relative to the outer fluid (spec (H4),
   * (H12a)) at all quadrature points of an element, with its spatial
   * gradient (the term 2 D(u) grad mu* of div(2 mu* D(u)), spec 4.8). A
   * model that depends on fields (the phase-dependent mu*(phi) of Part H)
   * declares what it reads. Evaluated once per element, never per point
   * through a virtual call.
   */
  template <int dim>
  class ViscosityModel
  {
  public:
    virtual ~ViscosityModel() = default;
    /// Inputs the model reads (none for a constant or a formula).
    virtual void
    declare(TermDeclaration<dim> & /*declaration*/)
    {}
    /// Whether it needs the quadrature points (a formula in x).
    virtual bool
    needs_points() const
    {
      return false;
    }
    /// Time of a formula (set before an assembly, never during one).
    virtual void
    set_time(const double /*t*/)
    {}
    virtual void
    evaluate(const QuadratureInputs<dim>         &in,
             std::vector<double>                 &mu,
             std::vector<dealii::Tensor<1, dim>> &grad_mu) const = 0;
  };

  /// mu* constant (1 for equal viscosities): nothing is evaluated per point.
  template <int dim>
  class ConstantViscosity : public ViscosityModel<dim>
  {
  public:
    explicit ConstantViscosity(const double value = 1.)
      : value(value)
    {}
    void
    evaluate(const QuadratureInputs<dim>         &in,
             std::vector<double>                 &mu,
             std::vector<dealii::Tensor<1, dim>> &grad_mu) const override
    {
      mu.assign(in.size(), value);
      grad_mu.assign(in.size(), dealii::Tensor<1, dim>());
    }

  private:
    const double value;
  };

  /// mu*(x, t) given by the user as a formula; its gradient by fourth-order
  /// differences of the formula (the formula's own derivative, not a
  /// discrete one).
  template <int dim>
  class FormulaViscosity : public ViscosityModel<dim>
  {
  public:
    explicit FormulaViscosity(std::shared_ptr<dealii::Function<dim>> mu)
      : mu(mu)
    {}
    bool
    needs_points() const override
    {
      return true;
    }
    void
    set_time(const double t) override
    {
      mu->set_time(t);
    }
    void
    evaluate(const QuadratureInputs<dim>         &in,
             std::vector<double>                 &values,
             std::vector<dealii::Tensor<1, dim>> &gradients) const override;

  private:
    std::shared_ptr<dealii::Function<dim>> mu;
  };


  /**
   * The body force per unit mass of the flow at all quadrature points of an
   * element (spec (H4) right-hand side without the vesicle forces).
   */
  template <int dim>
  class BodyForce
  {
  public:
    /// @p force: dim components (null: no body force).
    explicit BodyForce(std::shared_ptr<dealii::Function<dim>> force = {})
      : force(force)
    {}
    bool
    active() const
    {
      return static_cast<bool>(force);
    }
    /// Time of the formula (set before an assembly, never during one).
    void
    set_time(const double t) const
    {
      if (force)
        force->set_time(t);
    }
    /// f(x_q, t) for every point (nothing if inactive).
    void
    evaluate(const QuadratureInputs<dim>         &in,
             std::vector<dealii::Tensor<1, dim>> &f) const;

  private:
    std::shared_ptr<dealii::Function<dim>> force;
  };


  /// The material and forcing of the flow: Reynolds number, viscosity
  /// model, body force and the RBVMS constant C_I of (H19).
  template <int dim>
  struct FlowCoefficients
  {
    double                               reynolds_number = 1;
    std::shared_ptr<ViscosityModel<dim>> viscosity
      = std::make_shared<ConstantViscosity<dim>>();
    BodyForce<dim> body_force;
    /// Whether the terms need the quadrature points (formulas in x).
    bool
    needs_points() const
    {
      return viscosity->needs_points() || body_force.active();
    }
    void
    set_time(const double t) const
    {
      viscosity->set_time(t);
      body_force.set_time(t);
    }
    /// C_I of tau_M (H19); spec: 6 p^4 (read of the source's "6P4").
    double inverse_estimate_constant = 96;
    /// The time scale of the transient term 4 / dt^2 of tau_M (H19): 0, the
    /// step being taken (the source's choice); > 0, this fixed value, so
    /// that the discrete problem does not change with dt (adaptive steps:
    /// a step and its retry with a smaller dt then solve the same
    /// equations, and the local error estimate sees the solution's change,
    /// not a change of the stabilisation).
    double stabilisation_time_scale = 0;
    /// The dt that tau_M uses for a step of size @p dt.
    double
    tau_time_step(const double dt) const
    {
      return stabilisation_time_scale > 0 ? stabilisation_time_scale : dt;
    }
  };
} // namespace vesicle_iga
