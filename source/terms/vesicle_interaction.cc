// Short-range interaction of two vesicles, (H8)-(H11), spec 4.4.

#include <vesicle_iga/terms/vesicle_interaction.h>

namespace vesicle_iga
{
  template <int dim>
  VesicleInteractionFormula<dim>::VesicleInteractionFormula(
    const unsigned int          velocity,
    const unsigned int          phi_i,
    const unsigned int          phi_j,
    const MembraneCoefficients &coefficients)
    : eps(coefficients.epsilon)
    , eta(coefficients.mobility)
    , k(coefficients.interaction_factor())
  {
    using D = Derivative<dim>;
    inputs.push_back({phi_i, D::value});
    inputs.push_back({phi_j, D::value});
    for (unsigned int a = 0; a < dim; ++a)
      inputs.push_back({phi_i, D::gradient(a)});
    for (unsigned int a = 0; a < dim; ++a)
      inputs.push_back({phi_j, D::gradient(a)});
    outputs.push_back({phi_i, D::value});
    outputs.push_back({phi_j, D::value});
    for (unsigned int a = 0; a < dim; ++a)
      outputs.push_back({velocity + a, D::value});
  }

  template struct VesicleInteractionFormula<2>;
  template struct VesicleInteractionFormula<3>;
  template class PointwiseTerm<2, VesicleInteractionFormula<2>>;
  template class PointwiseTerm<3, VesicleInteractionFormula<3>>;
  template class InteractionEnergy<2>;
  template class InteractionEnergy<3>;
} // namespace vesicle_iga
