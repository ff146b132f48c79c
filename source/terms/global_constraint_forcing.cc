// Global area and volume multipliers of a vesicle in the flow: the
// lambda_g, lambda_v parts of (H1)/(H16) and of the forcing of (H14).

#include <vesicle_iga/terms/global_constraint_forcing.h>

namespace vesicle_iga
{
  template <int dim>
  GlobalConstraintForcingFormula<dim>::GlobalConstraintForcingFormula(
    const unsigned int          velocity,
    const unsigned int          phi,
    const MembraneCoefficients &coefficients)
    : eps(coefficients.epsilon)
    , eta(coefficients.mobility)
    , local(coefficients.local_volume_multiplier())
  {
    using D = Derivative<dim>;
    inputs.push_back({phi, D::value});
    for (unsigned int a = 0; a < dim; ++a)
      inputs.push_back({phi, D::gradient(a)});
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = a; b < dim; ++b)
        inputs.push_back({phi, D::hessian(a, b)});
    outputs.push_back({phi, D::value});
    for (unsigned int a = 0; a < dim; ++a)
      outputs.push_back({phi, D::gradient(a)});
    for (unsigned int a = 0; a < dim; ++a)
      outputs.push_back({velocity + a, D::value});
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int k = 0; k < dim; ++k)
        outputs.push_back({velocity + a, D::gradient(k)});
  }

  template struct GlobalConstraintForcingFormula<2>;
  template struct GlobalConstraintForcingFormula<3>;
  template class PointwiseTerm<2, GlobalConstraintForcingFormula<2>>;
  template class PointwiseTerm<3, GlobalConstraintForcingFormula<3>>;
} // namespace vesicle_iga
