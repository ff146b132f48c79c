#include <deal.II/lac/vector.h>

#include <vesicle_iga/terms/weak_velocity_dirichlet.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  WeakVelocityDirichlet<dim>::WeakVelocityDirichlet(
    const unsigned int            velocity,
    const unsigned int            pressure,
    const FlowCoefficients<dim>  &coefficients,
    const BoundarySelection<dim> &selection,
    const Function<dim>          &boundary_velocity,
    const double                  penalty_constant,
    const bool                    inflow_term)
    : velocity(velocity)
    , pressure(pressure)
    , coefficients(coefficients)
    , selection(selection)
    , boundary_velocity(boundary_velocity)
    , penalty_constant(penalty_constant)
    , inflow_term(inflow_term)
  {}


  template <int dim>
  void
  WeakVelocityDirichlet<dim>::declare(TermDeclaration<dim> &d)
  {
    using D = Derivative<dim>;
    d.needs_points();
    coefficients.viscosity->declare(d);
    p          = d.value(pressure, D::value);
    r_pressure = d.residual(pressure, D::value);
    for (unsigned int a = 0; a < dim; ++a)
      {
        u[a]       = d.value(velocity + a, D::value);
        r_value[a] = d.residual(velocity + a, D::value);
        j_vp[a]    = d.jacobian(velocity + a, D::value, pressure, D::value);
        j_pv[a]    = d.jacobian(pressure, D::value, velocity + a, D::value);
        for (unsigned int k = 0; k < dim; ++k)
          {
            grad_u[a][k]     = d.value(velocity + a, D::gradient(k));
            r_gradient[a][k] = d.residual(velocity + a, D::gradient(k));
          }
        for (unsigned int c = 0; c < dim; ++c)
          {
            j_vv[a][c]
              = d.jacobian(velocity + a, D::value, velocity + c, D::value);
            for (unsigned int l = 0; l < dim; ++l)
              {
                j_vg[a][c][l] = d.jacobian(velocity + a,
                                           D::value,
                                           velocity + c,
                                           D::gradient(l));
                j_gv[a][l][c] = d.jacobian(velocity + a,
                                           D::gradient(l),
                                           velocity + c,
                                           D::value);
              }
          }
      }
  }


  template <int dim>
  void
  WeakVelocityDirichlet<dim>::evaluate(const QuadratureInputs<dim> &in,
                                       TermCoefficients            &out) const
  {
    thread_local std::vector<double>         mu;
    thread_local std::vector<Tensor<1, dim>> grad_mu;
    coefficients.viscosity->evaluate(in, mu, grad_mu);
    const unsigned int face = in.face();
    const double       Re   = coefficients.reynolds_number;
    Vector<double>     ub(boundary_velocity.n_components);
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        if (!selection.contains(face, in.point(q)))
          continue;
        const Tensor<1, dim> &m  = in.normal(q);
        const double          nu = mu[q] / Re;
        // (H21): h_n = (m.G m)^(-1/2).
        const double h_n   = 1. / std::sqrt(m * (in.metric(q) * m));
        const double tau_b = penalty_constant * nu / h_n;
        boundary_velocity.vector_value(in.point(q), ub);
        Tensor<1, dim> uq, g;
        Tensor<2, dim> gu;
        for (unsigned int a = 0; a < dim; ++a)
          {
            uq[a] = in[u[a]][q];
            g[a]  = uq[a] - ub[a];
            for (unsigned int k = 0; k < dim; ++k)
              gu[a][k] = in[grad_u[a][k]][q];
          }
        const Tensor<1, dim> sigma
          = nu * ((gu + transpose(gu)) * m) - in[p][q] * m;
        const double u_n    = uq * m;
        const bool   inflow = inflow_term && u_n < 0;
        const double beta   = inflow ? u_n : 0.;
        // Residual on w = N e_a: N (-sigma_a + (tau_B - beta) g_a)
        // + d_k N (-nu (g_a m_k + m_a g_k)); on q = N: -N m.g.
        for (unsigned int a = 0; a < dim; ++a)
          {
            out[r_value[a]][q] += -sigma[a] + (tau_b - beta) * g[a];
            for (unsigned int k = 0; k < dim; ++k)
              out[r_gradient[a][k]][q] += -nu * (g[a] * m[k] + m[a] * g[k]);
          }
        out[r_pressure][q] += -(m * g);
        if (!out.matrix())
          continue;
        for (unsigned int a = 0; a < dim; ++a)
          {
            // d(-sigma_a)/dp = m_a; d(-m.g)/du_a = -m_a.
            out[j_vp[a]][q] += m[a];
            out[j_pv[a]][q] += -m[a];
            for (unsigned int c = 0; c < dim; ++c)
              {
                // d g = e_c; d beta = m_c on the inflow part.
                double value = (a == c ? tau_b - beta : 0.);
                if (inflow)
                  value -= g[a] * m[c];
                out[j_vv[a][c]][q] += value;
                for (unsigned int l = 0; l < dim; ++l)
                  {
                    // d(-sigma_a)/d(d_l u_c) = -nu (delta_ac m_l +
                    // delta_al m_c).
                    out[j_vg[a][c][l]][q]
                      += -nu * ((a == c ? m[l] : 0.) + (a == l ? m[c] : 0.));
                    // d(-nu (g_a m_l + m_a g_l))/du_c.
                    out[j_gv[a][l][c]][q]
                      += -nu * ((a == c ? m[l] : 0.) + (l == c ? m[a] : 0.));
                  }
              }
          }
      }
  }

  template class WeakVelocityDirichlet<2>;
  template class WeakVelocityDirichlet<3>;
} // namespace vesicle_iga
