#include <vesicle_iga/assembly/assembler.h>
#include <vesicle_iga/physics/phase_field_operator.h>

namespace vesicle_iga
{
  template <int dim>
  PhaseFieldOperator<dim>::PhaseFieldOperator(
    const SplineDofHandler<dim>                    &dofs,
    const std::vector<const PhaseFieldTerm<dim> *> &terms)
    : dofs(dofs)
    , terms(terms)
  {}


  template <int dim>
  void
  PhaseFieldOperator<dim>::set_state(const TrilinosWrappers::MPI::Vector &p,
                                     const TrilinosWrappers::MPI::Vector &pd,
                                     const double                         m,
                                     const double                         s,
                                     const bool                           with)
  {
    phi              = &p;
    phi_dot          = &pd;
    mass_factor      = m;
    stiffness_factor = s;
    with_matrix      = with;
  }


  template <int dim>
  PhaseFieldPoint<dim>
  PhaseFieldOperator<dim>::point(const SplineCellValues<dim> &v,
                                 const unsigned int           q,
                                 const std::vector<double>   &c)
  {
    PhaseFieldPoint<dim> p{0., Tensor<1, dim>(), 0.};
    for (unsigned int j = 0; j < v.n_basis_per_element(); ++j)
      {
        p.phi += c[j] * v.shape_value(j, q);
        p.grad_phi += c[j] * v.shape_grad(j, q);
        p.laplacian_phi += c[j] * v.shape_laplacian(j, q);
      }
    return p;
  }


  template <int dim>
  void
  PhaseFieldOperator<dim>::assemble_cell(const SplineCellValues<dim> &v,
                                         FullMatrix<double>          &A,
                                         Vector<double>              &b) const
  {
    using F                             = PointForm<dim>;
    constexpr unsigned int           nf = F::n_features;
    const unsigned int               n  = v.n_basis_per_element();
    std::vector<std::vector<double>> c, cd;
    get_element_coefficients(dofs, *phi, v.element(), c);
    get_element_coefficients(dofs, *phi_dot, v.element(), cd);

    std::vector<std::array<double, nf>> f(n), t(n);
    for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
      {
        const PhaseFieldPoint<dim> p       = point(v, q, c[0]);
        const double               phi_dot = v.value(cd[0], q);
        F                          form;
        for (const auto *term : terms)
          term->add_variation(p, form);
        const double JxW = v.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          {
            f[i][F::value] = v.shape_value(i, q);
            for (unsigned int d = 0; d < dim; ++d)
              f[i][F::gradient(d)] = v.shape_grad(i, q)[d];
            f[i][F::laplacian] = v.shape_laplacian(i, q);
            double r           = phi_dot * f[i][F::value];
            for (unsigned int k = 0; k < nf; ++k)
              r += form.r[k] * f[i][k];
            b(i) -= r * JxW;
          }
        if (!with_matrix)
          continue;
        // t_j = (s K + alpha_m e_0 e_0^T) f_j, then A_ij += f_i . t_j.
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int k = 0; k < nf; ++k)
            {
              double s = 0;
              for (unsigned int l = 0; l < nf; ++l)
                s += form.K[k][l] * f[j][l];
              t[j][k] = stiffness_factor * s * JxW;
            }
        for (unsigned int j = 0; j < n; ++j)
          t[j][F::value] += mass_factor * f[j][F::value] * JxW;
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              double s = 0;
              for (unsigned int k = 0; k < nf; ++k)
                s += f[i][k] * t[j][k];
              A(i, j) += s;
            }
      }
  }

  template class PhaseFieldOperator<2>;
  template class PhaseFieldOperator<3>;
} // namespace vesicle_iga
