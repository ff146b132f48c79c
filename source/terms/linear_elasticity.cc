#include <vesicle_iga/terms/linear_elasticity.h>

namespace vesicle_iga
{
  template <int dim>
  LinearElasticityTerm<dim>::LinearElasticityTerm(const double E,
                                                  const double nu,
                                                  const bool   plane_stress)
  {
    mu     = E / (2 * (1 + nu));
    lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    if (dim == 2 && plane_stress)
      lambda = 2 * lambda * mu / (lambda + 2 * mu); // = E nu / (1 - nu^2)
  }


  template <int dim>
  SymmetricTensor<2, dim>
  LinearElasticityTerm<dim>::stress(const SymmetricTensor<2, dim> &eps) const
  {
    return lambda * trace(eps) * unit_symmetric_tensor<dim>() + 2 * mu * eps;
  }


  template <int dim>
  void
  LinearElasticityTerm<dim>::assemble_cell(const SplineCellValues<dim> &v,
                                           FullMatrix<double>          &A,
                                           Vector<double> &) const
  {
    const unsigned int n = v.n_basis_per_element();
    for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
      {
        const double JxW = v.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          {
            const Tensor<1, dim> &gi = v.shape_grad(i, q);
            for (unsigned int j = 0; j < n; ++j)
              {
                const Tensor<1, dim> &gj = v.shape_grad(j, q);
                // Block (a, b) of the element matrix for components a, b:
                // lambda d_a v d_b u + mu (d_b v d_a u + delta_ab grad v.grad
                // u)
                const double gg = gi * gj;
                for (unsigned int a = 0; a < dim; ++a)
                  for (unsigned int c = 0; c < dim; ++c)
                    A(a * n + i, c * n + j)
                      += (lambda * gi[a] * gj[c] + mu * gi[c] * gj[a]
                          + (a == c ? mu * gg : 0.))
                         * JxW;
              }
          }
      }
  }


  template <int dim>
  void
  TractionTerm<dim>::assemble_face(const unsigned int           face,
                                   const SplineCellValues<dim> &v,
                                   FullMatrix<double> &,
                                   Vector<double> &b) const
  {
    const unsigned int n = v.n_basis_per_element();
    for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
      {
        if (!selection.contains(face, v.quadrature_point(q)))
          continue;
        const Tensor<1, dim> t
          = traction(v.quadrature_point(q), v.normal_vector(q));
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int i = 0; i < n; ++i)
            b(a * n + i) += v.shape_value(i, q) * t[a] * v.JxW(q);
      }
  }

  template class LinearElasticityTerm<2>;
  template class LinearElasticityTerm<3>;
  template class TractionTerm<2>;
  template class TractionTerm<3>;
} // namespace vesicle_iga
