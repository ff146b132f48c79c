#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vesicle_iga/spline/spline_space.h>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    /**
     * The values at @p xi of the tensor-product basis functions that do
     * not vanish on the element with multi-index @p element, in the
     * element's local order (first direction fastest): the products of the
     * univariate values. Shared by SplineSpace::evaluate() and
     * SplineSpace::evaluate_on_element().
     */
    template <int dim>
    std::vector<double>
    element_basis_values(const std::array<KnotVector, dim>   &kv,
                         const std::array<unsigned int, dim> &element,
                         const Point<dim>                    &xi)
    {
      std::array<std::vector<double>, dim> v1d;
      unsigned int                         n = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          v1d[d] = kv[d].evaluate_on_element(element[d], xi[d], 0)[0];
          n *= v1d[d].size();
        }
      std::vector<double> N(n, 1.);
      for (unsigned int j = 0; j < n; ++j)
        {
          unsigned int r = j;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const unsigned int pd = v1d[d].size();
              N[j] *= v1d[d][r % pd];
              r /= pd;
            }
        }
      return N;
    }
  } // namespace

  template <int dim>
  SplineSpace<dim>::SplineSpace(const std::array<KnotVector, dim> &kvs)
    : kv(kvs)
    , n_functions(1)
    , n_elems(1)
    , n_per_element(1)
  {
    for (unsigned int d = 0; d < dim; ++d)
      {
        n_functions *= kv[d].n_basis();
        n_elems *= kv[d].n_elements();
        n_per_element *= kv[d].degree() + 1;
        greville[d] = kv[d].greville_points();
      }
  }


  template <int dim>
  std::array<unsigned int, dim>
  SplineSpace<dim>::element_multi_index(unsigned int e) const
  {
    std::array<unsigned int, dim> m;
    for (unsigned int d = 0; d < dim; ++d)
      {
        m[d] = e % kv[d].n_elements();
        e /= kv[d].n_elements();
      }
    return m;
  }


  template <int dim>
  unsigned int
  SplineSpace<dim>::element_index(const std::array<unsigned int, dim> &m) const
  {
    unsigned int e = 0;
    for (int d = dim - 1; d >= 0; --d)
      e = e * kv[d].n_elements() + m[d];
    return e;
  }


  template <int dim>
  std::array<unsigned int, dim>
  SplineSpace<dim>::basis_multi_index(unsigned int i) const
  {
    std::array<unsigned int, dim> m;
    for (unsigned int d = 0; d < dim; ++d)
      {
        m[d] = i % kv[d].n_basis();
        i /= kv[d].n_basis();
      }
    return m;
  }


  template <int dim>
  unsigned int
  SplineSpace<dim>::basis_index(const std::array<unsigned int, dim> &m) const
  {
    unsigned int i = 0;
    for (int d = dim - 1; d >= 0; --d)
      i = i * kv[d].n_basis() + m[d];
    return i;
  }


  template <int dim>
  void
  SplineSpace<dim>::element_basis_indices(
    const unsigned int         e,
    std::vector<unsigned int> &indices) const
  {
    const auto em = element_multi_index(e);
    indices.resize(n_per_element);
    for (unsigned int j = 0; j < n_per_element; ++j)
      {
        unsigned int                  r = j;
        std::array<unsigned int, dim> bm;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int pd = kv[d].degree() + 1;
            bm[d]                 = kv[d].global_index(em[d], r % pd);
            r /= pd;
          }
        indices[j] = basis_index(bm);
      }
  }


  template <int dim>
  Point<dim>
  SplineSpace<dim>::element_lower_corner(const unsigned int e) const
  {
    const auto em = element_multi_index(e);
    Point<dim> x;
    for (unsigned int d = 0; d < dim; ++d)
      x[d] = kv[d].element_left(em[d]);
    return x;
  }


  template <int dim>
  Tensor<1, dim>
  SplineSpace<dim>::element_lengths(const unsigned int e) const
  {
    const auto     em = element_multi_index(e);
    Tensor<1, dim> h;
    for (unsigned int d = 0; d < dim; ++d)
      h[d] = kv[d].element_length(em[d]);
    return h;
  }


  template <int dim>
  unsigned int
  SplineSpace<dim>::find_element(const Point<dim> &xi) const
  {
    std::array<unsigned int, dim> m;
    for (unsigned int d = 0; d < dim; ++d)
      m[d] = kv[d].find_element(xi[d]);
    return element_index(m);
  }


  template <int dim>
  Point<dim>
  SplineSpace<dim>::greville_point(const unsigned int i) const
  {
    const auto m = basis_multi_index(i);
    Point<dim> x;
    for (unsigned int d = 0; d < dim; ++d)
      x[d] = greville[d][m[d]];
    return x;
  }


  template <int dim>
  bool
  SplineSpace<dim>::element_at_face(const unsigned int e,
                                    const unsigned int face) const
  {
    const unsigned int d = face / 2;
    if (kv[d].is_periodic())
      return false;
    const auto m = element_multi_index(e);
    return (face % 2 == 0) ? m[d] == 0 : m[d] == kv[d].n_elements() - 1;
  }


  template <int dim>
  bool
  SplineSpace<dim>::basis_in_face_layer(const unsigned int i,
                                        const unsigned int face,
                                        const unsigned int layer) const
  {
    const unsigned int d = face / 2;
    if (kv[d].is_periodic())
      return false;
    const auto m = basis_multi_index(i);
    return (face % 2 == 0) ? m[d] == layer :
                             m[d] == kv[d].n_basis() - 1 - layer;
  }


  template <int dim>
  void
  SplineSpace<dim>::evaluate(const std::vector<double> &c,
                             const unsigned int         nc,
                             const Point<dim>          &xi,
                             std::vector<double>       &values) const
  {
    std::array<unsigned int, dim> em;
    for (unsigned int d = 0; d < dim; ++d)
      em[d] = kv[d].find_element(xi[d]);
    const std::vector<double> N = element_basis_values<dim>(kv, em, xi);
    std::vector<unsigned int> indices;
    element_basis_indices(element_index(em), indices);
    values.assign(nc, 0.);
    for (unsigned int j = 0; j < n_per_element; ++j)
      for (unsigned int c_ = 0; c_ < nc; ++c_)
        values[c_] += N[j] * c[indices[j] * nc + c_];
  }


  template <int dim>
  double
  SplineSpace<dim>::evaluate_on_element(const unsigned int         e,
                                        const std::vector<double> &c,
                                        const Point<dim>          &xi) const
  {
    const std::vector<double> N
      = element_basis_values<dim>(kv, element_multi_index(e), xi);
    double value = 0;
    for (unsigned int j = 0; j < n_per_element; ++j)
      value += N[j] * c[j];
    return value;
  }


  template <int dim>
  bool
  SplineSpace<dim>::operator==(const SplineSpace<dim> &o) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (kv[d].knots() != o.kv[d].knots() || kv[d].degree() != o.kv[d].degree()
          || kv[d].is_periodic() != o.kv[d].is_periodic())
        return false;
    return true;
  }


  template <int dim>
  SplineSpace<dim>
  SplineSpace<dim>::h_refined(const unsigned int times) const
  {
    std::array<KnotVector, dim> r = kv;
    for (unsigned int d = 0; d < dim; ++d)
      r[d] = kv[d].h_refined(times);
    return SplineSpace<dim>(r);
  }


  template <int dim>
  SplineSpace<dim>
  SplineSpace<dim>::degree_elevated(const unsigned int by) const
  {
    std::array<KnotVector, dim> r = kv;
    for (unsigned int d = 0; d < dim; ++d)
      r[d] = kv[d].degree_elevated(by);
    return SplineSpace<dim>(r);
  }


  template <int dim>
  std::vector<double>
  interpolate_at_greville_points(const SplineSpace<dim>    &space,
                                 const std::vector<double> &values,
                                 const unsigned int         nc)
  {
    std::vector<double> c      = values;
    unsigned int        stride = nc;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const KnotVector  &kvd = space.knot_vector(d);
        const unsigned int n   = kvd.n_basis();
        const auto         g   = kvd.greville_points();
        FullMatrix<double> A(n, n);
        for (unsigned int r = 0; r < n; ++r)
          {
            const unsigned int e = kvd.find_element(g[r]);
            const auto         v = kvd.evaluate_on_element(e, g[r], 0)[0];
            for (unsigned int j = 0; j <= kvd.degree(); ++j)
              A(r, kvd.global_index(e, j)) += v[j];
          }
        A.gauss_jordan();
        // Apply A^{-1} along every line in direction d.
        const unsigned int n_lines = c.size() / n;
        Vector<double>     in(n), out(n);
        for (unsigned int line = 0; line < n_lines; ++line)
          {
            const unsigned int lo = line % stride, hi = line / stride;
            for (unsigned int r = 0; r < n; ++r)
              in[r] = c[lo + stride * (r + n * hi)];
            A.vmult(out, in);
            for (unsigned int r = 0; r < n; ++r)
              c[lo + stride * (r + n * hi)] = out[r];
          }
        stride *= n;
      }
    return c;
  }


  template class SplineSpace<1>;
  template class SplineSpace<2>;
  template class SplineSpace<3>;
  template std::vector<double>
  interpolate_at_greville_points(const SplineSpace<1> &,
                                 const std::vector<double> &,
                                 const unsigned int);
  template std::vector<double>
  interpolate_at_greville_points(const SplineSpace<2> &,
                                 const std::vector<double> &,
                                 const unsigned int);
  template std::vector<double>
  interpolate_at_greville_points(const SplineSpace<3> &,
                                 const std::vector<double> &,
                                 const unsigned int);
} // namespace vesicle_iga
