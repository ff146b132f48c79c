// Local inextensibility (H17) and the tension force of (H14).

#include <vesicle_iga/terms/local_inextensibility.h>

namespace vesicle_iga
{
  template <int dim>
  LocalInextensibilityFormula<dim>::LocalInextensibilityFormula(
    const unsigned int          velocity,
    const unsigned int          phi,
    const unsigned int          tension,
    const MembraneCoefficients &coefficients)
    : eps(coefficients.epsilon)
    , xi(coefficients.inextensibility_xi)
    , eta_n(1e-8 / coefficients.epsilon)
  {
    using D = Derivative<dim>;
    inputs.push_back({phi, D::value});
    for (unsigned int k = 0; k < dim; ++k)
      inputs.push_back({phi, D::gradient(k)});
    inputs.push_back({tension, D::value});
    for (unsigned int k = 0; k < dim; ++k)
      inputs.push_back({tension, D::gradient(k)});
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int k = 0; k < dim; ++k)
        inputs.push_back({velocity + a, D::gradient(k)});
    for (unsigned int k = 0; k < dim; ++k)
      outputs.push_back({tension, D::gradient(k)});
    outputs.push_back({tension, D::value});
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int k = 0; k < dim; ++k)
        outputs.push_back({velocity + a, D::gradient(k)});
  }

  template struct LocalInextensibilityFormula<2>;
  template struct LocalInextensibilityFormula<3>;
  template class PointwiseTerm<2, LocalInextensibilityFormula<2>>;
  template class PointwiseTerm<3, LocalInextensibilityFormula<3>>;
} // namespace vesicle_iga
