// Phase-dependent viscosity mu*(phi_bar), (H12a), beyond the outer fluid's.

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/terms/viscosity_contrast.h>

namespace vesicle_iga
{
  template <int dim>
  ViscosityContrastFormula<dim>::ViscosityContrastFormula(
    const unsigned int               velocity,
    const std::vector<unsigned int> &phases,
    const MembraneCoefficients      &coefficients)
    : n_phases(phases.size())
    , beta(coefficients.viscosity_ratio)
    , Re(coefficients.reynolds_number)
  {
    using D = Derivative<dim>;
    AssertThrow(phases.size() + dim * dim <= max_inputs,
                dealii::ExcMessage("viscosity contrast: at most "
                                   + std::to_string(max_inputs - dim * dim)
                                   + " vesicles"));
    for (const unsigned int phi : phases)
      inputs.push_back({phi, D::value});
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int k = 0; k < dim; ++k)
        inputs.push_back({velocity + a, D::gradient(k)});
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int k = 0; k < dim; ++k)
        outputs.push_back({velocity + a, D::gradient(k)});
  }

  template struct ViscosityContrastFormula<2>;
  template struct ViscosityContrastFormula<3>;
  template class PointwiseTerm<2, ViscosityContrastFormula<2>>;
  template class PointwiseTerm<3, ViscosityContrastFormula<3>>;
} // namespace vesicle_iga
