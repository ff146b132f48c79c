#include <deal.II/base/exceptions.h>

#include <vesicle_iga/kernel/tensor_product_kernel.h>

#include <algorithm>
#include <numeric>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    /**
     * Contract a tensor stored lexicographically (first index fastest) with
     * extents @p e along direction @p d with the matrix M:
     * y[.., k, ..] (+)= sum_j M(k, j) x[.., j, ..], where M(k, j) =
     * M[k * n + j] (rows = number of k) or, if @p transposed, M[j * rows +
     * k]. On return e[d] is the number of rows.
     */
    template <int dim>
    void
    contract(const double                  *x,
             std::array<unsigned int, dim> &e,
             const unsigned int             d,
             const double                  *M,
             const unsigned int             rows,
             const bool                     transposed,
             std::vector<double>           &y,
             const bool                     accumulate)
    {
      unsigned int stride = 1, outer = 1;
      for (unsigned int c = 0; c < d; ++c)
        stride *= e[c];
      for (unsigned int c = d + 1; c < dim; ++c)
        outer *= e[c];
      const unsigned int n    = e[d];
      const std::size_t  size = std::size_t(outer) * rows * stride;
      if (!accumulate)
        y.assign(size, 0.);
      const auto entry = [&](const unsigned int k, const unsigned int j) {
        return transposed ? M[j * rows + k] : M[k * n + j];
      };
      if (stride == 1)
        {
          // Along the fastest index: short dot products per line.
          for (unsigned int o = 0; o < outer; ++o)
            {
              const double *in  = x + std::size_t(o) * n;
              double       *out = &y[std::size_t(o) * rows];
              for (unsigned int k = 0; k < rows; ++k)
                {
                  double sum = 0;
                  for (unsigned int j = 0; j < n; ++j)
                    sum += entry(k, j) * in[j];
                  out[k] += sum;
                }
            }
        }
      else
        for (unsigned int o = 0; o < outer; ++o)
          for (unsigned int k = 0; k < rows; ++k)
            {
              double *out = &y[(std::size_t(o) * rows + k) * stride];
              for (unsigned int j = 0; j < n; ++j)
                {
                  const double  m  = entry(k, j);
                  const double *in = x + (std::size_t(o) * n + j) * stride;
                  for (unsigned int s = 0; s < stride; ++s)
                    out[s] += m * in[s];
                }
            }
      e[d] = rows;
    }


    /// The integration of one residual group: atoms [begin, end) sorted by
    /// their orders from the last direction down; contracts directions
    /// 0..level and accumulates into @p result.
    template <int dim>
    void
    reduce(const TensorProductFactors<dim>               &f,
           const typename TensorProductKernel<dim>::Atom *begin,
           const typename TensorProductKernel<dim>::Atom *end,
           const int                                      level,
           std::array<std::vector<double>, dim + 1>      &stage,
           std::vector<double>                           &result,
           const bool                                     accumulate)
    {
      using D = Derivative<dim>;
      // Extents before contracting direction `level`: points for d >= level,
      // basis for d < level.
      std::array<unsigned int, dim> e;
      for (unsigned int d = 0; d < dim; ++d)
        e[d] = int(d) < level ? f.n_basis[d] : f.n_points[d];
      bool first = !accumulate;
      for (auto *a = begin; a != end;)
        {
          const unsigned int o = D::orders(a->derivative)[level];
          auto              *b = a;
          while (b != end && D::orders(b->derivative)[level] == o)
            ++b;
          const double *input = a->coefficient;
          if (level > 0)
            {
              reduce<dim>(f, a, b, level - 1, stage, stage[level], false);
              input = stage[level].data();
            }
          std::array<unsigned int, dim> ext = e;
          contract<dim>(input,
                        ext,
                        level,
                        f.table(level, o),
                        f.n_basis[level],
                        true,
                        result,
                        !first);
          first = false;
          a     = b;
        }
    }
  } // namespace


  template <int dim>
  void
  TensorProductKernel<dim>::weights(const TensorProductFactors<dim> &f,
                                    std::vector<double>             &JxW)
  {
    const unsigned int n_q = f.n_quadrature_points();
    JxW.resize(n_q);
    for (unsigned int q = 0; q < n_q; ++q)
      {
        unsigned int r = q;
        double       w = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            w *= f.weights[d][r % f.n_points[d]];
            r /= f.n_points[d];
          }
        JxW[q] = w;
      }
  }


  template <int dim>
  void
  TensorProductKernel<dim>::evaluate(
    const TensorProductFactors<dim> &f,
    const double                    *u,
    const std::vector<unsigned int> &derivatives,
    double *const                   *out,
    Workspace                       &ws)
  {
    using D = Derivative<dim>;
    // Derivatives sorted by their orders (direction 0 first): consecutive
    // ones share the contractions of their common leading orders.
    std::array<unsigned int, 32> order_of;
    const unsigned int           n = derivatives.size();
    AssertIndexRange(n, 33);
    std::iota(order_of.begin(), order_of.begin() + n, 0u);
    std::sort(order_of.begin(),
              order_of.begin() + n,
              [&](const unsigned int a, const unsigned int b) {
                return D::orders(derivatives[a]) < D::orders(derivatives[b]);
              });
    std::array<unsigned int, dim> previous;
    previous.fill(~0u);
    for (unsigned int s = 0; s < n; ++s)
      {
        const unsigned int k     = order_of[s];
        const auto         o     = D::orders(derivatives[k]);
        unsigned int       start = 0;
        while (start < dim && o[start] == previous[start])
          ++start;
        if (start == dim)
          start = dim - 1; // the same derivative twice
        for (unsigned int d = start; d < dim; ++d)
          {
            std::array<unsigned int, dim> e;
            for (unsigned int c = 0; c < dim; ++c)
              e[c] = c < d ? f.n_points[c] : f.n_basis[c];
            contract<dim>(d == 0 ? u : ws.stage[d].data(),
                          e,
                          d,
                          f.table(d, o[d]),
                          f.n_points[d],
                          false,
                          ws.stage[d + 1],
                          false);
          }
        std::copy(ws.stage[dim].begin(), ws.stage[dim].end(), out[k]);
        previous = o;
      }
  }


  template <int dim>
  void
  TensorProductKernel<dim>::integrate(const TensorProductFactors<dim> &f,
                                      std::vector<Atom>               &atoms,
                                      double                          *rhs,
                                      Workspace                       &ws)
  {
    using D = Derivative<dim>;
    if (atoms.empty())
      return;
    // Sorted by the orders of the last direction first: atoms that agree
    // in the directions contracted last share those contractions.
    std::sort(atoms.begin(), atoms.end(), [](const Atom &a, const Atom &b) {
      auto oa = D::orders(a.derivative), ob = D::orders(b.derivative);
      std::reverse(oa.begin(), oa.end());
      std::reverse(ob.begin(), ob.end());
      return oa < ob;
    });
    reduce<dim>(f,
                atoms.data(),
                atoms.data() + atoms.size(),
                dim - 1,
                ws.stage,
                ws.accumulated,
                false);
    for (unsigned int i = 0; i < ws.accumulated.size(); ++i)
      rhs[i] += ws.accumulated[i];
  }


  namespace
  {
    /// B_d[q][i ns + j] = N^{(oa)}_i(q) M^{(ob)}_j(q) for direction d.
    template <int dim>
    const double *
    product(const TensorProductFactors<dim>              &test,
            const TensorProductFactors<dim>              &trial,
            const unsigned int                            d,
            const unsigned int                            oa,
            const unsigned int                            ob,
            typename TensorProductKernel<dim>::Workspace &ws)
    {
      auto              &v   = ws.products[d][oa * 4 + ob];
      const unsigned int bit = 1u << (oa * 4 + ob);
      if (!(ws.product_valid[d] & bit))
        {
          const unsigned int nt = test.n_basis[d], ns = trial.n_basis[d];
          const unsigned int m = test.n_points[d];
          v.resize(m * nt * ns);
          const double *Ft = test.table(d, oa), *Fs = trial.table(d, ob);
          for (unsigned int q = 0; q < m; ++q)
            for (unsigned int i = 0; i < nt; ++i)
              for (unsigned int j = 0; j < ns; ++j)
                v[(q * nt + i) * ns + j] = Ft[q * nt + i] * Fs[q * ns + j];
          ws.product_valid[d] |= bit;
        }
      return v.data();
    }

    /// T[q_out][k] += sum_q B[q][k] C[q_out + n_out q] for k < nn, the
    /// contraction of the direction contracted first.
    inline void
    accumulate_first(const double      *B,
                     const double      *C,
                     const unsigned int m,
                     const unsigned int n_out,
                     const unsigned int nn,
                     double            *T)
    {
      for (unsigned int q = 0; q < m; ++q)
        for (unsigned int o = 0; o < n_out; ++o)
          {
            const double c = C[o + n_out * q];
            if (c == 0.)
              continue;
            double       *t = T + std::size_t(o) * nn;
            const double *b = B + q * nn;
            for (unsigned int k = 0; k < nn; ++k)
              t[k] += b[k] * c;
          }
    }

    /// What the stages of a matrix integration share.
    template <int dim>
    struct MatrixStage
    {
      const TensorProductFactors<dim>              &test, &trial;
      bool                                          symmetric;
      double                                       *A;
      std::size_t                                   row_stride;
      typename TensorProductKernel<dim>::Workspace &ws;
    };


    /// The last stage, shared by all dim: A[(i0, I), (j0, J)] +=
    ///   sum_q0 B0[q0][i0 j0] T[q0][index(I, J)], with the outer test and
    /// trial multi-indices I < nI, J < nJ and T of stride @p stride per q0.
    template <int dim, typename Index>
    void
    last_stage(const MatrixStage<dim>    &m,
               const double              *B0,
               const std::vector<double> &T,
               const unsigned int         nI,
               const unsigned int         nJ,
               const std::size_t          stride,
               const Index               &index)
    {
      const unsigned int nt0 = m.test.n_basis[0], ns0 = m.trial.n_basis[0];
      const unsigned int m0 = m.test.n_points[0], nn0 = nt0 * ns0;
      AssertIndexRange(nn0, 65);
      double tmp[64];
      for (unsigned int I = 0; I < nI; ++I)
        for (unsigned int J = m.symmetric ? I : 0; J < nJ; ++J)
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
            for (unsigned int i0 = 0; i0 < nt0; ++i0)
              {
                double *row = m.A + (I * nt0 + i0) * m.row_stride + J * ns0;
                for (unsigned int j0 = 0; j0 < ns0; ++j0)
                  row[j0] += tmp[i0 * ns0 + j0];
              }
            // The block (J, I) of a symmetric matrix is the transpose.
            if (m.symmetric && J != I)
              for (unsigned int i0 = 0; i0 < nt0; ++i0)
                for (unsigned int j0 = 0; j0 < ns0; ++j0)
                  m.A[(J * nt0 + j0) * m.row_stride + I * ns0 + i0]
                    += tmp[i0 * ns0 + j0];
          }
    }


    using Key = std::vector<std::array<unsigned int, 6>>;

    /// 2D: per group of equal orders in direction 0, contract direction 1
    /// of every pair, then direction 0 once.
    void
    matrix_groups(const MatrixStage<2>                            &m,
                  const std::vector<TensorProductKernel<2>::Pair> &pairs,
                  const Key                                       &keys)
    {
      const unsigned int   nt1 = m.test.n_basis[1], ns1 = m.trial.n_basis[1];
      const unsigned int   m0 = m.test.n_points[0], m1 = m.test.n_points[1];
      const unsigned int   nn1 = nt1 * ns1;
      std::vector<double> &T1  = m.ws.stage[1];
      for (std::size_t g = 0; g < pairs.size();)
        {
          const auto k0 = keys[g];
          T1.assign(std::size_t(m0) * nn1, 0.);
          std::size_t e = g;
          for (; e < pairs.size() && keys[e][0] == k0[0] && keys[e][1] == k0[1];
               ++e)
            accumulate_first(
              product<2>(m.test, m.trial, 1, keys[e][2], keys[e][3], m.ws),
              pairs[e].coefficient,
              m1,
              m0,
              nn1,
              T1.data());
          last_stage(m,
                     product<2>(m.test, m.trial, 0, k0[0], k0[1], m.ws),
                     T1,
                     nt1,
                     ns1,
                     nn1,
                     [ns1](const unsigned int I, const unsigned int J) {
                       return std::size_t(I) * ns1 + J;
                     });
          g = e;
        }
    }


    /// T2[q0][(i1 ns1 + j1) nn2 + (i2 ns2 + j2)] +=
    ///   sum_q1 B1[q1][i1 j1] T1[q0 + m0 q1][i2 j2]
    /// (inner loops over contiguous (i2 j2): vectorised).
    void
    accumulate_middle(const double              *B1,
                      const std::vector<double> &T1,
                      const unsigned int         m0,
                      const unsigned int         m1,
                      const unsigned int         nn1,
                      const unsigned int         nn2,
                      std::vector<double>       &T2)
    {
      for (unsigned int q0 = 0; q0 < m0; ++q0)
        for (unsigned int q1 = 0; q1 < m1; ++q1)
          {
            const double *t1 = &T1[std::size_t(q0 + m0 * q1) * nn2];
            const double *b  = B1 + q1 * nn1;
            double       *t2 = &T2[std::size_t(q0) * nn1 * nn2];
            for (unsigned int k = 0; k < nn1; ++k)
              {
                const double c = b[k];
                if (c == 0.)
                  continue;
                double *row = t2 + k * nn2;
                for (unsigned int l = 0; l < nn2; ++l)
                  row[l] += c * t1[l];
              }
          }
    }


    /// 3D: per group of equal orders in direction 0, per subgroup of equal
    /// orders in direction 1, contract direction 2 of every pair, then
    /// direction 1 once per subgroup and direction 0 once per group.
    void
    matrix_groups(const MatrixStage<3>                            &m,
                  const std::vector<TensorProductKernel<3>::Pair> &pairs,
                  const Key                                       &keys)
    {
      const unsigned int   nt1 = m.test.n_basis[1], ns1 = m.trial.n_basis[1];
      const unsigned int   nt2 = m.test.n_basis[2], ns2 = m.trial.n_basis[2];
      const unsigned int   m0 = m.test.n_points[0], m1 = m.test.n_points[1];
      const unsigned int   m2  = m.test.n_points[2];
      const unsigned int   nn1 = nt1 * ns1, nn2 = nt2 * ns2;
      std::vector<double> &T1 = m.ws.stage[1], &T2 = m.ws.stage[2];
      for (std::size_t g = 0; g < pairs.size();)
        {
          const auto k0 = keys[g];
          T2.assign(std::size_t(m0) * nn1 * nn2, 0.);
          std::size_t e = g;
          while (e < pairs.size() && keys[e][0] == k0[0] && keys[e][1] == k0[1])
            {
              const auto k1 = keys[e];
              T1.assign(std::size_t(m0) * m1 * nn2, 0.);
              std::size_t h = e;
              for (; h < pairs.size() && keys[h][0] == k0[0]
                     && keys[h][1] == k0[1] && keys[h][2] == k1[2]
                     && keys[h][3] == k1[3];
                   ++h)
                accumulate_first(
                  product<3>(m.test, m.trial, 2, keys[h][4], keys[h][5], m.ws),
                  pairs[h].coefficient,
                  m2,
                  m0 * m1,
                  nn2,
                  T1.data());
              accumulate_middle(
                product<3>(m.test, m.trial, 1, k1[2], k1[3], m.ws),
                T1,
                m0,
                m1,
                nn1,
                nn2,
                T2);
              e = h;
            }
          last_stage(m,
                     product<3>(m.test, m.trial, 0, k0[0], k0[1], m.ws),
                     T2,
                     nt1 * nt2,
                     ns1 * ns2,
                     std::size_t(nn1) * nn2,
                     [=](const unsigned int I, const unsigned int J) {
                       const unsigned int i1 = I % nt1, i2 = I / nt1;
                       const unsigned int j1 = J % ns1, j2 = J / ns1;
                       return std::size_t(i1 * ns1 + j1) * nn2 + i2 * ns2 + j2;
                     });
          g = e;
        }
    }


    /**
     * The stages above with the univariate sizes fixed at compile time (NT
     * test and NS trial functions and M points per direction, the same in
     * every direction): the loops unroll and the partial sums of the last
     * stage stay in registers. Same operations in the same order as the
     * general stages, except that zero factors are not skipped.
     */
    template <int NT, int NS, int M>
    struct FixedSize
    {
      static constexpr unsigned int nn = NT * NS;

      /// T[o][k] += sum_q B[q][k] C[o + n_out q] (the first contraction).
      template <unsigned int n_out>
      static void
      first(const double *B, const double *C, double *T)
      {
        for (unsigned int q = 0; q < M; ++q)
          for (unsigned int o = 0; o < n_out; ++o)
            {
              const double  c = C[o + n_out * q];
              double       *t = T + o * nn;
              const double *b = B + q * nn;
              for (unsigned int k = 0; k < nn; ++k)
                t[k] += b[k] * c;
            }
      }

      /// 3D: T2[q0][k nn + l] += sum_q1 B1[q1][k] T1[q0 + M q1][l].
      static void
      middle(const double *B1, const double *T1, double *T2)
      {
        for (unsigned int q0 = 0; q0 < M; ++q0)
          for (unsigned int q1 = 0; q1 < M; ++q1)
            {
              const double *t1 = T1 + (q0 + M * q1) * nn;
              const double *b  = B1 + q1 * nn;
              double       *t2 = T2 + q0 * nn * nn;
              for (unsigned int k = 0; k < nn; ++k)
                {
                  const double c   = b[k];
                  double      *row = t2 + k * nn;
                  for (unsigned int l = 0; l < nn; ++l)
                    row[l] += c * t1[l];
                }
            }
      }

      /// A[(i0, I), (j0, J)] += sum_q0 B0[q0][i0 j0] T[q0][index(I, J)].
      template <int dim, typename Index>
      static void
      last(const MatrixStage<dim> &m,
           const double           *B0,
           const double           *T,
           const unsigned int      nI,
           const unsigned int      nJ,
           const std::size_t       stride,
           const Index            &index)
      {
        for (unsigned int I = 0; I < nI; ++I)
          for (unsigned int J = m.symmetric ? I : 0; J < nJ; ++J)
            {
              double            tmp[nn] = {};
              const std::size_t IJ      = index(I, J);
              for (unsigned int q = 0; q < M; ++q)
                {
                  const double  t = T[q * stride + IJ];
                  const double *b = B0 + q * nn;
                  for (unsigned int k = 0; k < nn; ++k)
                    tmp[k] += b[k] * t;
                }
              for (unsigned int i0 = 0; i0 < NT; ++i0)
                {
                  double *row = m.A + (I * NT + i0) * m.row_stride + J * NS;
                  for (unsigned int j0 = 0; j0 < NS; ++j0)
                    row[j0] += tmp[i0 * NS + j0];
                }
              if (m.symmetric && J != I)
                for (unsigned int i0 = 0; i0 < NT; ++i0)
                  for (unsigned int j0 = 0; j0 < NS; ++j0)
                    m.A[(J * NT + j0) * m.row_stride + I * NS + i0]
                      += tmp[i0 * NS + j0];
            }
      }

      static void
      groups(const MatrixStage<2>                            &m,
             const std::vector<TensorProductKernel<2>::Pair> &pairs,
             const Key                                       &keys)
      {
        std::vector<double> &T1 = m.ws.stage[1];
        for (std::size_t g = 0; g < pairs.size();)
          {
            const auto k0 = keys[g];
            T1.assign(M * nn, 0.);
            std::size_t e = g;
            for (;
                 e < pairs.size() && keys[e][0] == k0[0] && keys[e][1] == k0[1];
                 ++e)
              first<M>(
                product<2>(m.test, m.trial, 1, keys[e][2], keys[e][3], m.ws),
                pairs[e].coefficient,
                T1.data());
            last(m,
                 product<2>(m.test, m.trial, 0, k0[0], k0[1], m.ws),
                 T1.data(),
                 NT,
                 NS,
                 nn,
                 [](const unsigned int I, const unsigned int J) {
                   return std::size_t(I) * NS + J;
                 });
            g = e;
          }
      }

      static void
      groups(const MatrixStage<3>                            &m,
             const std::vector<TensorProductKernel<3>::Pair> &pairs,
             const Key                                       &keys)
      {
        std::vector<double> &T1 = m.ws.stage[1], &T2 = m.ws.stage[2];
        for (std::size_t g = 0; g < pairs.size();)
          {
            const auto k0 = keys[g];
            T2.assign(M * nn * nn, 0.);
            std::size_t e = g;
            while (e < pairs.size() && keys[e][0] == k0[0]
                   && keys[e][1] == k0[1])
              {
                const auto k1 = keys[e];
                T1.assign(M * M * nn, 0.);
                std::size_t h = e;
                for (; h < pairs.size() && keys[h][0] == k0[0]
                       && keys[h][1] == k0[1] && keys[h][2] == k1[2]
                       && keys[h][3] == k1[3];
                     ++h)
                  first<M * M>(
                    product<3>(
                      m.test, m.trial, 2, keys[h][4], keys[h][5], m.ws),
                    pairs[h].coefficient,
                    T1.data());
                middle(product<3>(m.test, m.trial, 1, k1[2], k1[3], m.ws),
                       T1.data(),
                       T2.data());
                e = h;
              }
            last(m,
                 product<3>(m.test, m.trial, 0, k0[0], k0[1], m.ws),
                 T2.data(),
                 NT * NT,
                 NS * NS,
                 nn * nn,
                 [](const unsigned int I, const unsigned int J) {
                   const unsigned int i1 = I % NT, i2 = I / NT;
                   const unsigned int j1 = J % NS, j2 = J / NS;
                   return std::size_t(i1 * NS + j1) * nn + i2 * NS + j2;
                 });
            g = e;
          }
      }
    };


    /// The fixed-size stages where the sizes are those of quadratic or
    /// cubic spaces with p+1 or p+2 points (the same in every direction);
    /// false where they are not.
    template <int dim>
    bool
    fixed_size_groups(
      const MatrixStage<dim>                                     &m,
      const std::vector<typename TensorProductKernel<dim>::Pair> &pairs,
      const Key                                                  &keys)
    {
      for (unsigned int d = 1; d < dim; ++d)
        if (m.test.n_basis[d] != m.test.n_basis[0]
            || m.trial.n_basis[d] != m.trial.n_basis[0]
            || m.test.n_points[d] != m.test.n_points[0])
          return false;
      const unsigned int nt = m.test.n_basis[0], ns = m.trial.n_basis[0];
      const unsigned int q = m.test.n_points[0];
      if (nt != ns)
        return false;
      if (nt == 3 && q == 3)
        FixedSize<3, 3, 3>::groups(m, pairs, keys);
      else if (nt == 3 && q == 4)
        FixedSize<3, 3, 4>::groups(m, pairs, keys);
      else if (nt == 4 && q == 4)
        FixedSize<4, 4, 4>::groups(m, pairs, keys);
      else if (nt == 4 && q == 5)
        FixedSize<4, 4, 5>::groups(m, pairs, keys);
      else
        return false;
      return true;
    }
  } // namespace


  template <int dim>
  void
  TensorProductKernel<dim>::integrate_matrix(
    const TensorProductFactors<dim> &test,
    const TensorProductFactors<dim> &trial,
    std::vector<Pair>               &pairs,
    const bool                       symmetric,
    double                          *A,
    const std::size_t                row_stride,
    Workspace                       &ws)
  {
    using D = Derivative<dim>;
    if (pairs.empty())
      return;
    ws.product_valid.fill(0);
    // The orders (test, trial) per direction: pairs are grouped by those of
    // direction 0, then 1, ..., so that the last contraction (direction 0,
    // the most expensive) is done once per group.
    const auto key = [](const Pair &p) {
      std::array<unsigned int, 6> k{};
      const auto                  a = D::orders(p.test);
      const auto                  b = D::orders(p.trial);
      for (unsigned int d = 0; d < dim; ++d)
        {
          k[2 * d]     = a[d];
          k[2 * d + 1] = b[d];
        }
      return k;
    };
    std::sort(pairs.begin(), pairs.end(), [&](const Pair &a, const Pair &b) {
      return key(a) < key(b);
    });
    thread_local Key keys;
    keys.resize(pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k)
      keys[k] = key(pairs[k]);
    const MatrixStage<dim> stage{test, trial, symmetric, A, row_stride, ws};
    if (!fixed_size_groups<dim>(stage, pairs, keys))
      matrix_groups(stage, pairs, keys);
  }

  template class TensorProductKernel<2>;
  template class TensorProductKernel<3>;
} // namespace vesicle_iga
