#include <deal.II/base/exceptions.h>

#include <vesicle_iga/spline/sum_factorization.h>

#include <algorithm>
#include <map>

namespace vesicle_iga
{
  namespace
  {
    /**
     * Contract a tensor stored lexicographically (first index fastest) with
     * extents @p e along direction @p d with the matrix M (rows x e[d],
     * row-major): y[.., k, ..] = sum_j M[k][j] x[.., j, ..]. On return e[d]
     * is the number of rows.
     */
    template <int dim>
    void
    contract(const std::vector<double>     &x,
             std::array<unsigned int, dim> &e,
             const unsigned int             d,
             const double                  *M,
             const unsigned int             rows,
             std::vector<double>           &y)
    {
      unsigned int stride = 1, outer = 1;
      for (unsigned int c = 0; c < d; ++c)
        stride *= e[c];
      for (unsigned int c = d + 1; c < dim; ++c)
        outer *= e[c];
      const unsigned int n = e[d];
      y.assign(std::size_t(outer) * rows * stride, 0.);
      if (stride == 1)
        {
          // Along the fastest index: short dot products per line.
          for (unsigned int o = 0; o < outer; ++o)
            {
              const double *in  = &x[std::size_t(o) * n];
              double       *out = &y[std::size_t(o) * rows];
              for (unsigned int k = 0; k < rows; ++k)
                {
                  double sum = 0;
                  for (unsigned int j = 0; j < n; ++j)
                    sum += M[k * n + j] * in[j];
                  out[k] = sum;
                }
            }
          e[d] = rows;
          return;
        }
      for (unsigned int o = 0; o < outer; ++o)
        for (unsigned int k = 0; k < rows; ++k)
          {
            double *out = &y[(std::size_t(o) * rows + k) * stride];
            for (unsigned int j = 0; j < n; ++j)
              {
                const double  m  = M[k * n + j];
                const double *in = &x[(std::size_t(o) * n + j) * stride];
                for (unsigned int s = 0; s < stride; ++s)
                  out[s] += m * in[s];
              }
          }
      e[d] = rows;
    }
  } // namespace


  template <int dim>
  unsigned int
  SumFactorization<dim>::order(const unsigned int a, const unsigned int d)
  {
    if (a == value_atom)
      return 0;
    if (a <= dim)
      return (a - 1 == d) ? 1 : 0;
    return (a - 1 - dim == d) ? 2 : 0;
  }


  template <int dim>
  SumFactorization<dim>::SumFactorization(
    const TensorProductFactors<dim> &factors)
    : f(factors)
  {
    Assert(f.max_order >= 2,
           ExcMessage("Sum factorisation needs derivatives up to order 2."));
  }


  template <int dim>
  unsigned int
  SumFactorization<dim>::n_quadrature_points() const
  {
    unsigned int n = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n *= f.n_points[d];
    return n;
  }


  template <int dim>
  unsigned int
  SumFactorization<dim>::n_basis() const
  {
    unsigned int n = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n *= f.n_basis[d];
    return n;
  }


  template <int dim>
  double
  SumFactorization<dim>::JxW(const unsigned int q) const
  {
    double       w = 1;
    unsigned int r = q;
    for (unsigned int d = 0; d < dim; ++d)
      {
        w *= f.weights[d][r % f.n_points[d]];
        r /= f.n_points[d];
      }
    return w;
  }


  template <int dim>
  void
  SumFactorization<dim>::evaluate(const std::vector<double>       &u,
                                  const std::array<bool, n_atoms> &wanted,
                                  AtomValues                      &out) const
  {
    thread_local std::vector<double> x, y;
    for (unsigned int a = 0; a < n_atoms; ++a)
      {
        if (!wanted[a])
          continue;
        std::array<unsigned int, dim> e = f.n_basis;
        x                               = u;
        for (unsigned int d = 0; d < dim; ++d)
          {
            // M[q][j] = N_j^{(r)}(q): exactly the layout of the factors.
            const double *M
              = &f.shape[d][order(a, d) * f.n_points[d] * f.n_basis[d]];
            contract<dim>(x, e, d, M, f.n_points[d], y);
            std::swap(x, y);
          }
        out[a] = x;
      }
  }


  template <int dim>
  void
  SumFactorization<dim>::integrate(const AtomValues                &c,
                                   const std::array<bool, n_atoms> &used,
                                   Vector<double>                  &rhs) const
  {
    thread_local std::vector<double> x, y, Mt;
    for (unsigned int a = 0; a < n_atoms; ++a)
      {
        if (!used[a])
          continue;
        std::array<unsigned int, dim> e = f.n_points;
        x                               = c[a];
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int n = f.n_basis[d], m = f.n_points[d];
            Mt.resize(n * m);
            for (unsigned int j = 0; j < n; ++j)
              for (unsigned int q = 0; q < m; ++q)
                Mt[j * m + q] = f(d, order(a, d), q, j);
            contract<dim>(x, e, d, Mt.data(), n, y);
            std::swap(x, y);
          }
        for (unsigned int i = 0; i < x.size(); ++i)
          rhs(i) += x[i];
      }
  }


  template <int dim>
  void
  SumFactorization<dim>::integrate_matrix(
    const std::vector<const AtomPair *> &pairs,
    FullMatrix<double>                  &A,
    const bool                           symmetric) const
  {
    if (pairs.empty())
      return;
    // Products B_d[(oa, ob)][q][i n + j] = N^{(oa)}_i(q) N^{(ob)}_j(q).
    std::array<
      std::map<std::pair<unsigned int, unsigned int>, std::vector<double>>,
      dim>
               B;
    const auto product = [&](const unsigned int d,
                             const unsigned int oa,
                             const unsigned int ob) -> const double * {
      auto &v = B[d][{oa, ob}];
      if (v.empty())
        {
          const unsigned int n = f.n_basis[d], m = f.n_points[d];
          v.resize(m * n * n);
          for (unsigned int q = 0; q < m; ++q)
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                v[(q * n + i) * n + j] = f(d, oa, q, i) * f(d, ob, q, j);
        }
      return v.data();
    };

    // Group the pairs by the derivative orders of the outer directions
    // (sorted by the orders of direction 0, then 1, ...).
    std::vector<const AtomPair *> sorted = pairs;
    const auto                    key    = [](const AtomPair *p) {
      std::array<unsigned int, 2 * dim> k;
      for (unsigned int d = 0; d < dim; ++d)
        {
          k[2 * d]     = order(p->test_atom, d);
          k[2 * d + 1] = order(p->trial_atom, d);
        }
      return k;
    };
    std::sort(sorted.begin(),
              sorted.end(),
              [&](const AtomPair *a, const AtomPair *b) {
                return key(a) < key(b);
              });

    const unsigned int n0 = f.n_basis[0], m0 = f.n_points[0];
    const unsigned int nn0 = n0 * n0;
    // Last stage, shared by all dim: A[(i0, I), (j0, J)] +=
    //   sum_q0 B0[q0][i0 j0] T[q0][index(I, J)], with the outer
    //   multi-indices I, J of size nI and T of stride @p stride per q0.
    const auto last_stage = [&](const double              *B0,
                                const std::vector<double> &T,
                                const unsigned int         nI,
                                const std::size_t          stride,
                                const auto                &index) {
      double tmp[64];
      AssertIndexRange(nn0, 65);
      for (unsigned int I = 0; I < nI; ++I)
        for (unsigned int J = symmetric ? I : 0; J < nI; ++J)
          {
            std::fill(tmp, tmp + nn0, 0.);
            const std::size_t IJ = index(I, J);
            for (unsigned int q = 0; q < m0; ++q)
              {
                const double t = T[q * stride + IJ];
                if (t == 0.)
                  continue;
                const double *b = B0 + q * nn0;
                for (unsigned int k = 0; k < nn0; ++k)
                  tmp[k] += b[k] * t;
              }
            for (unsigned int i0 = 0; i0 < n0; ++i0)
              for (unsigned int j0 = 0; j0 < n0; ++j0)
                A(I * n0 + i0, J * n0 + j0) += tmp[i0 * n0 + j0];
            // The block (J, I) of a symmetric matrix is the transpose.
            if (symmetric && J != I)
              for (unsigned int i0 = 0; i0 < n0; ++i0)
                for (unsigned int j0 = 0; j0 < n0; ++j0)
                  A(J * n0 + j0, I * n0 + i0) += tmp[i0 * n0 + j0];
          }
    };

    if constexpr (dim == 2)
      {
        const unsigned int  n1 = f.n_basis[1], m1 = f.n_points[1];
        const unsigned int  nn1 = n1 * n1;
        std::vector<double> T1(std::size_t(m0) * nn1);
        for (std::size_t g = 0; g < sorted.size();)
          {
            const auto k0 = key(sorted[g]);
            std::fill(T1.begin(), T1.end(), 0.);
            std::size_t e = g;
            for (; e < sorted.size() && key(sorted[e])[0] == k0[0]
                   && key(sorted[e])[1] == k0[1];
                 ++e)
              {
                const auto    k  = key(sorted[e]);
                const double *B1 = product(1, k[2], k[3]);
                const auto   &C  = sorted[e]->coefficient;
                // T1[q0][i1 j1] += sum_q1 B1[q1][i1 j1] C[q0 + m0 q1]
                for (unsigned int q1 = 0; q1 < m1; ++q1)
                  for (unsigned int q0 = 0; q0 < m0; ++q0)
                    {
                      const double c = C[q0 + m0 * q1];
                      if (c == 0.)
                        continue;
                      double       *t = &T1[std::size_t(q0) * nn1];
                      const double *b = B1 + q1 * nn1;
                      for (unsigned int k = 0; k < nn1; ++k)
                        t[k] += b[k] * c;
                    }
              }
            // T1 is [q0][i1 n1 + j1].
            last_stage(product(0, k0[0], k0[1]),
                       T1,
                       n1,
                       nn1,
                       [n1](const unsigned int I, const unsigned int J) {
                         return std::size_t(I) * n1 + J;
                       });
            g = e;
          }
      }
    else
      {
        const unsigned int  n1 = f.n_basis[1], m1 = f.n_points[1];
        const unsigned int  n2 = f.n_basis[2], m2 = f.n_points[2];
        const unsigned int  nn1 = n1 * n1, nn2 = n2 * n2;
        const unsigned int  nI = n1 * n2;
        std::vector<double> T1(std::size_t(m0) * m1 * nn2);
        std::vector<double> T2(std::size_t(m0) * nn1 * nn2);
        for (std::size_t g = 0; g < sorted.size();)
          {
            const auto k0 = key(sorted[g]);
            std::fill(T2.begin(), T2.end(), 0.);
            std::size_t e = g;
            while (e < sorted.size() && key(sorted[e])[0] == k0[0]
                   && key(sorted[e])[1] == k0[1])
              {
                const auto k1 = key(sorted[e]);
                std::fill(T1.begin(), T1.end(), 0.);
                std::size_t h = e;
                for (;
                     h < sorted.size() && key(sorted[h])[0] == k0[0]
                     && key(sorted[h])[1] == k0[1] && key(sorted[h])[2] == k1[2]
                     && key(sorted[h])[3] == k1[3];
                     ++h)
                  {
                    const auto    k  = key(sorted[h]);
                    const double *B2 = product(2, k[4], k[5]);
                    const auto   &C  = sorted[h]->coefficient;
                    // T1[q0 + m0 q1][i2 j2] += sum_q2 B2[q2][i2 j2] C[q]
                    for (unsigned int q2 = 0; q2 < m2; ++q2)
                      for (unsigned int q01 = 0; q01 < m0 * m1; ++q01)
                        {
                          const double c = C[q01 + m0 * m1 * q2];
                          if (c == 0.)
                            continue;
                          double       *t = &T1[std::size_t(q01) * nn2];
                          const double *b = B2 + q2 * nn2;
                          for (unsigned int k = 0; k < nn2; ++k)
                            t[k] += b[k] * c;
                        }
                  }
                // T2[q0][(i1 n1 + j1) nn2 + (i2 n2 + j2)] +=
                //   sum_q1 B1[q1][i1 j1] T1[q0 + m0 q1][i2 j2]
                // (inner loops over contiguous (i2 j2): vectorised).
                const double *B1 = product(1, k1[2], k1[3]);
                for (unsigned int q0 = 0; q0 < m0; ++q0)
                  for (unsigned int q1 = 0; q1 < m1; ++q1)
                    {
                      const double *t1 = &T1[std::size_t(q0 + m0 * q1) * nn2];
                      const double *b  = B1 + q1 * nn1;
                      double       *t2 = &T2[std::size_t(q0) * nn1 * nn2];
                      for (unsigned int k1 = 0; k1 < nn1; ++k1)
                        {
                          const double c = b[k1];
                          if (c == 0.)
                            continue;
                          double *row = t2 + k1 * nn2;
                          for (unsigned int k2 = 0; k2 < nn2; ++k2)
                            row[k2] += c * t1[k2];
                        }
                    }
                e = h;
              }
            last_stage(product(0, k0[0], k0[1]),
                       T2,
                       nI,
                       std::size_t(nn1) * nn2,
                       [n1, n2, nn2](const unsigned int I,
                                     const unsigned int J) {
                         const unsigned int i1 = I % n1, i2 = I / n1;
                         const unsigned int j1 = J % n1, j2 = J / n1;
                         return std::size_t(i1 * n1 + j1) * nn2 + i2 * n2 + j2;
                       });
            g = e;
          }
      }
  }

  template class SumFactorization<2>;
  template class SumFactorization<3>;
} // namespace vesicle_iga
