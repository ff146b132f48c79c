#include <vesicle_iga/physics/electric_energies.h>

#include <cmath>

namespace vesicle_iga
{
  template <int dim>
  FlexoelectricEnergy<dim>::FlexoelectricEnergy(const double c1,
                                                const double d_m,
                                                const double eps)
    : C(3 * c1 * d_m / (2 * std::sqrt(2.)))
    , eps(eps)
  {}


  template <int dim>
  double
  FlexoelectricEnergy<dim>::density(const PhaseFieldPoint<dim> &p) const
  {
    const double h = p.phi * (1 - p.phi * p.phi) / eps;
    return -C * (eps * p.laplacian_phi + h) * (p.grad_phi * p.grad_psi);
  }


  template <int dim>
  void
  FlexoelectricEnergy<dim>::add_variation(const PhaseFieldPoint<dim> &p,
                                          PointForm<dim> &form) const
  {
    using F          = PointForm<dim>;
    const double phi = p.phi;
    const double h   = phi * (1 - phi * phi) / eps; // (E4)
    const double h1  = (1 - 3 * phi * phi) / eps;   // (E13)
    const double h2  = -6 * phi / eps;              // (E13)
    const double gg  = p.grad_phi * p.grad_psi;
    // (E18): -C [(h' grad phi.grad psi, w) + (eps grad phi.grad psi,
    //   Delta w) + ((eps Delta phi + h) grad psi, grad w)]
    form.r[F::value] += -C * h1 * gg;
    form.r[F::laplacian] += -C * eps * gg;
    for (unsigned int d = 0; d < dim; ++d)
      form.r[F::gradient(d)]
        += -C * (eps * p.laplacian_phi + h) * p.grad_psi[d];
    // (E20): -C [(h'' dphi grad phi.grad psi + h' grad dphi.grad psi, w)
    //   + (eps grad dphi.grad psi, Delta w)
    //   + ((eps Delta dphi + h' dphi) grad psi, grad w)]
    form.K[F::value][F::value] += -C * h2 * gg;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double s = p.grad_psi[d];
        form.K[F::value][F::gradient(d)] += -C * h1 * s;
        form.K[F::laplacian][F::gradient(d)] += -C * eps * s;
        form.K[F::gradient(d)][F::laplacian] += -C * eps * s;
        form.K[F::gradient(d)][F::value] += -C * h1 * s;
      }
  }


  template <int dim>
  MembraneDielectricEnergy<dim>::MembraneDielectricEnergy(const double d_m,
                                                          const double e_m,
                                                          const double eps)
    : C(3 * d_m * e_m / (2 * std::sqrt(2.) * eps))
  {}


  template <int dim>
  double
  MembraneDielectricEnergy<dim>::density(const PhaseFieldPoint<dim> &p) const
  {
    const double s = 1 - p.phi * p.phi;
    // 3 d_m e_m / (8 sqrt2 eps) = C / 4
    return -0.25 * C * s * s * p.grad_psi.norm_square();
  }


  template <int dim>
  void
  MembraneDielectricEnergy<dim>::add_variation(const PhaseFieldPoint<dim> &p,
                                               PointForm<dim> &form) const
  {
    using F          = PointForm<dim>;
    const double E2  = p.grad_psi.norm_square();
    const double phi = p.phi;
    form.r[F::value] += C * (phi - phi * phi * phi) * E2;       // (E18)
    form.K[F::value][F::value] += C * (1 - 3 * phi * phi) * E2; // (E20)
  }


  template <int dim>
  ElectrolyteDielectricEnergy<dim>::ElectrolyteDielectricEnergy(
    const double e_in,
    const double e_out)
    : e_in(e_in)
    , e_out(e_out)
  {}


  template <int dim>
  double
  ElectrolyteDielectricEnergy<dim>::density(const PhaseFieldPoint<dim> &p) const
  {
    const double e = 0.5 * e_in * (1 - p.phi) + 0.5 * e_out * (1 + p.phi);
    return -0.5 * e * p.grad_psi.norm_square();
  }


  template <int dim>
  void
  ElectrolyteDielectricEnergy<dim>::add_variation(const PhaseFieldPoint<dim> &p,
                                                  PointForm<dim> &form) const
  {
    // (E18): (e_in - e_out)/4 (|grad psi|^2, w).
    form.r[PointForm<dim>::value]
      += 0.25 * (e_in - e_out) * p.grad_psi.norm_square();
  }

  template class FlexoelectricEnergy<2>;
  template class FlexoelectricEnergy<3>;
  template class MembraneDielectricEnergy<2>;
  template class MembraneDielectricEnergy<3>;
  template class ElectrolyteDielectricEnergy<2>;
  template class ElectrolyteDielectricEnergy<3>;
} // namespace vesicle_iga
