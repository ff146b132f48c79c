// Transport of a phase field by the flow, first line of (H16).

#include <vesicle_iga/terms/phase_field_advection.h>

namespace vesicle_iga
{
  template <int dim>
  PhaseFieldAdvectionFormula<dim>::PhaseFieldAdvectionFormula(
    const unsigned int velocity,
    const unsigned int phi)
  {
    using D = Derivative<dim>;
    inputs.push_back({phi, D::value, FieldSource::rate});
    for (unsigned int a = 0; a < dim; ++a)
      inputs.push_back({velocity + a, D::value});
    for (unsigned int a = 0; a < dim; ++a)
      inputs.push_back({phi, D::gradient(a)});
    outputs.push_back({phi, D::value});
  }

  template struct PhaseFieldAdvectionFormula<2>;
  template struct PhaseFieldAdvectionFormula<3>;
  template class PointwiseTerm<2, PhaseFieldAdvectionFormula<2>>;
  template class PointwiseTerm<3, PhaseFieldAdvectionFormula<3>>;
} // namespace vesicle_iga
