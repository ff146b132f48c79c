// The lumped viscous operator of the tension Schur complement (see the
// header).

#include <vesicle_iga/terms/rbvms_lumped_schur.h>
#include <vesicle_iga/terms/tension_lumped_schur.h>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  void
  TensionLumpedSchur<dim>::declare(TermDeclaration<dim> &d)
  {
    using D = Derivative<dim>;
    flow.viscosity->declare(d);
    if (flow.viscosity->needs_points())
      d.needs_points();
    for (unsigned int a = 0; a < dim; ++a)
      u[a] = d.value(velocity + a, D::value);
    phase     = d.value(phi, D::value);
    r_tension = d.residual(tension, D::value);
  }


  template <int dim>
  void
  TensionLumpedSchur<dim>::evaluate(const QuadratureInputs<dim> &in,
                                    TermCoefficients            &out) const
  {
    thread_local std::vector<double>         mu;
    thread_local std::vector<Tensor<1, dim>> grad_mu;
    flow.viscosity->evaluate(in, mu, grad_mu);
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        Tensor<1, dim> uq;
        for (unsigned int a = 0; a < dim; ++a)
          uq[a] = in[u[a]][q];
        const double delta = membrane::surface_delta(in[phase][q], eps);
        out[r_tension][q]
          += k_lambda * delta * delta
             * inverse_schur_viscosity<dim>(in.metric(q),
                                            uq,
                                            flow.tau_time_step(in.time_step),
                                            mu[q] / flow.reynolds_number,
                                            flow.inverse_estimate_constant);
      }
  }

  template class TensionLumpedSchur<2>;
  template class TensionLumpedSchur<3>;
} // namespace vesicle_iga
