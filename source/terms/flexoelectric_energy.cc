#include <vesicle_iga/terms/flexoelectric_energy.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  FlexoelectricEnergy<dim>::FlexoelectricEnergy(const unsigned int phi,
                                                const unsigned int potential,
                                                const double       prefactor,
                                                const double       eps)
    : fields(phi, potential)
    , C(prefactor)
    , eps(eps)
  {}


  template <int dim>
  void
  FlexoelectricEnergy<dim>::declare(TermDeclaration<dim> &d)
  {
    using D = Derivative<dim>;
    fields.declare_value(d);
    fields.declare_gradient(d);
    fields.declare_laplacian(d);
    fields.declare_potential_gradient(d);
    const unsigned int phi = fields.phi;
    r_value                = d.residual(phi, D::value);
    r_laplacian            = d.residual(phi, D::laplacian);
    k_vv                   = d.jacobian(phi, D::value, phi, D::value);
    for (unsigned int k = 0; k < dim; ++k)
      {
        r_gradient[k] = d.residual(phi, D::gradient(k));
        k_vg[k]       = d.jacobian(phi, D::value, phi, D::gradient(k));
        k_lg[k]       = d.jacobian(phi, D::laplacian, phi, D::gradient(k));
        k_gl[k]       = d.jacobian(phi, D::gradient(k), phi, D::laplacian);
        k_gv[k]       = d.jacobian(phi, D::gradient(k), phi, D::value);
      }
  }


  template <int dim>
  void
  FlexoelectricEnergy<dim>::evaluate(const QuadratureInputs<dim> &in,
                                     TermCoefficients            &out) const
  {
    const double *phi = in[fields.value], *lap = in[fields.laplacian];
    std::array<const double *, dim> gphi, gpsi;
    std::array<double *, dim>       rg;
    for (unsigned int k = 0; k < dim; ++k)
      {
        gphi[k] = in[fields.gradient[k]];
        gpsi[k] = in[fields.potential_gradient[k]];
        rg[k]   = out[r_gradient[k]];
      }
    double *rv = out[r_value], *rl = out[r_laplacian];
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        const double p  = phi[q];
        const double h  = p * (1 - p * p) / eps; // (E4)
        const double h1 = (1 - 3 * p * p) / eps; // (E13)
        double       gg = 0;
        for (unsigned int k = 0; k < dim; ++k)
          gg += gphi[k][q] * gpsi[k][q];
        // (E18): -C [(h' grad phi.grad psi, w) + (eps grad phi.grad psi,
        //   Delta w) + ((eps Delta phi + h) grad psi, grad w)]
        rv[q] += -C * h1 * gg;
        rl[q] += -C * eps * gg;
        for (unsigned int k = 0; k < dim; ++k)
          rg[k][q] += -C * (eps * lap[q] + h) * gpsi[k][q];
      }
    if (!out.matrix())
      return;
    // (E20): -C [(h'' dphi grad phi.grad psi + h' grad dphi.grad psi, w)
    //   + (eps grad dphi.grad psi, Delta w)
    //   + ((eps Delta dphi + h' dphi) grad psi, grad w)]
    double *vv = out[k_vv];
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        double gg = 0;
        for (unsigned int k = 0; k < dim; ++k)
          gg += gphi[k][q] * gpsi[k][q];
        vv[q] += -C * (-6 * phi[q] / eps) * gg;
      }
    for (unsigned int k = 0; k < dim; ++k)
      {
        double *vg = out[k_vg[k]], *lg = out[k_lg[k]], *gl = out[k_gl[k]],
               *gv = out[k_gv[k]];
        for (unsigned int q = 0; q < in.size(); ++q)
          {
            const double s  = gpsi[k][q];
            const double h1 = (1 - 3 * phi[q] * phi[q]) / eps;
            vg[q] += -C * h1 * s;
            lg[q] += -C * eps * s;
            gl[q] += -C * eps * s;
            gv[q] += -C * h1 * s;
          }
      }
  }


  template <int dim>
  void
  FlexoelectricEnergy<dim>::integrate(const QuadratureInputs<dim> &in,
                                      const double                *JxW,
                                      double                      *sums) const
  {
    const double *phi = in[fields.value], *lap = in[fields.laplacian];
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        const double h  = phi[q] * (1 - phi[q] * phi[q]) / eps;
        double       gg = 0;
        for (unsigned int k = 0; k < dim; ++k)
          gg += in[fields.gradient[k]][q] * in[fields.potential_gradient[k]][q];
        sums[0] += -C * (eps * lap[q] + h) * gg * JxW[q]; // (E6)
      }
  }

  template class FlexoelectricEnergy<2>;
  template class FlexoelectricEnergy<3>;
} // namespace vesicle_iga
