// RBVMS Navier-Stokes, spec Part H: weak form (H14) without vesicle terms,
// fine scales (H18a)-(H18b), stabilisation parameters (H19). The Jacobian
// is the exact derivative of the residual coefficients (including
// d tau / d u), see the header.

#include <vesicle_iga/terms/navier_stokes_rbvms.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  double
  NavierStokesRBVMS<dim>::tau_momentum(const Tensor<2, dim> &G,
                                       const Tensor<1, dim> &u,
                                       const double          dt,
                                       const double          nu,
                                       const double          C_I)
  {
    const double transient = dt > 0 ? 4. / (dt * dt) : 0.;
    return 1.
           / std::sqrt(transient + u * (G * u)
                       + C_I * nu * nu * scalar_product(G, G));
  }


  /// Fields, residuals and stabilisation at one quadrature point.
  template <int dim>
  struct NavierStokesRBVMS<dim>::FlowPoint
  {
    Tensor<1, dim> u, u_rate, grad_p, laplacian_u, grad_div_u;
    Tensor<2, dim> grad_u; // grad_u[a][k] = d_k u_a
    double         p = 0;
    double         mu, Re;
    Tensor<1, dim> grad_mu, force;
    Tensor<2, dim> G;
    // r_M, r_C, tau_M, tau_C, s = tau_M r_M.
    Tensor<1, dim> r_m, s;
    double         r_c, tau_m, tau_c;
  };


  template <int dim>
  NavierStokesRBVMS<dim>::NavierStokesRBVMS(
    const unsigned int           velocity,
    const unsigned int           pressure,
    const FlowCoefficients<dim> &coefficients)
    : velocity(velocity)
    , pressure(pressure)
    , coefficients(coefficients)
  {
    for (unsigned int c = 0; c < dim; ++c)
      {
        atoms.push_back({Atom::u_value, c, 0, 0});
        atoms.push_back({Atom::u_rate, c, 0, 0});
        for (unsigned int l = 0; l < dim; ++l)
          atoms.push_back({Atom::u_gradient, c, l, 0});
        for (unsigned int l = 0; l < dim; ++l)
          for (unsigned int m = l; m < dim; ++m)
            atoms.push_back({Atom::u_hessian, c, l, m});
      }
    atoms.push_back({Atom::p_value, 0, 0, 0});
    for (unsigned int l = 0; l < dim; ++l)
      atoms.push_back({Atom::p_gradient, 0, l, 0});
  }


  template <int dim>
  void
  NavierStokesRBVMS<dim>::declare(TermDeclaration<dim> &d)
  {
    using D = Derivative<dim>;
    for (unsigned int a = 0; a < dim; ++a)
      {
        const unsigned int ua = velocity + a;
        u[a]                  = d.value(ua, D::value);
        u_rate[a]             = d.rate(ua, D::value);
        for (unsigned int k = 0; k < dim; ++k)
          {
            grad_u[a][k] = d.value(ua, D::gradient(k));
            for (unsigned int l = 0; l < dim; ++l)
              hessian_u[a][k * dim + l] = d.value(ua, D::hessian(k, l));
          }
      }
    p = d.value(pressure, D::value);
    for (unsigned int k = 0; k < dim; ++k)
      grad_p[k] = d.value(pressure, D::gradient(k));
    coefficients.viscosity->declare(d);
    if (coefficients.needs_points())
      d.needs_points();

    for (unsigned int a = 0; a < dim; ++a)
      {
        r_value[a] = d.residual(velocity + a, D::value);
        for (unsigned int k = 0; k < dim; ++k)
          r_gradient[a][k] = d.residual(velocity + a, D::gradient(k));
      }
    r_continuity = d.residual(pressure, D::value);
    for (unsigned int k = 0; k < dim; ++k)
      r_fine_scale[k] = d.residual(pressure, D::gradient(k));

    // The Jacobian of every residual coefficient with respect to every
    // atom (the continuity residual div u only depends on d_c u_c).
    const auto trial = [&](const Atom &at) {
      switch (at.kind)
        {
          case Atom::u_value:
          case Atom::u_rate:
            return std::make_pair(velocity + at.c, D::value);
          case Atom::u_gradient:
            return std::make_pair(velocity + at.c, D::gradient(at.l));
          case Atom::u_hessian:
            return std::make_pair(velocity + at.c, D::hessian(at.l, at.m));
          case Atom::p_value:
            return std::make_pair(pressure, D::value);
          default:
            return std::make_pair(pressure, D::gradient(at.l));
        }
    };
    const auto jacobian = [&](const unsigned int test_component,
                              const unsigned int test_derivative,
                              const Atom        &at) {
      const auto [c, b] = trial(at);
      return d.jacobian(test_component,
                        test_derivative,
                        c,
                        b,
                        at.kind == Atom::u_rate ? FieldSource::rate :
                                                  FieldSource::value);
    };
    j_velocity.assign(dim * (1 + dim), {});
    j_fine_scale.assign(dim, {});
    j_continuity.clear();
    for (const auto &at : atoms)
      {
        for (unsigned int a = 0; a < dim; ++a)
          {
            j_velocity[a * (1 + dim)].push_back(
              jacobian(velocity + a, D::value, at));
            for (unsigned int k = 0; k < dim; ++k)
              j_velocity[a * (1 + dim) + 1 + k].push_back(
                jacobian(velocity + a, D::gradient(k), at));
          }
        for (unsigned int k = 0; k < dim; ++k)
          j_fine_scale[k].push_back(jacobian(pressure, D::gradient(k), at));
        j_continuity.push_back(at.kind == Atom::u_gradient && at.l == at.c ?
                                 jacobian(pressure, D::value, at) :
                                 JacobianHandle());
      }
  }


  template <int dim>
  typename NavierStokesRBVMS<dim>::FlowPoint
  NavierStokesRBVMS<dim>::point(const QuadratureInputs<dim> &in,
                                const unsigned int           q,
                                const double                 mu,
                                const Tensor<1, dim>        &grad_mu,
                                const Tensor<1, dim>        &force) const
  {
    FlowPoint f;
    f.mu      = mu;
    f.grad_mu = grad_mu;
    f.force   = force;
    f.Re      = coefficients.reynolds_number;
    f.G       = in.metric(q);
    for (unsigned int a = 0; a < dim; ++a)
      {
        f.u[a]      = in[u[a]][q];
        f.u_rate[a] = in[u_rate[a]][q];
        for (unsigned int k = 0; k < dim; ++k)
          {
            f.grad_u[a][k] = in[grad_u[a][k]][q];
            // grad(div u)_k = sum_a d_k d_a u_a
            f.grad_div_u[k] += in[hessian_u[a][a * dim + k]][q];
          }
        for (unsigned int l = 0; l < dim; ++l)
          f.laplacian_u[a] += in[hessian_u[a][l * dim + l]][q];
      }
    f.p = in[p][q];
    for (unsigned int k = 0; k < dim; ++k)
      f.grad_p[k] = in[grad_p[k]][q];

    // div(2 mu D(u)) = mu (Delta u + grad div u) + 2 D(u) grad mu (spec 4.8).
    const Tensor<2, dim> two_D = f.grad_u + transpose(f.grad_u);
    const Tensor<1, dim> viscous
      = mu * (f.laplacian_u + f.grad_div_u) + two_D * grad_mu;
    f.r_m   = f.u_rate + f.grad_u * f.u + f.grad_p - viscous / f.Re - force;
    f.r_c   = trace(f.grad_u);
    f.tau_m = tau_momentum(f.G,
                           f.u,
                           coefficients.tau_time_step(in.time_step),
                           mu / f.Re,
                           coefficients.inverse_estimate_constant);
    f.tau_c = 1. / (trace(f.G) * f.tau_m);
    f.s     = f.tau_m * f.r_m;
    return f;
  }


  template <int dim>
  void
  NavierStokesRBVMS<dim>::evaluate(const QuadratureInputs<dim> &in,
                                   TermCoefficients            &out) const
  {
    thread_local std::vector<double>         mu;
    thread_local std::vector<Tensor<1, dim>> grad_mu, force;
    coefficients.viscosity->evaluate(in, mu, grad_mu);
    coefficients.body_force.evaluate(in, force);
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        const FlowPoint      f     = point(in, q, mu[q], grad_mu[q], force[q]);
        const Tensor<2, dim> two_D = f.grad_u + transpose(f.grad_u);
        // Test-side coefficients of (H14): velocity test w = N e_a gives
        // N V_a + grad N . S_a, pressure test q = N gives N r_c + grad N . s.
        const Tensor<1, dim> V
          = f.u_rate + f.grad_u * f.u - f.force - f.grad_u * f.s;
        Tensor<2, dim> S = (f.mu / f.Re) * two_D + outer_product(f.s, f.u)
                           - outer_product(f.s, f.s);
        for (unsigned int a = 0; a < dim; ++a)
          S[a][a] += -f.p + f.tau_c * f.r_c;
        for (unsigned int a = 0; a < dim; ++a)
          {
            out[r_value[a]][q] += V[a];
            for (unsigned int k = 0; k < dim; ++k)
              out[r_gradient[a][k]][q] += S[a][k];
          }
        out[r_continuity][q] += f.r_c;
        for (unsigned int k = 0; k < dim; ++k)
          out[r_fine_scale[k]][q] += f.s[k];
        if (out.matrix())
          write_jacobian(f, q, out);
      }
  }


  template <int dim>
  void
  NavierStokesRBVMS<dim>::write_jacobian(const FlowPoint   &f,
                                         const unsigned int q,
                                         TermCoefficients  &out) const
  {
    // d tau_M / d u = -tau_M^3 G u (H19); tau_C = 1 / (tr G tau_M).
    const Tensor<1, dim> dtau_m_du = -f.tau_m * f.tau_m * f.tau_m * (f.G * f.u);
    for (unsigned int j = 0; j < atoms.size(); ++j)
      {
        const Atom    &at = atoms[j];
        Tensor<1, dim> d_u, d_rate, d_grad_p, d_viscous;
        Tensor<2, dim> d_grad_u;
        double         d_p = 0;
        switch (at.kind)
          {
            case Atom::u_value:
              d_u[at.c] = 1;
              break;
            case Atom::u_rate:
              d_rate[at.c] = 1;
              break;
            case Atom::u_gradient:
              d_grad_u[at.c][at.l] = 1;
              d_viscous = (d_grad_u + transpose(d_grad_u)) * f.grad_mu;
              break;
            case Atom::u_hessian:
              // d_l d_m u_c in mu (Delta u + grad div u): the Laplacian of
              // u_c (l = m) and the components k of grad div u with
              // {k, c} = {l, m}.
              if (at.l == at.m)
                d_viscous[at.c] += f.mu;
              if (at.c == at.l)
                d_viscous[at.m] += f.mu;
              if (at.c == at.m && at.l != at.m)
                d_viscous[at.l] += f.mu;
              break;
            case Atom::p_value:
              d_p = 1;
              break;
            case Atom::p_gradient:
              d_grad_p[at.l] = 1;
              break;
          }
        const Tensor<1, dim> d_r_m = d_rate + d_grad_u * f.u + f.grad_u * d_u
                                     + d_grad_p - d_viscous / f.Re;
        const double         d_r_c   = trace(d_grad_u);
        const double         d_tau_m = dtau_m_du * d_u;
        const double         d_tau_c = -f.tau_c / f.tau_m * d_tau_m;
        const Tensor<1, dim> d_s     = d_tau_m * f.r_m + f.tau_m * d_r_m;
        const Tensor<1, dim> d_V     = d_rate + d_grad_u * f.u + f.grad_u * d_u
                                   - d_grad_u * f.s - f.grad_u * d_s;
        Tensor<2, dim> d_S = (f.mu / f.Re) * (d_grad_u + transpose(d_grad_u))
                             + outer_product(d_s, f.u) + outer_product(f.s, d_u)
                             - outer_product(d_s, f.s)
                             - outer_product(f.s, d_s);
        for (unsigned int a = 0; a < dim; ++a)
          d_S[a][a] += -d_p + d_tau_c * f.r_c + f.tau_c * d_r_c;

        for (unsigned int a = 0; a < dim; ++a)
          {
            out[j_velocity[a * (1 + dim)][j]][q] += d_V[a];
            for (unsigned int k = 0; k < dim; ++k)
              out[j_velocity[a * (1 + dim) + 1 + k][j]][q] += d_S[a][k];
          }
        for (unsigned int k = 0; k < dim; ++k)
          out[j_fine_scale[k][j]][q] += d_s[k];
        if (j_continuity[j].index != ~0u)
          out[j_continuity[j]][q] += d_r_c;
      }
  }

  template class NavierStokesRBVMS<2>;
  template class NavierStokesRBVMS<3>;
} // namespace vesicle_iga
