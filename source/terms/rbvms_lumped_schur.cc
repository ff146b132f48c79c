#include <vesicle_iga/terms/navier_stokes_rbvms.h>
#include <vesicle_iga/terms/rbvms_lumped_schur.h>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  double
  inverse_schur_viscosity(const Tensor<2, dim> &G,
                          const Tensor<1, dim> &u,
                          const double          time_step,
                          const double          nu,
                          const double          inverse_estimate_constant)
  {
    const double tau_m = NavierStokesRBVMS<dim>::tau_momentum(
      G, u, time_step, nu, inverse_estimate_constant);
    const double tau_c = 1. / (trace(G) * tau_m);
    return 1. / (nu + tau_c);
  }


  template <int dim>
  void
  RBVMSLumpedSchurOperators<dim>::declare(TermDeclaration<dim> &d)
  {
    using D = Derivative<dim>;
    coefficients.viscosity->declare(d);
    if (coefficients.viscosity->needs_points())
      d.needs_points();
    for (unsigned int a = 0; a < dim; ++a)
      {
        u[a]          = d.value(velocity + a, D::value);
        r_velocity[a] = d.residual(velocity + a, D::value);
      }
    r_pressure = d.residual(pressure, D::value);
  }


  template <int dim>
  void
  RBVMSLumpedSchurOperators<dim>::evaluate(const QuadratureInputs<dim> &in,
                                           TermCoefficients &out) const
  {
    thread_local std::vector<double>         mu;
    thread_local std::vector<Tensor<1, dim>> grad_mu;
    coefficients.viscosity->evaluate(in, mu, grad_mu);
    const double Re = coefficients.reynolds_number;
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        Tensor<1, dim> uq;
        for (unsigned int a = 0; a < dim; ++a)
          uq[a] = in[u[a]][q];
        for (unsigned int a = 0; a < dim; ++a)
          out[r_velocity[a]][q] += k_m;
        out[r_pressure][q] += k_p
                              * inverse_schur_viscosity<dim>(
                                in.metric(q),
                                uq,
                                coefficients.tau_time_step(in.time_step),
                                mu[q] / Re,
                                coefficients.inverse_estimate_constant);
      }
  }

  template double
  inverse_schur_viscosity<2>(const Tensor<2, 2> &,
                             const Tensor<1, 2> &,
                             double,
                             double,
                             double);
  template double
  inverse_schur_viscosity<3>(const Tensor<2, 3> &,
                             const Tensor<1, 3> &,
                             double,
                             double,
                             double);
  template class RBVMSLumpedSchurOperators<2>;
  template class RBVMSLumpedSchurOperators<3>;
} // namespace vesicle_iga
