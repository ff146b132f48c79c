#include <vesicle_iga/assembly/dirichlet_constraints.h>

namespace vesicle_iga
{
  namespace
  {
    /**
     * Greville interpolant on face f of the scalar function @p value(x, xi)
     * (x physical, xi parametric), as coefficients of the face's trace
     * functions, indexed by the natural index of the volume basis function
     * of layer 0. Also returns the physical face Greville point of each.
     */
    template <int dim>
    void
    interpolate_on_face(const SplineSpace<dim>                   &space,
                        std::shared_ptr<const NurbsGeometry<dim>> geometry,
                        const unsigned int                        face,
                        const std::function<double(const Point<dim> &,
                                                   const Point<dim> &)> &value,
                        std::vector<unsigned int>                       &basis,
                        std::vector<double>     &coefficients,
                        std::vector<Point<dim>> &greville_x)
    {
      const unsigned int                d = face / 2;
      std::array<KnotVector, dim - 1>   other;
      std::array<unsigned int, dim - 1> dirs;
      for (unsigned int k = 0, j = 0; k < dim; ++k)
        if (k != d)
          {
            other[j]  = space.knot_vector(k);
            dirs[j++] = k;
          }
      const SplineSpace<dim - 1> trace(other);
      const double               xi_d = (face % 2) ?
                                          space.knot_vector(d).breakpoints().back() :
                                          space.knot_vector(d).breakpoints().front();
      const unsigned int         layer_index
        = (face % 2) ? space.knot_vector(d).n_basis() - 1 : 0;

      std::vector<double> values(trace.n_basis());
      basis.resize(trace.n_basis());
      greville_x.resize(trace.n_basis());
      std::vector<double> w;
      for (unsigned int i = 0; i < trace.n_basis(); ++i)
        {
          const Point<dim - 1>          g = trace.greville_point(i);
          const auto                    m = trace.basis_multi_index(i);
          Point<dim>                    xi;
          std::array<unsigned int, dim> bm;
          xi[d] = xi_d;
          bm[d] = layer_index;
          for (unsigned int j = 0; j < dim - 1; ++j)
            {
              xi[dirs[j]] = g[j];
              bm[dirs[j]] = m[j];
            }
          basis[i]          = space.basis_index(bm);
          double     weight = 1.;
          Point<dim> x      = xi;
          if (geometry)
            {
              x = geometry->point(xi);
              space.evaluate(geometry->weights(), 1, xi, w);
              weight = w[0];
            }
          greville_x[i] = x;
          values[i]     = value(x, xi) * weight;
        }
      coefficients = interpolate_at_greville_points(trace, values, 1);
      if (geometry)
        for (unsigned int i = 0; i < trace.n_basis(); ++i)
          coefficients[i] /= geometry->weight(basis[i]);
    }
  } // namespace


  template <int dim>
  void
  add_strong_dirichlet_constraints(
    const SplineDofHandler<dim>              &dof_handler,
    std::shared_ptr<const NurbsGeometry<dim>> geometry,
    const BoundarySelection<dim>             &selection,
    const Function<dim>                      &g,
    const std::vector<bool>                  &components,
    AffineConstraints<double>                &constraints)
  {
    const SplineSpace<dim> &space    = dof_handler.get_space();
    const IndexSet         &relevant = dof_handler.locally_relevant_dofs();
    for (unsigned int f = 0; f < 2 * dim; ++f)
      {
        if (!selection.touches_face(f)
            || space.knot_vector(f / 2).is_periodic())
          continue;
        for (unsigned int c = 0; c < dof_handler.n_components(); ++c)
          {
            if (!components[c])
              continue;
            std::vector<unsigned int> basis;
            std::vector<double>       coefficients;
            std::vector<Point<dim>>   x;
            interpolate_on_face<dim>(
              space,
              geometry,
              f,
              [&](const Point<dim> &p, const Point<dim> &) {
                return g.value(p, c);
              },
              basis,
              coefficients,
              x);
            for (unsigned int i = 0; i < basis.size(); ++i)
              {
                const auto dof = dof_handler.dof_index(basis[i], c);
                if (selection.contains(f, x[i]) && relevant.is_element(dof)
                    && !constraints.is_constrained(dof))
                  {
                    constraints.add_line(dof);
                    constraints.set_inhomogeneity(dof, coefficients[i]);
                  }
              }
          }
      }
  }


  template <int dim>
  void
  add_clamped_constraints(
    const SplineDofHandler<dim>  &dof_handler,
    const BoundarySelection<dim> &selection,
    const Function<dim>          &g,
    const std::function<double(const Point<dim> &, const Tensor<1, dim> &)> &gn,
    AffineConstraints<double> &constraints)
  {
    const SplineSpace<dim> &space = dof_handler.get_space();
    add_strong_dirichlet_constraints<dim>(
      dof_handler, nullptr, selection, g, {true}, constraints);
    const IndexSet &relevant = dof_handler.locally_relevant_dofs();
    for (unsigned int f = 0; f < 2 * dim; ++f)
      {
        const unsigned int d = f / 2;
        if (!selection.touches_face(f) || space.knot_vector(d).is_periodic())
          continue;
        const KnotVector  &kv = space.knot_vector(d);
        const auto        &t  = kv.knots();
        const unsigned int p = kv.degree(), n = kv.n_basis();
        const double delta = (f % 2) ? t.back() - t[n - 1] : t[p + 1] - t[0];
        std::vector<unsigned int> basis;
        std::vector<double>       c0, cn;
        std::vector<Point<dim>>   x;
        interpolate_on_face<dim>(
          space,
          nullptr,
          f,
          [&](const Point<dim> &p_, const Point<dim> &) { return g.value(p_); },
          basis,
          c0,
          x);
        interpolate_on_face<dim>(
          space,
          nullptr,
          f,
          [&](const Point<dim> &p_, const Point<dim> &) {
            Tensor<1, dim> n;
            n[d] = (f % 2) ? 1. : -1.;
            return gn(p_, n);
          },
          basis,
          cn,
          x);
        for (unsigned int i = 0; i < basis.size(); ++i)
          {
            auto m         = space.basis_multi_index(basis[i]);
            m[d]           = (f % 2) ? n - 2 : 1;
            const auto dof = dof_handler.dof_index(space.basis_index(m));
            if (selection.contains(f, x[i]) && relevant.is_element(dof)
                && !constraints.is_constrained(dof))
              {
                constraints.add_line(dof);
                constraints.set_inhomogeneity(dof, c0[i] - delta / p * cn[i]);
              }
          }
      }
  }

#define INSTANTIATE(dim)                                                       \
  template void add_strong_dirichlet_constraints(                              \
    const SplineDofHandler<dim> &,                                             \
    std::shared_ptr<const NurbsGeometry<dim>>,                                 \
    const BoundarySelection<dim> &,                                            \
    const Function<dim> &,                                                     \
    const std::vector<bool> &,                                                 \
    AffineConstraints<double> &);                                              \
  template void add_clamped_constraints(                                       \
    const SplineDofHandler<dim> &,                                             \
    const BoundarySelection<dim> &,                                            \
    const Function<dim> &,                                                     \
    const std::function<double(const Point<dim> &, const Tensor<1, dim> &)> &, \
    AffineConstraints<double> &);
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace vesicle_iga
