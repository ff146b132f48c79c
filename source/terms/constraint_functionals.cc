#include <vesicle_iga/terms/constraint_functionals.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  AreaConstraint<dim>::AreaConstraint(const unsigned int phi,
                                      const double       epsilon)
    : fields(phi)
    , eps(epsilon)
  {}


  template <int dim>
  void
  AreaConstraint<dim>::declare(TermDeclaration<dim> &d)
  {
    using D = Derivative<dim>;
    fields.declare_value(d);
    fields.declare_gradient(d);
    const unsigned int phi = fields.phi;
    r_value                = d.residual(phi, D::value);
    k_vv                   = d.jacobian(phi, D::value, phi, D::value);
    for (unsigned int k = 0; k < dim; ++k)
      {
        r_gradient[k] = d.residual(phi, D::gradient(k));
        k_gg[k]       = d.jacobian(phi, D::gradient(k), phi, D::gradient(k));
      }
  }


  template <int dim>
  void
  AreaConstraint<dim>::evaluate(const QuadratureInputs<dim> &in,
                                TermCoefficients            &out) const
  {
    const double  c   = 3 * Lambda / (2 * std::sqrt(2.));
    const double *phi = in[fields.value];
    double       *rv  = out[r_value];
    // (E18): c [(eps grad phi, grad w) + ((phi^3 - phi)/eps, w)]
    for (unsigned int q = 0; q < in.size(); ++q)
      rv[q] += c * (phi[q] * phi[q] * phi[q] - phi[q]) / eps;
    for (unsigned int k = 0; k < dim; ++k)
      {
        const double *g  = in[fields.gradient[k]];
        double       *rg = out[r_gradient[k]];
        for (unsigned int q = 0; q < in.size(); ++q)
          rg[q] += c * eps * g[q];
      }
    if (!out.matrix())
      return;
    // (E20): c [(eps grad dphi, grad w) + ((3 phi^2 - 1)/eps dphi, w)]
    double *vv = out[k_vv];
    for (unsigned int q = 0; q < in.size(); ++q)
      vv[q] += c * (3 * phi[q] * phi[q] - 1) / eps;
    for (unsigned int k = 0; k < dim; ++k)
      {
        double *gg = out[k_gg[k]];
        for (unsigned int q = 0; q < in.size(); ++q)
          gg[q] += c * eps;
      }
  }


  template <int dim>
  void
  AreaConstraint<dim>::integrate(const QuadratureInputs<dim> &in,
                                 const double                *JxW,
                                 double                      *sums) const
  {
    const double *phi = in[fields.value];
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        double g2 = 0;
        for (unsigned int k = 0; k < dim; ++k)
          g2 += in[fields.gradient[k]][q] * in[fields.gradient[k]][q];
        const double s = phi[q] * phi[q] - 1;
        // (E9)
        sums[0] += 3 / (2 * std::sqrt(2.))
                   * (0.5 * eps * g2 + s * s / (4 * eps)) * JxW[q];
      }
  }


  template <int dim>
  void
  VolumeConstraint<dim>::declare(TermDeclaration<dim> &d)
  {
    fields.declare_value(d);
    r_value = d.residual(fields.phi, Derivative<dim>::value);
  }


  template <int dim>
  void
  VolumeConstraint<dim>::evaluate(const QuadratureInputs<dim> &in,
                                  TermCoefficients            &out) const
  {
    // (E18): -Lambda_V / 2 (1, w)
    double *rv = out[r_value];
    for (unsigned int q = 0; q < in.size(); ++q)
      rv[q] += -0.5 * Lambda;
  }


  template <int dim>
  void
  VolumeConstraint<dim>::integrate(const QuadratureInputs<dim> &in,
                                   const double                *JxW,
                                   double                      *sums) const
  {
    const double *phi = in[fields.value];
    for (unsigned int q = 0; q < in.size(); ++q)
      sums[0] += 0.5 * (1 - phi[q]) * JxW[q]; // (E9)
  }

  template class AreaConstraint<2>;
  template class AreaConstraint<3>;
  template class VolumeConstraint<2>;
  template class VolumeConstraint<3>;
} // namespace vesicle_iga
