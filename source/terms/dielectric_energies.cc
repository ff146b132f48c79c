#include <vesicle_iga/terms/dielectric_energies.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    double
    field_squared(const QuadratureInputs<dim>        &in,
                  const std::array<InputHandle, dim> &g,
                  const unsigned int                  q)
    {
      double s = 0;
      for (unsigned int k = 0; k < dim; ++k)
        s += in[g[k]][q] * in[g[k]][q];
      return s;
    }
  } // namespace


  template <int dim>
  MembraneDielectricEnergy<dim>::MembraneDielectricEnergy(
    const unsigned int phi,
    const unsigned int potential,
    const double       d_m,
    const double       e_m,
    const double       eps)
    : fields(phi, potential)
    , C(3 * d_m * e_m / (2 * std::sqrt(2.) * eps))
  {}


  template <int dim>
  void
  MembraneDielectricEnergy<dim>::declare(TermDeclaration<dim> &d)
  {
    using D = Derivative<dim>;
    fields.declare_value(d);
    fields.declare_potential_gradient(d);
    r_value = d.residual(fields.phi, D::value);
    k_vv    = d.jacobian(fields.phi, D::value, fields.phi, D::value);
  }


  template <int dim>
  void
  MembraneDielectricEnergy<dim>::evaluate(const QuadratureInputs<dim> &in,
                                          TermCoefficients &out) const
  {
    const double *phi = in[fields.value];
    double       *rv  = out[r_value];
    double       *vv  = out.matrix() ? out[k_vv] : nullptr;
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        const double E2 = field_squared<dim>(in, fields.potential_gradient, q);
        const double p  = phi[q];
        rv[q] += C * (p - p * p * p) * E2; // (E18)
        if (vv)
          vv[q] += C * (1 - 3 * p * p) * E2; // (E20)
      }
  }


  template <int dim>
  void
  MembraneDielectricEnergy<dim>::integrate(const QuadratureInputs<dim> &in,
                                           const double                *JxW,
                                           double *sums) const
  {
    const double *phi = in[fields.value];
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        const double s = 1 - phi[q] * phi[q];
        // (E7): 3 d_m e_m / (8 sqrt2 eps) = C / 4
        sums[0] += -0.25 * C * s * s
                   * field_squared<dim>(in, fields.potential_gradient, q)
                   * JxW[q];
      }
  }


  template <int dim>
  ElectrolyteDielectricEnergy<dim>::ElectrolyteDielectricEnergy(
    const unsigned int phi,
    const unsigned int potential,
    const double       e_in,
    const double       e_out)
    : fields(phi, potential)
    , e_in(e_in)
    , e_out(e_out)
  {}


  template <int dim>
  void
  ElectrolyteDielectricEnergy<dim>::declare(TermDeclaration<dim> &d)
  {
    fields.declare_value(d);
    fields.declare_potential_gradient(d);
    r_value = d.residual(fields.phi, Derivative<dim>::value);
  }


  template <int dim>
  void
  ElectrolyteDielectricEnergy<dim>::evaluate(const QuadratureInputs<dim> &in,
                                             TermCoefficients &out) const
  {
    // (E18): (e_in - e_out)/4 (|grad psi|^2, w).
    double *rv = out[r_value];
    for (unsigned int q = 0; q < in.size(); ++q)
      rv[q] += 0.25 * (e_in - e_out)
               * field_squared<dim>(in, fields.potential_gradient, q);
  }


  template <int dim>
  void
  ElectrolyteDielectricEnergy<dim>::integrate(const QuadratureInputs<dim> &in,
                                              const double                *JxW,
                                              double *sums) const
  {
    const double *phi = in[fields.value];
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        const double e = 0.5 * e_in * (1 - phi[q]) + 0.5 * e_out * (1 + phi[q]);
        sums[0] += -0.5 * e
                   * field_squared<dim>(in, fields.potential_gradient, q)
                   * JxW[q]; // (E8)
      }
  }

  template class MembraneDielectricEnergy<2>;
  template class MembraneDielectricEnergy<3>;
  template class ElectrolyteDielectricEnergy<2>;
  template class ElectrolyteDielectricEnergy<3>;
} // namespace vesicle_iga
