#include <vesicle_iga/terms/bending_energy.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  BendingEnergy<dim>::BendingEnergy(const unsigned int phi,
                                    const double       kappa,
                                    const double       epsilon,
                                    const double       spontaneous_curvature)
    : fields(phi)
    , kappa(kappa)
    , eps(epsilon)
    , H_sp(spontaneous_curvature)
  {}


  template <int dim>
  void
  BendingEnergy<dim>::declare(TermDeclaration<dim> &d)
  {
    using D = Derivative<dim>;
    fields.declare_value(d);
    fields.declare_laplacian(d);
    const unsigned int phi = fields.phi;
    r_value                = d.residual(phi, D::value);
    r_laplacian            = d.residual(phi, D::laplacian);
    k_vv                   = d.jacobian(phi, D::value, phi, D::value);
    k_vl                   = d.jacobian(phi, D::value, phi, D::laplacian);
    k_lv                   = d.jacobian(phi, D::laplacian, phi, D::value);
    k_ll                   = d.jacobian(phi, D::laplacian, phi, D::laplacian);
  }


  template <int dim>
  void
  BendingEnergy<dim>::evaluate(const QuadratureInputs<dim> &in,
                               TermCoefficients            &out) const
  {
    const double *phi = in[fields.value], *lap = in[fields.laplacian];
    double       *rv = out[r_value], *rl = out[r_laplacian];
    const double  c  = 3 * kappa / (2 * std::sqrt(2.) * eps);
    const double  s2 = std::sqrt(2.);
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        const double p = phi[q];
        // (E4), (E13)
        const double g  = (p / eps - H_sp / s2) * (1 - p * p);
        const double g1 = (1 - 3 * p * p) / eps + s2 * H_sp * p;
        const double W  = eps * lap[q] + g;
        // (E18): c (W, eps Delta w + g' w)
        rv[q] += c * W * g1;
        rl[q] += c * W * eps;
      }
    if (!out.matrix())
      return;
    double *vv = out[k_vv], *vl = out[k_vl], *lv = out[k_lv], *ll = out[k_ll];
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        const double p  = phi[q];
        const double g  = (p / eps - H_sp / s2) * (1 - p * p);
        const double g1 = (1 - 3 * p * p) / eps + s2 * H_sp * p;
        const double g2 = -6 * p / eps + s2 * H_sp;
        const double W  = eps * lap[q] + g;
        // (E20): c [(eps Delta dphi + g' dphi, eps Delta w + g' w)
        //           + (W g'' dphi, w)]
        vv[q] += c * (g1 * g1 + W * g2);
        vl[q] += c * g1 * eps;
        lv[q] += c * eps * g1;
        ll[q] += c * eps * eps;
      }
  }


  template <int dim>
  void
  BendingEnergy<dim>::integrate(const QuadratureInputs<dim> &in,
                                const double                *JxW,
                                double                      *sums) const
  {
    const double *phi = in[fields.value], *lap = in[fields.laplacian];
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        const double p = phi[q];
        const double W
          = eps * lap[q] + (p / eps - H_sp / std::sqrt(2.)) * (1 - p * p);
        // (E5)
        sums[0] += 3 * kappa / (4 * std::sqrt(2.) * eps) * W * W * JxW[q];
      }
  }

  template class BendingEnergy<2>;
  template class BendingEnergy<3>;
} // namespace vesicle_iga
