#include <vesicle_iga/terms/laplace.h>

namespace vesicle_iga
{
  template <int dim>
  void
  LaplaceTerm<dim>::assemble_cell(const SplineCellValues<dim> &v,
                                  FullMatrix<double>          &A,
                                  Vector<double>              &b) const
  {
    const unsigned int n = v.n_basis_per_element();
    for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
      {
        const double JxW = v.JxW(q);
        const double fq  = f.value(v.quadrature_point(q));
        for (unsigned int i = 0; i < n; ++i)
          {
            const Tensor<1, dim> &gi = v.shape_grad(i, q);
            for (unsigned int j = 0; j < n; ++j)
              A(i, j) += gi * v.shape_grad(j, q) * JxW;
            b(i) += v.shape_value(i, q) * fq * JxW;
          }
      }
  }


  template <int dim>
  void
  NitscheDirichletTerm<dim>::assemble_face(const unsigned int           face,
                                           const SplineCellValues<dim> &v,
                                           FullMatrix<double>          &A,
                                           Vector<double>              &b) const
  {
    const unsigned int n = v.n_basis_per_element();
    for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
      {
        if (!selection.contains(face, v.quadrature_point(q)))
          continue;
        const double          JxW   = v.JxW(q);
        const Tensor<1, dim> &nrm   = v.normal_vector(q);
        const double          gamma = penalty / v.normal_element_size(q);
        const double          gq    = g.value(v.quadrature_point(q));
        for (unsigned int i = 0; i < n; ++i)
          {
            const double vi  = v.shape_value(i, q);
            const double dvi = v.shape_grad(i, q) * nrm;
            for (unsigned int j = 0; j < n; ++j)
              {
                const double uj  = v.shape_value(j, q);
                const double duj = v.shape_grad(j, q) * nrm;
                A(i, j) += (-dvi * uj - vi * duj + gamma * vi * uj) * JxW;
              }
            b(i) += (-dvi + gamma * vi) * gq * JxW;
          }
      }
  }


  template <int dim>
  void
  NeumannTerm<dim>::assemble_face(const unsigned int           face,
                                  const SplineCellValues<dim> &v,
                                  FullMatrix<double> &,
                                  Vector<double> &b) const
  {
    for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
      {
        if (!where(face, v.quadrature_point(q)))
          continue;
        const double gN = flux(v.quadrature_point(q)) * v.normal_vector(q);
        for (unsigned int i = 0; i < v.n_basis_per_element(); ++i)
          b(i) += v.shape_value(i, q) * gN * v.JxW(q);
      }
  }

  template class LaplaceTerm<2>;
  template class LaplaceTerm<3>;
  template class NitscheDirichletTerm<2>;
  template class NitscheDirichletTerm<3>;
  template class NeumannTerm<2>;
  template class NeumannTerm<3>;
} // namespace vesicle_iga
