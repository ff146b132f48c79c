#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/fields/dirichlet_constraints.h>

#include <algorithm>
#include <memory>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    /**
     * The trace functions of one direction of a face that do not vanish on
     * the parametric interval [lo, hi], and the inverse of their collocation
     * matrix at the Greville points of the space restricted to [lo, hi].
     * The B-splines that are non-zero on an interval, restricted to it, are
     * a basis of the restricted spline space, so this square collocation is
     * invertible; for the whole direction it is the usual Greville
     * interpolation (also for periodic directions).
     */
    struct TraceDirection
    {
      std::vector<unsigned int> functions;
      std::vector<double>       points;
      FullMatrix<double>        inverse;
    };

    TraceDirection
    make_trace_direction(const KnotVector  &kv,
                         const double       lo,
                         const double       hi,
                         const std::string &parameter)
    {
      TraceDirection r;
      const auto    &z     = kv.breakpoints();
      const double   tol   = 1e-10 * (z.back() - z.front());
      const bool     whole = lo <= z.front() + tol && hi >= z.back() - tol;
      std::unique_ptr<KnotVector> restricted;
      if (whole)
        {
          for (unsigned int i = 0; i < kv.n_basis(); ++i)
            r.functions.push_back(i);
          r.points = kv.greville_points();
        }
      else
        {
          // Strong conditions on a part of a face need the part to end at
          // breakpoints: an element cut by the end would have its whole
          // trace fixed, also where the condition does not hold.
          const auto snap = [&](const double x) {
            for (unsigned int i = 0; i < z.size(); ++i)
              if (std::abs(z[i] - x) <= tol)
                return i;
            throw InputError(parameter,
                             value_text(x),
                             "coordinate ranges of strongly imposed "
                             "conditions that start and end at breakpoints "
                             "of the mesh (or beyond the face)");
          };
          const unsigned int first = lo <= z.front() + tol ? 0 : snap(lo);
          const unsigned int last
            = hi >= z.back() - tol ? z.size() - 1 : snap(hi);
          std::vector<double> zr(z.begin() + first, z.begin() + last + 1);
          std::vector<int>    kr;
          for (unsigned int i = first + 1; i < last; ++i)
            kr.push_back(kv.interior_continuity()[i - 1]);
          for (unsigned int e = first; e < last; ++e)
            for (unsigned int j = 0; j <= kv.degree(); ++j)
              {
                const unsigned int g = kv.global_index(e, j);
                if (std::find(r.functions.begin(), r.functions.end(), g)
                    == r.functions.end())
                  r.functions.push_back(g);
              }
          r.points = KnotVector(kv.degree(), zr, kr).greville_points();
        }
      const unsigned int n = r.functions.size();
      AssertThrow(r.points.size() == n, ExcInternalError());
      FullMatrix<double> A(n, n);
      for (unsigned int q = 0; q < n; ++q)
        {
          const unsigned int e = kv.find_element(r.points[q]);
          const auto         v = kv.evaluate_on_element(e, r.points[q], 0)[0];
          for (unsigned int j = 0; j <= kv.degree(); ++j)
            {
              const auto it = std::find(r.functions.begin(),
                                        r.functions.end(),
                                        kv.global_index(e, j));
              if (it != r.functions.end())
                A(q, it - r.functions.begin()) += v[j];
            }
        }
      A.gauss_jordan();
      r.inverse = A;
      return r;
    }


    /**
     * Coefficients of the layer-0 functions of face f whose trace does not
     * vanish on the piece (whole face, or the part cut by coordinate
     * ranges), such that the trace equals the Greville interpolant of
     * @p value on the piece (of value * W on a NURBS patch). Returns the
     * natural indices of those functions and their coefficients.
     */
    template <int dim>
    void
    interpolate_on_face_piece(
      const SplineSpace<dim>                                    &space,
      std::shared_ptr<const NurbsGeometry<dim>>                  geometry,
      const unsigned int                                         face,
      const std::vector<typename BoundarySelection<dim>::Range> &ranges,
      const std::string                                         &parameter,
      const std::function<double(const Point<dim> &)>           &value,
      std::vector<unsigned int>                                 &basis,
      std::vector<double>                                       &coefficients)
    {
      basis.clear();
      coefficients.clear();
      const unsigned int d    = face / 2;
      const KnotVector  &kv_d = space.knot_vector(d);
      const double       xi_d
        = (face % 2) ? kv_d.breakpoints().back() : kv_d.breakpoints().front();
      check_input(ranges.empty() || !geometry,
                  parameter,
                  "coordinate ranges",
                  "whole faces on NURBS patches (ranges are physical "
                  "coordinates, which are not parametric ones there)");

      std::array<double, dim> lo, hi;
      for (unsigned int k = 0; k < dim; ++k)
        {
          lo[k] = space.knot_vector(k).breakpoints().front();
          hi[k] = space.knot_vector(k).breakpoints().back();
        }
      for (const auto &r : ranges)
        {
          if (r.coordinate == d)
            {
              if (xi_d < r.min - 1e-12 || xi_d > r.max + 1e-12)
                return; // the piece does not reach this face
              continue;
            }
          lo[r.coordinate] = std::max(lo[r.coordinate], r.min);
          hi[r.coordinate] = std::min(hi[r.coordinate], r.max);
          if (lo[r.coordinate] >= hi[r.coordinate])
            return; // empty piece
        }

      std::vector<unsigned int>   dirs;
      std::vector<TraceDirection> trace;
      for (unsigned int k = 0; k < dim; ++k)
        if (k != d)
          {
            dirs.push_back(k);
            trace.push_back(make_trace_direction(
              space.knot_vector(k), lo[k], hi[k], parameter));
          }

      // Values at the tensor grid of points (first trace direction fastest).
      unsigned int n = 1;
      for (const auto &t : trace)
        n *= t.functions.size();
      std::vector<double> c(n);
      std::vector<double> w;
      for (unsigned int i = 0; i < n; ++i)
        {
          Point<dim>   xi;
          unsigned int r = i;
          xi[d]          = xi_d;
          for (unsigned int j = 0; j < trace.size(); ++j)
            {
              xi[dirs[j]] = trace[j].points[r % trace[j].functions.size()];
              r /= trace[j].functions.size();
            }
          if (geometry)
            {
              space.evaluate(geometry->weights(), 1, xi, w);
              c[i] = value(geometry->point(xi)) * w[0];
            }
          else
            c[i] = value(xi);
        }
      // Apply the inverse collocation matrices direction by direction.
      unsigned int stride = 1;
      for (const auto &t : trace)
        {
          const unsigned int m = t.functions.size();
          Vector<double>     in(m), out(m);
          for (unsigned int line = 0; line < n / m; ++line)
            {
              const unsigned int a = line % stride, b = line / stride;
              for (unsigned int q = 0; q < m; ++q)
                in[q] = c[a + stride * (q + m * b)];
              t.inverse.vmult(out, in);
              for (unsigned int q = 0; q < m; ++q)
                c[a + stride * (q + m * b)] = out[q];
            }
          stride *= m;
        }
      const unsigned int layer = (face % 2) ? kv_d.n_basis() - 1 : 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          std::array<unsigned int, dim> bm;
          bm[d]          = layer;
          unsigned int r = i;
          for (unsigned int j = 0; j < trace.size(); ++j)
            {
              bm[dirs[j]] = trace[j].functions[r % trace[j].functions.size()];
              r /= trace[j].functions.size();
            }
          basis.push_back(space.basis_index(bm));
          coefficients.push_back(
            geometry ? c[i] / geometry->weight(basis.back()) : c[i]);
        }
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
        if (space.knot_vector(f / 2).is_periodic())
          continue;
        for (const auto &piece : selection.pieces_on_face(f))
          // Components beyond the mask (fields a model coupled to this
          // one, e.g. the vesicles of the flow) are not constrained.
          for (unsigned int c = 0;
               c < std::min<std::size_t>(dof_handler.n_components(),
                                         components.size());
               ++c)
            {
              if (!components[c])
                continue;
              std::vector<unsigned int> basis;
              std::vector<double>       coefficients;
              interpolate_on_face_piece<dim>(
                space,
                geometry,
                f,
                piece,
                selection.parameter_name(),
                [&](const Point<dim> &x) { return g.value(x, c); },
                basis,
                coefficients);
              for (unsigned int i = 0; i < basis.size(); ++i)
                {
                  const auto dof = dof_handler.dof_index(basis[i], c);
                  if (relevant.is_element(dof)
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
        if (space.knot_vector(d).is_periodic())
          continue;
        const KnotVector  &kv = space.knot_vector(d);
        const auto        &t  = kv.knots();
        const unsigned int p = kv.degree(), n = kv.n_basis();
        const double   delta = (f % 2) ? t.back() - t[n - 1] : t[p + 1] - t[0];
        Tensor<1, dim> normal;
        normal[d] = (f % 2) ? 1. : -1.;
        for (const auto &piece : selection.pieces_on_face(f))
          {
            std::vector<unsigned int> basis;
            std::vector<double>       c0, cn;
            interpolate_on_face_piece<dim>(
              space,
              nullptr,
              f,
              piece,
              selection.parameter_name(),
              [&](const Point<dim> &x) { return g.value(x); },
              basis,
              c0);
            interpolate_on_face_piece<dim>(
              space,
              nullptr,
              f,
              piece,
              selection.parameter_name(),
              [&](const Point<dim> &x) { return gn(x, normal); },
              basis,
              cn);
            for (unsigned int i = 0; i < basis.size(); ++i)
              {
                auto m         = space.basis_multi_index(basis[i]);
                m[d]           = (f % 2) ? n - 2 : 1;
                const auto dof = dof_handler.dof_index(space.basis_index(m));
                if (relevant.is_element(dof)
                    && !constraints.is_constrained(dof))
                  {
                    constraints.add_line(dof);
                    constraints.set_inhomogeneity(dof,
                                                  c0[i] - delta / p * cn[i]);
                  }
              }
          }
      }
  }


  template <int dim>
  void
  add_zero_normal_derivative_constraints(
    const SplineDofHandler<dim> &dof_handler,
    const std::vector<bool>     &components,
    AffineConstraints<double>   &constraints)
  {
    AssertDimension(components.size(), dof_handler.n_components());
    const IndexSet &relevant = dof_handler.locally_relevant_dofs();
    for (unsigned int k = 0; k < components.size(); ++k)
      {
        if (!components[k])
          continue;
        const SplineSpace<dim> &space = dof_handler.component_space(k);
        for (unsigned int d = 0; d < dim; ++d)
          AssertThrow(space.knot_vector(d).is_periodic()
                        || space.knot_vector(d).n_basis() >= 3,
                      ExcMessage("du/dn = 0 needs 3 or more basis functions "
                                 "in every non-periodic direction."));
        for (unsigned int b = 0; b < space.n_basis(); ++b)
          {
            const auto m   = space.basis_multi_index(b);
            auto       rep = m;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const KnotVector &kv = space.knot_vector(d);
                if (kv.is_periodic())
                  continue;
                if (m[d] == 0)
                  rep[d] = 1;
                else if (m[d] == kv.n_basis() - 1)
                  rep[d] = kv.n_basis() - 2;
              }
            if (rep == m)
              continue;
            const auto dof = dof_handler.dof_index(b, k);
            if (!relevant.is_element(dof) || constraints.is_constrained(dof))
              continue;
            constraints.add_line(dof);
            constraints.add_entry(
              dof, dof_handler.dof_index(space.basis_index(rep), k), 1.);
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
    AffineConstraints<double> &);                                              \
  template void add_zero_normal_derivative_constraints(                        \
    const SplineDofHandler<dim> &,                                             \
    const std::vector<bool> &,                                                 \
    AffineConstraints<double> &);
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace vesicle_iga
