// Weak inflow condition phi = -1 of a Part H phase field (spec 4.10).

#include <vesicle_iga/terms/phase_field_inflow.h>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  PhaseFieldInflow<dim>::PhaseFieldInflow(const unsigned int           velocity,
                                          const unsigned int           phi,
                                          const std::array<bool, dim> &periodic,
                                          const double outside_value)
    : velocity(velocity)
    , phi(phi)
    , periodic(periodic)
    , outside_value(outside_value)
  {}


  template <int dim>
  void
  PhaseFieldInflow<dim>::declare(TermDeclaration<dim> &d)
  {
    using D   = Derivative<dim>;
    phi_value = d.value(phi, D::value);
    r_phi     = d.residual(phi, D::value);
    j_phi_phi = d.jacobian(phi, D::value, phi, D::value);
    for (unsigned int a = 0; a < dim; ++a)
      {
        u[a]       = d.value(velocity + a, D::value);
        j_phi_u[a] = d.jacobian(phi, D::value, velocity + a, D::value);
      }
  }


  template <int dim>
  void
  PhaseFieldInflow<dim>::evaluate(const QuadratureInputs<dim> &in,
                                  TermCoefficients            &out) const
  {
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        const Tensor<1, dim> &m   = in.normal(q);
        double                u_n = 0;
        for (unsigned int a = 0; a < dim; ++a)
          u_n += in[u[a]][q] * m[a];
        if (u_n >= 0)
          continue;
        // -(u.m) (phi - phi_b) on the inflow part.
        const double jump = in[phi_value][q] - outside_value;
        out[r_phi][q] += -u_n * jump;
        if (!out.matrix())
          continue;
        out[j_phi_phi][q] += -u_n;
        for (unsigned int a = 0; a < dim; ++a)
          out[j_phi_u[a]][q] += -m[a] * jump;
      }
  }

  template class PhaseFieldInflow<2>;
  template class PhaseFieldInflow<3>;
} // namespace vesicle_iga
