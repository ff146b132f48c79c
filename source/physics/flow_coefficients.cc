#include <vesicle_iga/physics/flow_coefficients.h>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  void
  FormulaViscosity<dim>::evaluate(const QuadratureInputs<dim> &in,
                                  std::vector<double>         &values,
                                  std::vector<Tensor<1, dim>> &gradients) const
  {
    values.resize(in.size());
    gradients.resize(in.size());
    for (unsigned int q = 0; q < in.size(); ++q)
      {
        values[q] = mu->value(in.point(q));
        // Central differences of the formula, exact to O(d^2) for smooth
        // fields.
        const double d = 1e-6;
        for (unsigned int k = 0; k < dim; ++k)
          {
            Point<dim> xp = in.point(q), xm = in.point(q);
            xp[k] += d;
            xm[k] -= d;
            gradients[q][k] = (mu->value(xp) - mu->value(xm)) / (2 * d);
          }
      }
  }


  template <int dim>
  void
  BodyForce<dim>::evaluate(const QuadratureInputs<dim> &in,
                           std::vector<Tensor<1, dim>> &f) const
  {
    f.assign(in.size(), Tensor<1, dim>());
    if (!force)
      return;
    for (unsigned int q = 0; q < in.size(); ++q)
      for (unsigned int a = 0; a < dim; ++a)
        f[q][a] = force->value(in.point(q), a);
  }

  template class FormulaViscosity<2>;
  template class FormulaViscosity<3>;
  template class BodyForce<2>;
  template class BodyForce<3>;
} // namespace vesicle_iga
