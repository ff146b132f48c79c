// RBVMS Navier-Stokes, spec Part H: weak form (H14) without vesicle terms,
// fine scales (H18a)-(H18b), stabilisation parameters (H19), weak Dirichlet
// conditions (H20)-(H21). The tangent is the exact derivative of the
// residual (including d tau / d u), see the header.

#include <deal.II/base/tensor.h>

#include <vesicle_iga/assembly/assembler.h>
#include <vesicle_iga/physics/navier_stokes_rbvms.h>

#include <cmath>

namespace vesicle_iga
{
  template <int dim>
  Tensor<1, dim>
  FlowCoefficients<dim>::viscosity_gradient_at(const Point<dim> &x) const
  {
    Tensor<1, dim> g;
    if (!viscosity)
      return g;
    // mu*(x) is given as a formula: central differences, exact to O(d^2)
    // for smooth fields (mu* is constant in all verification studies).
    const double d = 1e-6;
    for (unsigned int k = 0; k < dim; ++k)
      {
        Point<dim> xp = x, xm = x;
        xp[k] += d;
        xm[k] -= d;
        g[k] = (viscosity->value(xp) - viscosity->value(xm)) / (2 * d);
      }
    return g;
  }


  namespace
  {
    /// Fields of the flow at one quadrature point.
    template <int dim>
    struct FlowPoint
    {
      Tensor<1, dim> u, u_rate, grad_p;
      Tensor<2, dim> grad_u; // grad_u[a][k] = d_k u_a
      Tensor<1, dim> laplacian_u, grad_div_u;
      double         p = 0;
    };

    template <int dim>
    FlowPoint<dim>
    evaluate_point(const SplineCellValues<dim>            &v,
                   const unsigned int                      q,
                   const std::vector<std::vector<double>> &u,
                   const std::vector<std::vector<double>> &u_rate,
                   const std::vector<std::vector<double>> &p)
    {
      FlowPoint<dim> f;
      for (unsigned int a = 0; a < dim; ++a)
        {
          f.u[a]                 = v.value(u[a], q);
          f.u_rate[a]            = v.value(u_rate[a], q);
          const Tensor<1, dim> g = v.gradient(u[a], q);
          for (unsigned int k = 0; k < dim; ++k)
            f.grad_u[a][k] = g[k];
          const Tensor<2, dim> H = v.hessian(u[a], q);
          f.laplacian_u[a]       = trace(H);
          // grad(div u)_k = sum_a d_k d_a u_a
          for (unsigned int k = 0; k < dim; ++k)
            f.grad_div_u[k] += H[a][k];
        }
      f.p      = v.value(p[dim], q);
      f.grad_p = v.gradient(p[dim], q);
      return f;
    }

    /// tau_M of (H19).
    template <int dim>
    double
    tau_momentum(const Tensor<2, dim> &G,
                 const Tensor<1, dim> &u,
                 const double          dt,
                 const double          kinematic_viscosity,
                 const double          C_I)
    {
      const double transient = dt > 0 ? 4. / (dt * dt) : 0.;
      return 1.
             / std::sqrt(transient + u * (G * u)
                         + C_I * kinematic_viscosity * kinematic_viscosity
                             * scalar_product(G, G));
    }
  } // namespace


  template <int dim>
  void
  NavierStokesRBVMS<dim>::assemble_cell(const SplineCellValues<dim> &v,
                                        FullMatrix<double>          &A,
                                        Vector<double>              &b) const
  {
    const unsigned int               n = v.n_basis_per_element(), nc = dim + 1;
    std::vector<std::vector<double>> cu, cr, cp;
    get_element_coefficients(dofs, *state.velocity, v.element(), cu);
    get_element_coefficients(dofs, *state.velocity_rate, v.element(), cr);
    get_element_coefficients(dofs, *state.pressure, v.element(), cp);
    const double Re = coefficients.reynolds_number;
    const double km = state.rate_factor, ku = state.velocity_factor,
                 kp = state.pressure_factor;

    // Per trial column (component c, function j): the derivatives of the
    // test-side coefficients. Rows 0..dim-1: velocity test component a,
    // row dim: pressure test; feature 0: value, 1..dim: gradient.
    FullMatrix<double> D(nc * (dim + 1), state.with_matrix ? nc * n : 0);

    for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
      {
        const Point<dim>     &x       = v.quadrature_point(q);
        const double          JxW     = v.JxW(q);
        const FlowPoint<dim>  f       = evaluate_point(v, q, cu, cr, cp);
        const double          mu      = coefficients.viscosity_at(x);
        const Tensor<1, dim>  grad_mu = coefficients.viscosity_gradient_at(x);
        const Tensor<2, dim> &G       = v.metric_tensor(q);
        Tensor<1, dim>        force;
        if (coefficients.body_force)
          for (unsigned int a = 0; a < dim; ++a)
            force[a] = coefficients.body_force->value(x, a);

        // Strain rate times 2 and the viscous term div(2 mu D(u)) =
        // mu (Delta u + grad div u) + 2 D(u) grad mu (spec 4.8).
        const Tensor<2, dim> two_D = f.grad_u + transpose(f.grad_u);
        const Tensor<1, dim> viscous
          = mu * (f.laplacian_u + f.grad_div_u) + two_D * grad_mu;
        const Tensor<1, dim> r_m
          = f.u_rate + f.grad_u * f.u + f.grad_p - viscous / Re - force;
        const double r_c   = trace(f.grad_u);
        const double tau_m = tau_momentum(
          G, f.u, state.dt, mu / Re, coefficients.inverse_estimate_constant);
        const double         tau_c = 1. / (trace(G) * tau_m);
        const Tensor<1, dim> s     = tau_m * r_m; // -u'

        // Test-side coefficients of (H14): velocity test w = N e_a gives
        // N V_a + grad N . S_a, pressure test q = N gives N r_c + grad N . s.
        const Tensor<1, dim> V
          = f.u_rate + f.grad_u * f.u - force - f.grad_u * s;
        Tensor<2, dim> S
          = (mu / Re) * two_D + outer_product(s, f.u) - outer_product(s, s);
        for (unsigned int a = 0; a < dim; ++a)
          S[a][a] += -f.p + tau_c * r_c;

        for (unsigned int i = 0; i < n; ++i)
          {
            const double          N  = v.shape_value(i, q);
            const Tensor<1, dim> &dN = v.shape_grad(i, q);
            for (unsigned int a = 0; a < dim; ++a)
              b(a * n + i) -= (N * V[a] + dN * S[a]) * JxW;
            b(dim * n + i) -= (N * r_c + dN * s) * JxW;
          }
        if (!state.with_matrix)
          continue;

        // d tau_M / d u = -tau_M^3 G u (H19); tau_C = 1 / (tr G tau_M).
        const Tensor<1, dim> dtau_m_du = -tau_m * tau_m * tau_m * (G * f.u);
        for (unsigned int c = 0; c < nc; ++c)
          for (unsigned int j = 0; j < n; ++j)
            {
              const double          phi  = v.shape_value(j, q);
              const Tensor<1, dim> &dphi = v.shape_grad(j, q);
              const Tensor<2, dim> &Hphi = v.shape_hessian(j, q);
              Tensor<1, dim>        d_u, d_rate, d_grad_p;
              Tensor<2, dim>        d_grad_u;
              Tensor<1, dim>        d_viscous;
              if (c < dim)
                {
                  d_u[c]    = ku * phi;
                  d_rate[c] = km * phi;
                  for (unsigned int k = 0; k < dim; ++k)
                    d_grad_u[c][k] = ku * dphi[k];
                  const Tensor<2, dim> d_two_D = d_grad_u + transpose(d_grad_u);
                  // Delta of (phi e_c) and grad div (phi e_c).
                  Tensor<1, dim> lap_grad_div;
                  lap_grad_div[c] += ku * trace(Hphi);
                  for (unsigned int k = 0; k < dim; ++k)
                    lap_grad_div[k] += ku * Hphi[c][k];
                  d_viscous = mu * lap_grad_div + d_two_D * grad_mu;
                }
              else
                d_grad_p = kp * dphi;
              const double d_p = c == dim ? kp * phi : 0.;

              const Tensor<1, dim> d_r_m = d_rate + d_grad_u * f.u
                                           + f.grad_u * d_u + d_grad_p
                                           - d_viscous / Re;
              const double         d_r_c   = trace(d_grad_u);
              const double         d_tau_m = dtau_m_du * d_u;
              const double         d_tau_c = -tau_c / tau_m * d_tau_m;
              const Tensor<1, dim> d_s     = d_tau_m * r_m + tau_m * d_r_m;

              const Tensor<1, dim> d_V = d_rate + d_grad_u * f.u
                                         + f.grad_u * d_u - d_grad_u * s
                                         - f.grad_u * d_s;
              Tensor<2, dim> d_S
                = (mu / Re) * (d_grad_u + transpose(d_grad_u))
                  + outer_product(d_s, f.u) + outer_product(s, d_u)
                  - outer_product(d_s, s) - outer_product(s, d_s);
              for (unsigned int a = 0; a < dim; ++a)
                d_S[a][a] += -d_p + d_tau_c * r_c + tau_c * d_r_c;

              const unsigned int col = c * n + j;
              for (unsigned int a = 0; a < dim; ++a)
                {
                  D(a * (dim + 1), col) = d_V[a];
                  for (unsigned int k = 0; k < dim; ++k)
                    D(a * (dim + 1) + 1 + k, col) = d_S[a][k];
                }
              D(dim * (dim + 1), col) = d_r_c;
              for (unsigned int k = 0; k < dim; ++k)
                D(dim * (dim + 1) + 1 + k, col) = d_s[k];
            }
        // A(row(a, i), col) += JxW [N_i, grad N_i] . D(a-block, col).
        for (unsigned int i = 0; i < n; ++i)
          {
            std::array<double, dim + 1> T;
            T[0] = v.shape_value(i, q) * JxW;
            for (unsigned int k = 0; k < dim; ++k)
              T[1 + k] = v.shape_grad(i, q)[k] * JxW;
            for (unsigned int a = 0; a < nc; ++a)
              {
                double *row = &A(a * n + i, 0);
                for (unsigned int feature = 0; feature <= dim; ++feature)
                  {
                    const double t = T[feature];
                    if (t == 0)
                      continue;
                    const double *d = &D(a * (dim + 1) + feature, 0);
                    for (unsigned int col = 0; col < nc * n; ++col)
                      row[col] += t * d[col];
                  }
              }
          }
      }
  }


  template <int dim>
  WeakVelocityDirichlet<dim>::WeakVelocityDirichlet(
    const SplineDofHandler<dim>  &dofs,
    const FlowCoefficients<dim>  &coefficients,
    const BoundarySelection<dim> &selection,
    const Function<dim>          &boundary_velocity,
    const double                  penalty_constant,
    const bool                    inflow_term)
    : FlowTerm<dim>(dofs, coefficients)
    , selection(selection)
    , boundary_velocity(boundary_velocity)
    , penalty_constant(penalty_constant)
    , inflow_term(inflow_term)
  {}


  template <int dim>
  void
  WeakVelocityDirichlet<dim>::assemble_face(const unsigned int           face,
                                            const SplineCellValues<dim> &v,
                                            FullMatrix<double>          &A,
                                            Vector<double> &b) const
  {
    const unsigned int               n = v.n_basis_per_element();
    std::vector<std::vector<double>> cu, cp;
    get_element_coefficients(dofs, *state.velocity, v.element(), cu);
    get_element_coefficients(dofs, *state.pressure, v.element(), cp);
    const double Re = coefficients.reynolds_number;
    const double ku = state.velocity_factor, kp = state.pressure_factor;

    for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
      {
        const Point<dim> &x = v.quadrature_point(q);
        if (!selection.contains(face, x))
          continue;
        const double          JxW = v.JxW(q);
        const Tensor<1, dim> &m   = v.normal_vector(q);
        const double          nu  = coefficients.viscosity_at(x) / Re;
        // (H21): h_n = (m.G m)^(-1/2).
        const double h_n   = 1. / std::sqrt(m * (v.metric_tensor(q) * m));
        const double tau_b = penalty_constant * nu / h_n;

        Tensor<1, dim> u, g;
        Tensor<2, dim> grad_u;
        for (unsigned int a = 0; a < dim; ++a)
          {
            u[a]                   = v.value(cu[a], q);
            const Tensor<1, dim> d = v.gradient(cu[a], q);
            for (unsigned int k = 0; k < dim; ++k)
              grad_u[a][k] = d[k];
            g[a] = u[a] - boundary_velocity.value(x, a);
          }
        const double         p = v.value(cp[dim], q);
        const Tensor<1, dim> sigma
          = nu * ((grad_u + transpose(grad_u)) * m) - p * m;
        const double u_n    = u * m;
        const bool   inflow = inflow_term && u_n < 0;
        const double beta   = inflow ? u_n : 0.;

        // Residual on w = N e_a: -N sigma_a - nu (g_a dN.m + m_a dN.g)
        // + tau_B N g_a - N beta g_a; on q = N: -N m.g.
        for (unsigned int i = 0; i < n; ++i)
          {
            const double          N   = v.shape_value(i, q);
            const Tensor<1, dim> &dN  = v.shape_grad(i, q);
            const double          dNm = dN * m, dNg = dN * g;
            for (unsigned int a = 0; a < dim; ++a)
              b(a * n + i) -= (-N * sigma[a] - nu * (g[a] * dNm + m[a] * dNg)
                               + (tau_b - beta) * N * g[a])
                              * JxW;
            b(dim * n + i) -= -N * (m * g) * JxW;
          }
        if (!state.with_matrix)
          continue;
        for (unsigned int j = 0; j < n; ++j)
          {
            const double          phi   = v.shape_value(j, q);
            const Tensor<1, dim> &dphi  = v.shape_grad(j, q);
            const double          dphim = dphi * m;
            for (unsigned int i = 0; i < n; ++i)
              {
                const double          N   = v.shape_value(i, q);
                const Tensor<1, dim> &dN  = v.shape_grad(i, q);
                const double          dNm = dN * m;
                // Velocity trial phi e_c: d g = ku phi e_c,
                // d sigma_a = nu ku (delta_ac dphi.m + d_a phi m_c),
                // d beta = ku phi m_c on the inflow part.
                for (unsigned int c = 0; c < dim; ++c)
                  for (unsigned int a = 0; a < dim; ++a)
                    {
                      double value
                        = -N * nu * ku
                            * ((a == c ? dphim : 0.) + dphi[a] * m[c])
                          - nu * ku * phi
                              * ((a == c ? dNm : 0.) + m[a] * dN[c]);
                      if (a == c)
                        value += (tau_b - beta) * N * ku * phi;
                      if (inflow)
                        value -= N * g[a] * ku * phi * m[c];
                      A(a * n + i, c * n + j) += value * JxW;
                    }
                // Pressure trial: d sigma_a = -kp phi m_a.
                for (unsigned int a = 0; a < dim; ++a)
                  A(a * n + i, dim * n + j) += N * kp * phi * m[a] * JxW;
                // Pressure test row: -N m . d g.
                for (unsigned int c = 0; c < dim; ++c)
                  A(dim * n + i, c * n + j) += -N * m[c] * ku * phi * JxW;
              }
          }
      }
  }


  template struct FlowCoefficients<2>;
  template struct FlowCoefficients<3>;
  template <int dim>
  void
  RBVMSLumpedSchurOperators<dim>::assemble_cell(const SplineCellValues<dim> &v,
                                                FullMatrix<double> & /*matrix*/,
                                                Vector<double> &b) const
  {
    const unsigned int               n = v.n_basis_per_element();
    std::vector<std::vector<double>> cu;
    get_element_coefficients(dofs, *state.velocity, v.element(), cu);
    const double Re = coefficients.reynolds_number;
    for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
      {
        Tensor<1, dim> u;
        for (unsigned int a = 0; a < dim; ++a)
          u[a] = v.value(cu[a], q);
        const double nu = coefficients.viscosity_at(v.quadrature_point(q)) / Re;
        const Tensor<2, dim> &G     = v.metric_tensor(q);
        const double          tau_m = tau_momentum(
          G, u, state.dt, nu, coefficients.inverse_estimate_constant);
        const double tau_c = 1. / (trace(G) * tau_m);
        for (unsigned int i = 0; i < n; ++i)
          {
            const double NJxW = v.shape_value(i, q) * v.JxW(q);
            for (unsigned int a = 0; a < dim; ++a)
              b(a * n + i) += state.rate_factor * NJxW;
            b(dim * n + i) += state.pressure_factor * NJxW / (nu + tau_c);
          }
      }
  }


  template class NavierStokesRBVMS<2>;
  template class NavierStokesRBVMS<3>;
  template class RBVMSLumpedSchurOperators<2>;
  template class RBVMSLumpedSchurOperators<3>;
  template class WeakVelocityDirichlet<2>;
  template class WeakVelocityDirichlet<3>;
} // namespace vesicle_iga
