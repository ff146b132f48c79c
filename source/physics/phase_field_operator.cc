#include <deal.II/base/mpi.h>

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
    PhaseFieldPoint<dim> p;
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
  PhaseFieldOperator<dim>::evaluate_points(
    const SumFactorization<dim>       &kernel,
    const std::vector<double>         &c,
    const std::vector<double>         &c_psi,
    std::vector<PhaseFieldPoint<dim>> &points)
  {
    using SF = SumFactorization<dim>;
    typename SF::AtomValues       u, v;
    std::array<bool, SF::n_atoms> all, gradients{};
    all.fill(true);
    kernel.evaluate(c, all, u);
    if (!c_psi.empty())
      {
        for (unsigned int d = 0; d < dim; ++d)
          gradients[SF::gradient_atom(d)] = true;
        kernel.evaluate(c_psi, gradients, v);
      }
    points.resize(kernel.n_quadrature_points());
    for (unsigned int q = 0; q < points.size(); ++q)
      {
        auto &p         = points[q];
        p.phi           = u[SF::value_atom][q];
        p.laplacian_phi = 0;
        for (unsigned int d = 0; d < dim; ++d)
          {
            p.grad_phi[d] = u[SF::gradient_atom(d)][q];
            p.laplacian_phi += u[SF::second_derivative_atom(d)][q];
            p.grad_psi[d] = c_psi.empty() ? 0. : v[SF::gradient_atom(d)][q];
          }
      }
  }


  template <int dim>
  void
  PhaseFieldOperator<dim>::assemble_cell(const SplineCellValues<dim> &v,
                                         FullMatrix<double>          &A,
                                         Vector<double>              &b) const
  {
    // Sum factorisation (doc/splines.md): the point forms r, K of the
    // energy terms, given on the features [w, grad w, Delta w], are
    // rewritten on the separable atoms [w, d_x w, .., d_xx w, ..] (the
    // Laplacian feature is the sum of the dim second-derivative atoms),
    // and the element integrals are contracted direction by direction.
    using F                   = PointForm<dim>;
    using SF                  = SumFactorization<dim>;
    constexpr unsigned int nf = F::n_features, na = SF::n_atoms;
    const SF               kernel(v.tensor_product_factors());
    const unsigned int     nq = kernel.n_quadrature_points();

    std::vector<std::vector<double>> c, cd, cp(1);
    get_element_coefficients(dofs, *phi, v.element(), c);
    get_element_coefficients(dofs, *phi_dot, v.element(), cd);
    if (psi)
      get_element_coefficients(dofs, *psi, v.element(), cp);
    std::vector<PhaseFieldPoint<dim>> points;
    evaluate_points(kernel, c[0], cp[0], points);
    typename SF::AtomValues rate;
    std::array<bool, na>    value_only{};
    value_only[SF::value_atom] = true;
    kernel.evaluate(cd[0], value_only, rate);

    // The feature of each atom.
    std::array<unsigned int, na> feature;
    feature[SF::value_atom] = F::value;
    for (unsigned int d = 0; d < dim; ++d)
      {
        feature[SF::gradient_atom(d)]          = F::gradient(d);
        feature[SF::second_derivative_atom(d)] = F::laplacian;
      }

    typename SF::AtomValues residual;
    for (auto &r : residual)
      r.assign(nq, 0.);
    // Tangent coefficients per feature pair; which pairs are non-zero.
    std::vector<Tensor<2, nf>>           K(with_matrix ? nq : 0);
    std::array<std::array<bool, nf>, nf> active{};
    for (unsigned int q = 0; q < nq; ++q)
      {
        F form;
        for (const auto *term : terms)
          term->add_variation(points[q], form);
        const double JxW = kernel.JxW(q);
        residual[SF::value_atom][q]
          = (rate[SF::value_atom][q] + form.r[F::value]) * JxW;
        for (unsigned int d = 0; d < dim; ++d)
          {
            residual[SF::gradient_atom(d)][q] = form.r[F::gradient(d)] * JxW;
            residual[SF::second_derivative_atom(d)][q]
              = form.r[F::laplacian] * JxW;
          }
        if (!with_matrix)
          continue;
        // (N4): K = alpha_m M + alpha_f gamma dt DR.
        K[q] = stiffness_factor * JxW * form.K;
        K[q][F::value][F::value] += mass_factor * JxW;
        for (unsigned int k = 0; k < nf; ++k)
          for (unsigned int l = 0; l < nf; ++l)
            active[k][l] = active[k][l] || K[q][k][l] != 0.;
      }
    std::array<bool, na> all;
    all.fill(true);
    Vector<double> R(b.size());
    kernel.integrate(residual, all, R);
    b -= R;

    if (!with_matrix)
      return;
    std::vector<typename SF::AtomPair> pairs;
    pairs.reserve(na * na);
    for (unsigned int a = 0; a < na; ++a)
      for (unsigned int bb = 0; bb < na; ++bb)
        {
          const unsigned int k = feature[a], l = feature[bb];
          if (!active[k][l])
            continue;
          typename SF::AtomPair pair{a, bb, std::vector<double>(nq)};
          for (unsigned int q = 0; q < nq; ++q)
            pair.coefficient[q] = K[q][k][l];
          pairs.push_back(std::move(pair));
        }
    std::vector<const typename SF::AtomPair *> pointers;
    for (const auto &p : pairs)
      pointers.push_back(&p);
    // The tangent of an energy is symmetric (bending, area); the
    // flexoelectric one (E20) is not.
    bool symmetric = true;
    for (unsigned int q = 0; q < nq && symmetric; ++q)
      for (unsigned int k = 0; k < nf && symmetric; ++k)
        for (unsigned int l = k + 1; l < nf; ++l)
          if (K[q][k][l] != K[q][l][k])
            {
              symmetric = false;
              break;
            }
    kernel.integrate_matrix(pointers, A, symmetric);
  }


  template <int dim>
  std::vector<double>
  PhaseFieldOperator<dim>::integrate(
    const TrilinosWrappers::MPI::Vector              &ghosted_phi,
    const Quadrature<1>                              &quadrature_1d,
    const unsigned int                                n_sums,
    const std::function<void(const PhaseFieldPoint<dim> &,
                             const double,
                             std::vector<double> &)> &integrand) const
  {
    return integrate(&ghosted_phi,
                     nullptr,
                     quadrature_1d,
                     n_sums,
                     [&](const PhaseFieldPoint<dim> &p,
                         const PhaseFieldPoint<dim> &,
                         const double         JxW,
                         std::vector<double> &sums) {
                       integrand(p, JxW, sums);
                     });
  }


  template <int dim>
  std::vector<double>
  PhaseFieldOperator<dim>::integrate(
    const TrilinosWrappers::MPI::Vector              *ghosted_phi,
    const TrilinosWrappers::MPI::Vector              *ghosted_other,
    const Quadrature<1>                              &quadrature_1d,
    const unsigned int                                n_sums,
    const std::function<void(const PhaseFieldPoint<dim> &,
                             const PhaseFieldPoint<dim> &,
                             const double,
                             std::vector<double> &)> &integrand) const
  {
    SplineCellValues<dim> values(
      dofs.get_space(), nullptr, quadrature_1d, derivative_order(), false);
    std::vector<double>               sums(n_sums, 0.);
    std::vector<std::vector<double>>  c, cp(1), co(1);
    std::vector<PhaseFieldPoint<dim>> points, other(1);
    for (const unsigned int e : dofs.get_mesh().locally_owned_elements())
      {
        values.reinit(e);
        const SumFactorization<dim> kernel(values.tensor_product_factors());
        get_element_coefficients(dofs, *ghosted_phi, e, c);
        if (psi)
          get_element_coefficients(dofs, *psi, e, cp);
        evaluate_points(kernel, c[0], cp[0], points);
        if (ghosted_other)
          {
            get_element_coefficients(dofs, *ghosted_other, e, co);
            evaluate_points(kernel, co[0], {}, other);
          }
        for (unsigned int q = 0; q < points.size(); ++q)
          integrand(points[q],
                    other[ghosted_other ? q : 0],
                    kernel.JxW(q),
                    sums);
      }
    Utilities::MPI::sum(sums, dofs.get_mesh().get_communicator(), sums);
    return sums;
  }


  template <int dim>
  std::vector<double>
  PhaseFieldOperator<dim>::integrate_terms(
    const std::vector<const PhaseFieldTerm<dim> *> &list,
    const TrilinosWrappers::MPI::Vector            &ghosted_phi,
    const Quadrature<1>                            &quadrature_1d) const
  {
    return integrate(ghosted_phi,
                     quadrature_1d,
                     list.size(),
                     [&](const PhaseFieldPoint<dim> &p,
                         const double                JxW,
                         std::vector<double>        &sums) {
                       for (unsigned int k = 0; k < list.size(); ++k)
                         sums[k] += list[k]->density(p) * JxW;
                     });
  }


  template class PhaseFieldOperator<2>;
  template class PhaseFieldOperator<3>;
} // namespace vesicle_iga
