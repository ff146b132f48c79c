#include <vesicle_iga/terms/biharmonic.h>

namespace vesicle_iga
{
  template <int dim>
  void
  BiharmonicTerm<dim>::assemble_cell(const SplineCellValues<dim> &v,
                                     FullMatrix<double>          &A,
                                     Vector<double>              &b) const
  {
    const unsigned int  n = v.n_basis_per_element();
    std::vector<double> lap(n);
    for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
      {
        const double JxW = v.JxW(q);
        const double fq  = f.value(v.quadrature_point(q));
        for (unsigned int i = 0; i < n; ++i)
          lap[i] = v.shape_laplacian(i, q);
        for (unsigned int i = 0; i < n; ++i)
          {
            for (unsigned int j = 0; j < n; ++j)
              A(i, j) += lap[i] * lap[j] * JxW;
            b(i) += v.shape_value(i, q) * fq * JxW;
          }
      }
  }


  template <int dim>
  void
  BoundaryLaplacianTerm<dim>::assemble_face(const unsigned int           face,
                                            const SplineCellValues<dim> &v,
                                            FullMatrix<double> &,
                                            Vector<double> &b) const
  {
    for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
      {
        if (!selection.contains(face, v.quadrature_point(q)))
          continue;
        const double mq = m.value(v.quadrature_point(q));
        for (unsigned int i = 0; i < v.n_basis_per_element(); ++i)
          b(i) += mq * (v.shape_grad(i, q) * v.normal_vector(q)) * v.JxW(q);
      }
  }

  template class BiharmonicTerm<2>;
  template class BiharmonicTerm<3>;
  template class BoundaryLaplacianTerm<2>;
  template class BoundaryLaplacianTerm<3>;
} // namespace vesicle_iga
