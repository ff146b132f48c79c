#include <vesicle_iga/physics/bending_energy.h>

#include <cmath>

namespace vesicle_iga
{
  // (E4) and its derivatives (E13).
  template <int dim>
  double
  BendingEnergy<dim>::g(const double phi) const
  {
    return (phi / eps - H_sp / std::sqrt(2.)) * (1 - phi * phi);
  }

  template <int dim>
  double
  BendingEnergy<dim>::g1(const double phi) const
  {
    return (1 - 3 * phi * phi) / eps + std::sqrt(2.) * H_sp * phi;
  }

  template <int dim>
  double
  BendingEnergy<dim>::g2(const double phi) const
  {
    return -6 * phi / eps + std::sqrt(2.) * H_sp;
  }


  template <int dim>
  double
  BendingEnergy<dim>::density(const PhaseFieldPoint<dim> &p) const
  {
    const double W = eps * p.laplacian_phi + g(p.phi);
    return 3 * kappa / (4 * std::sqrt(2.) * eps) * W * W;
  }


  template <int dim>
  void
  BendingEnergy<dim>::add_variation(const PhaseFieldPoint<dim> &p,
                                    PointForm<dim>             &form) const
  {
    using F         = PointForm<dim>;
    const double c  = 3 * kappa / (2 * std::sqrt(2.) * eps);
    const double W  = eps * p.laplacian_phi + g(p.phi);
    const double gp = g1(p.phi);
    // (E18): c (W, eps Delta w + g' w)
    form.r[F::value] += c * W * gp;
    form.r[F::laplacian] += c * W * eps;
    // (E20): c [(eps Delta dphi + g' dphi, eps Delta w + g' w)
    //           + (W g'' dphi, w)]
    form.K[F::value][F::value] += c * (gp * gp + W * g2(p.phi));
    form.K[F::value][F::laplacian] += c * gp * eps;
    form.K[F::laplacian][F::value] += c * eps * gp;
    form.K[F::laplacian][F::laplacian] += c * eps * eps;
  }


  template <int dim>
  double
  AreaConstraint<dim>::density(const PhaseFieldPoint<dim> &p) const
  {
    const double s = p.phi * p.phi - 1;
    return 3 / (2 * std::sqrt(2.))
           * (0.5 * eps * p.grad_phi.norm_square() + s * s / (4 * eps));
  }


  template <int dim>
  void
  AreaConstraint<dim>::add_variation(const PhaseFieldPoint<dim> &p,
                                     PointForm<dim>             &form) const
  {
    using F        = PointForm<dim>;
    const double c = 3 * Lambda / (2 * std::sqrt(2.));
    // (E18): c [(eps grad phi, grad w) + ((phi^3 - phi)/eps, w)]
    form.r[F::value] += c * (p.phi * p.phi * p.phi - p.phi) / eps;
    for (unsigned int d = 0; d < dim; ++d)
      {
        form.r[F::gradient(d)] += c * eps * p.grad_phi[d];
        // (E20): c [(eps grad dphi, grad w) + ((3 phi^2 - 1)/eps dphi, w)]
        form.K[F::gradient(d)][F::gradient(d)] += c * eps;
      }
    form.K[F::value][F::value] += c * (3 * p.phi * p.phi - 1) / eps;
  }

  template class BendingEnergy<2>;
  template class BendingEnergy<3>;
  template class AreaConstraint<2>;
  template class AreaConstraint<3>;
} // namespace vesicle_iga
