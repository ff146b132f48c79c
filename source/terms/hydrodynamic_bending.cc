// Bending force of the Part H phase fields, mixed-free: (H24), (H25),
// spec 4.13.

#include <vesicle_iga/terms/hydrodynamic_bending.h>

namespace vesicle_iga
{
  template <int dim>
  HydrodynamicBendingFormula<dim>::HydrodynamicBendingFormula(
    const unsigned int          velocity,
    const unsigned int          phi,
    const MembraneCoefficients &coefficients)
    : eps(coefficients.epsilon)
    , eta(coefficients.mobility)
    , c(coefficients.bending_factor())
  {
    using D = Derivative<dim>;
    // Inputs: phi, d_k phi, d_k d_l phi (k <= l), d_a Delta phi.
    inputs.push_back({phi, D::value});
    for (unsigned int k = 0; k < dim; ++k)
      inputs.push_back({phi, D::gradient(k)});
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int l = k; l < dim; ++l)
        inputs.push_back({phi, D::hessian(k, l)});
    for (unsigned int a = 0; a < dim; ++a)
      inputs.push_back({phi, D::gradient_of_laplacian(a)});
    // Outputs: phase-field test (Laplacian, value); per velocity component
    // a: Laplacian, gradient, value of the test function.
    outputs.push_back({phi, D::laplacian});
    outputs.push_back({phi, D::value});
    for (unsigned int a = 0; a < dim; ++a)
      {
        outputs.push_back({velocity + a, D::laplacian});
        for (unsigned int k = 0; k < dim; ++k)
          outputs.push_back({velocity + a, D::gradient(k)});
        outputs.push_back({velocity + a, D::value});
      }
  }


  template <int dim>
  unsigned int
  HydrodynamicBendingFormula<dim>::hessian(const unsigned int k,
                                           const unsigned int l)
  {
    const unsigned int a = std::min(k, l), b = std::max(k, l);
    unsigned int       i = 1 + dim;
    for (unsigned int x = 0; x < dim; ++x)
      for (unsigned int y = x; y < dim; ++y, ++i)
        if (x == a && y == b)
          return i;
    return i;
  }


  template <int dim>
  template <typename T>
  void
  HydrodynamicBendingFormula<dim>::residual(const T *in, T *out) const
  {
    const T &phi = in[0];
    T        laplacian(0.);
    for (unsigned int l = 0; l < dim; ++l)
      laplacian += in[hessian(l, l)];
    // (H2) and the factor (3 phi^2 - 1) / eps^2 of (H3).
    const T f  = membrane::chemical_potential(phi, laplacian, eps);
    const T sf = (3. * phi * phi - 1.) / (eps * eps) * f;
    // (H24), times eta_phi (H16).
    out[0] = eta * c * f;
    out[1] = -eta * c * sf;
    // (H25) with the sign of (H14): -b(f; w . grad phi), w = N e_a.
    unsigned int o = 2;
    for (unsigned int a = 0; a < dim; ++a)
      {
        const T &grad_a = in[1 + a];
        out[o++]        = -c * f * grad_a;
        for (unsigned int k = 0; k < dim; ++k)
          out[o++] = -2. * c * f * in[hessian(k, a)];
        out[o++] = -c * (f * in[1 + dim + n_hessian + a] - sf * grad_a);
      }
  }


  template <int dim>
  void
  HydrodynamicBendingEnergy<dim>::declare(TermDeclaration<dim> &d)
  {
    value     = d.value(phi, Derivative<dim>::value);
    laplacian = d.value(phi, Derivative<dim>::laplacian);
  }


  template <int dim>
  void
  HydrodynamicBendingEnergy<dim>::integrate(const QuadratureInputs<dim> &in,
                                            const double                *JxW,
                                            double *sums) const
  {
    const double eps = coefficients.epsilon;
    const double c   = coefficients.bending_factor() / (2 * eps);
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        const double f
          = membrane::chemical_potential(in[value][q], in[laplacian][q], eps);
        sums[0] += c * f * f * JxW[q];
      }
  }

  template struct HydrodynamicBendingFormula<2>;
  template struct HydrodynamicBendingFormula<3>;
  template class PointwiseTerm<2, HydrodynamicBendingFormula<2>>;
  template class PointwiseTerm<3, HydrodynamicBendingFormula<3>>;
  template class HydrodynamicBendingEnergy<2>;
  template class HydrodynamicBendingEnergy<3>;
} // namespace vesicle_iga
