#include <vesicle_iga/kernel/term.h>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  InputHandle
  TermDeclaration<dim>::input(const FieldInput &in)
  {
    for (unsigned int i = 0; i < inputs.size(); ++i)
      if (inputs[i] == in)
        return {i};
    inputs.push_back(in);
    return {static_cast<unsigned int>(inputs.size() - 1)};
  }


  template <int dim>
  ResidualHandle
  TermDeclaration<dim>::residual(const unsigned int component,
                                 const unsigned int derivative)
  {
    for (unsigned int i = 0; i < residuals.size(); ++i)
      if (residuals[i].component == component
          && residuals[i].derivative == derivative)
        return {i};
    residuals.push_back({component, derivative});
    return {static_cast<unsigned int>(residuals.size() - 1)};
  }


  template <int dim>
  JacobianHandle
  TermDeclaration<dim>::jacobian(const unsigned int test_component,
                                 const unsigned int test_derivative,
                                 const unsigned int trial_component,
                                 const unsigned int trial_derivative,
                                 const FieldSource  trial_source)
  {
    for (unsigned int i = 0; i < jacobians.size(); ++i)
      {
        const auto &j = jacobians[i];
        if (j.test_component == test_component
            && j.test_derivative == test_derivative
            && j.trial_component == trial_component
            && j.trial_derivative == trial_derivative
            && j.trial_source == trial_source)
          return {i};
      }
    jacobians.push_back({test_component,
                         test_derivative,
                         trial_component,
                         trial_derivative,
                         trial_source});
    return {static_cast<unsigned int>(jacobians.size() - 1)};
  }

  template class TermDeclaration<2>;
  template class TermDeclaration<3>;
} // namespace vesicle_iga
