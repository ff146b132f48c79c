#include <deal.II/fe/fe_bernstein.h>

#include <vesicle_iga/spline/spline_cell_values.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  SplineCellValues<dim>::SplineCellValues(
    const SplineSpace<dim>                   &space_,
    std::shared_ptr<const NurbsGeometry<dim>> geometry_,
    const Quadrature<1>                      &quadrature_1d,
    const unsigned int                        max_derivative,
    const bool                                with_shape_tables)
    : space(space_)
    , geometry(geometry_)
    , order(geometry_ ? std::max(1u, max_derivative) : max_derivative)
    , shape_tables(with_shape_tables || geometry_)
    , n_local(space_.n_basis_per_element())
  {
    AssertThrow(order <= 3, ExcMessage("Derivatives up to order 3 only."));
    AssertThrow(!geometry || geometry->space() == space,
                ExcMessage("The NURBS geometry must be defined on the "
                           "analysis space: call refined_to() first."));
    std::vector<double> qp;
    for (unsigned int q = 0; q < quadrature_1d.size(); ++q)
      {
        qp.push_back(quadrature_1d.point(q)[0]);
        q_weights.push_back(quadrature_1d.weight(q));
      }
    for (unsigned int d = 0; d < dim; ++d)
      {
        tables[d][0] = make_table(d, qp);
        tables[d][1] = make_table(d, {0.});
        tables[d][2] = make_table(d, {1.});
      }
  }


  template <int dim>
  typename SplineCellValues<dim>::BernsteinTable
  SplineCellValues<dim>::make_table(const unsigned int         d,
                                    const std::vector<double> &pts) const
  {
    const unsigned int p = space.knot_vector(d).degree();
    // FE_Bernstein<1> numbers its shape functions vertex 0, vertex 1, then
    // the interior ones; B_a (a = 0..p, lexicographic) is shape function:
    const auto fe_index = [p](const unsigned int a) {
      return a == 0 ? 0u : (a == p ? 1u : a + 1);
    };
    const FE_Bernstein<1> fe(p);
    BernsteinTable        t;
    t.points = pts;
    t.table.assign(order + 1, std::vector<double>(pts.size() * (p + 1), 0.));
    for (unsigned int q = 0; q < pts.size(); ++q)
      {
        const Point<1> x(pts[q]);
        for (unsigned int a = 0; a <= p; ++a)
          {
            const unsigned int i        = fe_index(a);
            t.table[0][q * (p + 1) + a] = fe.shape_value(i, x);
            if (order >= 1)
              t.table[1][q * (p + 1) + a] = fe.shape_grad(i, x)[0];
            if (order >= 2)
              t.table[2][q * (p + 1) + a] = fe.shape_grad_grad(i, x)[0][0];
            if (order >= 3)
              t.table[3][q * (p + 1) + a]
                = fe.shape_3rd_derivative(i, x)[0][0][0];
          }
      }
    return t;
  }


  template <int dim>
  void
  SplineCellValues<dim>::reinit(const unsigned int element)
  {
    std::array<const BernsteinTable *, dim>      t;
    std::array<const std::vector<double> *, dim> w;
    for (unsigned int d = 0; d < dim; ++d)
      {
        t[d] = &tables[d][0];
        w[d] = &q_weights;
      }
    compute(element, t, w, -1);
  }


  template <int dim>
  void
  SplineCellValues<dim>::reinit_face(const unsigned int element,
                                     const unsigned int face)
  {
    std::array<const BernsteinTable *, dim>      t;
    std::array<const std::vector<double> *, dim> w;
    for (unsigned int d = 0; d < dim; ++d)
      {
        t[d] = (d == face / 2) ? &tables[d][1 + face % 2] : &tables[d][0];
        w[d] = (d == face / 2) ? &unit_weight : &q_weights;
      }
    compute(element, t, w, face);
  }


  template <int dim>
  void
  SplineCellValues<dim>::reinit_points(
    const unsigned int                          element,
    const std::array<std::vector<double>, dim> &unit_points)
  {
    std::array<const BernsteinTable *, dim>      t;
    std::array<const std::vector<double> *, dim> w;
    std::array<std::vector<double>, dim>         ones;
    for (unsigned int d = 0; d < dim; ++d)
      {
        if (custom[d].points != unit_points[d])
          custom[d] = make_table(d, unit_points[d]);
        t[d] = &custom[d];
        ones[d].assign(unit_points[d].size(), 1.);
        w[d] = &ones[d];
      }
    compute(element, t, w, -1);
  }


  template <int dim>
  void
  SplineCellValues<dim>::compute_univariate(
    const std::array<const BernsteinTable *, dim>      &tab,
    const std::array<const std::vector<double> *, dim> &wts,
    const int                                           face)
  {
    const auto           em    = space.element_multi_index(current_element);
    const Tensor<1, dim> h     = space.element_lengths(current_element);
    const Point<dim>     lower = space.element_lower_corner(current_element);
    std::array<unsigned int, dim>        &np = univariate.n_basis;
    std::array<unsigned int, dim>        &nq = univariate.n_points;
    std::array<std::vector<double>, dim> &N  = univariate.shape;
    univariate.max_order                     = order;
    n_q                                      = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const KnotVector &kv = space.knot_vector(d);
        np[d]                = kv.degree() + 1;
        nq[d]                = tab[d]->points.size();
        n_q *= nq[d];
        const auto &C = kv.extraction(em[d]);
        N[d].assign((order + 1) * nq[d] * np[d], 0.);
        double scale = 1.;
        for (unsigned int r = 0; r <= order; ++r, scale /= h[d])
          for (unsigned int q = 0; q < nq[d]; ++q)
            for (unsigned int j = 0; j < np[d]; ++j)
              {
                double s = 0;
                for (unsigned int a = 0; a < np[d]; ++a)
                  s += C[j][a] * tab[d]->table[r][q * np[d] + a];
                N[d][(r * nq[d] + q) * np[d] + j] = s * scale;
              }
        univariate.weights[d].resize(nq[d]);
        univariate.points[d].resize(nq[d]);
        for (unsigned int q = 0; q < nq[d]; ++q)
          {
            univariate.weights[d][q]
              = (*wts[d])[q] * (int(d) == face / 2 && face >= 0 ? 1. : h[d]);
            univariate.points[d][q] = lower[d] + h[d] * tab[d]->points[q];
          }
      }
  }


  template <int dim>
  void
  SplineCellValues<dim>::parametric_derivatives(
    const std::array<unsigned int, dim> &qm)
  {
    // The derivative of multi-order (r_1..r_d) is prod_d N_d^{(r_d)}.
    const auto &np = univariate.n_basis;
    const auto &nq = univariate.n_points;
    const auto &N  = univariate.shape;
    for (unsigned int j = 0; j < n_local; ++j)
      {
        std::array<const double *, dim> f;
        unsigned int                    rj = j;
        for (unsigned int d = 0; d < dim; ++d)
          {
            f[d] = &N[d][qm[d] * np[d] + rj % np[d]];
            rj /= np[d];
          }
        const auto D = [&](const std::array<unsigned int, dim> &r) {
          double s = 1;
          for (unsigned int d = 0; d < dim; ++d)
            s *= *(f[d] + r[d] * nq[d] * np[d]);
          return s;
        };
        std::array<unsigned int, dim> r{};
        v[j] = D(r);
        for (unsigned int a = 0; a < dim && order >= 1; ++a)
          {
            ++r[a];
            g[j][a] = D(r);
            for (unsigned int b = a; b < dim && order >= 2; ++b)
              {
                ++r[b];
                H[j][a][b] = H[j][b][a] = D(r);
                for (unsigned int c = b; c < dim && order >= 3; ++c)
                  {
                    ++r[c];
                    const double t = D(r);
                    T[j][a][b][c] = T[j][a][c][b] = T[j][b][a][c]
                      = T[j][b][c][a] = T[j][c][a][b] = T[j][c][b][a] = t;
                    --r[c];
                  }
                --r[b];
              }
            --r[a];
          }
      }
  }


  template <int dim>
  void
  SplineCellValues<dim>::apply_weights()
  {
    double         W = 0;
    Tensor<1, dim> Wg;
    Tensor<2, dim> WH;
    Tensor<3, dim> WT;
    for (unsigned int j = 0; j < n_local; ++j)
      {
        const double wj = geometry->weight(indices[j]);
        v[j] *= wj;
        g[j] *= wj;
        H[j] *= wj;
        T[j] *= wj;
        W += v[j];
        Wg += g[j];
        WH += H[j];
        WT += T[j];
      }
    for (unsigned int j = 0; j < n_local; ++j)
      {
        const double   R = v[j] / W;
        Tensor<1, dim> Rg;
        Tensor<2, dim> RH;
        Tensor<3, dim> RT;
        for (unsigned int a = 0; a < dim; ++a)
          Rg[a] = (g[j][a] - R * Wg[a]) / W;
        if (order >= 2)
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              RH[a][b]
                = (H[j][a][b] - Rg[a] * Wg[b] - Rg[b] * Wg[a] - R * WH[a][b])
                  / W;
        if (order >= 3)
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              for (unsigned int c = 0; c < dim; ++c)
                RT[a][b][c]
                  = (T[j][a][b][c] - RH[a][b] * Wg[c] - RH[a][c] * Wg[b]
                     - RH[b][c] * Wg[a] - Rg[a] * WH[b][c] - Rg[b] * WH[a][c]
                     - Rg[c] * WH[a][b] - R * WT[a][b][c])
                    / W;
        v[j] = R;
        g[j] = Rg;
        H[j] = RH;
        T[j] = RT;
      }
  }


  template <int dim>
  double
  SplineCellValues<dim>::map_to_physical(const unsigned int q,
                                         Tensor<2, dim>    &Jinv)
  {
    // The geometry map and its derivatives: x = sum_j R_j P_j.
    Point<dim>     x;
    Tensor<2, dim> J;
    Tensor<3, dim> X2; // X2[i][a][b] = d^2 x_i / dxi_a dxi_b
    Tensor<4, dim> X3;
    for (unsigned int j = 0; j < n_local; ++j)
      {
        const Point<dim> &P = geometry->control_point(indices[j]);
        for (unsigned int i = 0; i < dim; ++i)
          {
            x[i] += v[j] * P[i];
            for (unsigned int a = 0; a < dim; ++a)
              {
                J[i][a] += g[j][a] * P[i];
                for (unsigned int b = 0; b < dim && order >= 2; ++b)
                  {
                    X2[i][a][b] += H[j][a][b] * P[i];
                    for (unsigned int c = 0; c < dim && order >= 3; ++c)
                      X3[i][a][b][c] += T[j][a][b][c] * P[i];
                  }
              }
          }
      }
    points[q] = x;
    Jinv      = invert(J); // Jinv[a][i] = dxi_a/dx_i
    // Chain rule (doc/splines.md): with g_i, H_ij, T_ijk the physical
    // derivatives,
    //   R_a   = g_i J_ia
    //   R_ab  = H_ij J_ia J_jb + g_i X2_iab
    //   R_abc = T_ijk J_ia J_jb J_kc
    //         + H_ij (X2_iac J_jb + J_ia X2_jbc + X2_iab J_jc) + g_i X3_iabc
    for (unsigned int j = 0; j < n_local; ++j)
      {
        values[q * n_local + j] = v[j];
        Tensor<1, dim> gp;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int a = 0; a < dim; ++a)
            gp[i] += g[j][a] * Jinv[a][i];
        grads[q * n_local + j] = gp;
        if (order < 2)
          continue;
        Tensor<2, dim> Hr; // reduced parametric
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            {
              Hr[a][b] = H[j][a][b];
              for (unsigned int i = 0; i < dim; ++i)
                Hr[a][b] -= gp[i] * X2[i][a][b];
            }
        const Tensor<2, dim> Hp   = transpose(Jinv) * Hr * Jinv;
        hessians[q * n_local + j] = Hp;
        if (order < 3)
          continue;
        Tensor<3, dim> Tr, Tp;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            for (unsigned int c = 0; c < dim; ++c)
              {
                double s = T[j][a][b][c];
                for (unsigned int i = 0; i < dim; ++i)
                  {
                    s -= gp[i] * X3[i][a][b][c];
                    for (unsigned int k = 0; k < dim; ++k)
                      s -= Hp[i][k]
                           * (X2[i][a][c] * J[k][b] + J[i][a] * X2[k][b][c]
                              + X2[i][a][b] * J[k][c]);
                  }
                Tr[a][b][c] = s;
              }
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = 0; l < dim; ++l)
              {
                double s = 0;
                for (unsigned int a = 0; a < dim; ++a)
                  for (unsigned int b = 0; b < dim; ++b)
                    for (unsigned int c = 0; c < dim; ++c)
                      s += Tr[a][b][c] * Jinv[a][i] * Jinv[b][k] * Jinv[c][l];
                Tp[i][k][l] = s;
              }
        thirds[q * n_local + j] = Tp;
      }
    return determinant(J);
  }


  template <int dim>
  void
  SplineCellValues<dim>::compute(
    const unsigned int                                  element,
    const std::array<const BernsteinTable *, dim>      &tab,
    const std::array<const std::vector<double> *, dim> &wts,
    const int                                           face)
  {
    current_element = element;
    space.element_basis_indices(element, indices);
    compute_univariate(tab, wts, face);
    const auto          &nq = univariate.n_points;
    const Tensor<1, dim> h  = space.element_lengths(element);
    jxw.resize(n_q);
    if (!shape_tables)
      {
        // Only the univariate factors and the weights are wanted.
        for (unsigned int q = 0; q < n_q; ++q)
          {
            unsigned int rq = q;
            double       w  = 1.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                w *= univariate.weights[d][rq % nq[d]];
                rq /= nq[d];
              }
            jxw[q] = w;
          }
        return;
      }

    values.resize(n_q * n_local);
    grads.resize(order >= 1 ? n_q * n_local : 0);
    hessians.resize(order >= 2 ? n_q * n_local : 0);
    thirds.resize(order >= 3 ? n_q * n_local : 0);
    points.resize(n_q);
    xi.resize(n_q);
    normals.resize(n_q);
    metric.resize(n_q);
    v.resize(n_local);
    g.resize(n_local);
    H.resize(n_local);
    T.resize(n_local);

    for (unsigned int q = 0; q < n_q; ++q)
      {
        std::array<unsigned int, dim> qm;
        unsigned int                  rq = q;
        double                        w  = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          {
            qm[d] = rq % nq[d];
            rq /= nq[d];
            xi[q][d] = univariate.points[d][qm[d]];
            w *= univariate.weights[d][qm[d]];
          }
        parametric_derivatives(qm);

        Tensor<2, dim> Jinv = unit_symmetric_tensor<dim>();
        double         detJ = 1.;
        if (!geometry)
          {
            points[q] = xi[q];
            for (unsigned int j = 0; j < n_local; ++j)
              {
                values[q * n_local + j] = v[j];
                if (order >= 1)
                  grads[q * n_local + j] = g[j];
                if (order >= 2)
                  hessians[q * n_local + j] = H[j];
                if (order >= 3)
                  thirds[q * n_local + j] = T[j];
              }
          }
        else
          {
            apply_weights();
            detJ = map_to_physical(q, Jinv);
          }

        // Metric tensor (N1) with the parent element [-1,1]^d:
        // dxi_parent/dx = (2/h) dxi/dx.
        Tensor<2, dim> G;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int a = 0; a < dim; ++a)
              G[i][k] += 4. / (h[a] * h[a]) * Jinv[a][i] * Jinv[a][k];
        metric[q] = G;

        double measure = std::abs(detJ);
        if (face >= 0)
          {
            const unsigned int fd   = face / 2;
            const double       sign = (face % 2) ? 1. : -1.;
            Tensor<1, dim>     n;
            for (unsigned int i = 0; i < dim; ++i)
              n[i] = sign * Jinv[fd][i];
            const double nn = n.norm();
            normals[q]      = n / nn;
            measure *= nn;
          }
        jxw[q] = w * measure;
      }
  }


  template <int dim>
  double
  SplineCellValues<dim>::normal_element_size(const unsigned int q) const
  {
    return 2. / std::sqrt(normals[q] * (metric[q] * normals[q]));
  }


  template <int dim>
  double
  SplineCellValues<dim>::value(const std::vector<double> &c,
                               const unsigned int         q) const
  {
    double s = 0;
    for (unsigned int j = 0; j < n_local; ++j)
      s += c[j] * values[q * n_local + j];
    return s;
  }


  template <int dim>
  Tensor<1, dim>
  SplineCellValues<dim>::gradient(const std::vector<double> &c,
                                  const unsigned int         q) const
  {
    Tensor<1, dim> s;
    for (unsigned int j = 0; j < n_local; ++j)
      s += c[j] * grads[q * n_local + j];
    return s;
  }


  template <int dim>
  Tensor<2, dim>
  SplineCellValues<dim>::hessian(const std::vector<double> &c,
                                 const unsigned int         q) const
  {
    Tensor<2, dim> s;
    for (unsigned int j = 0; j < n_local; ++j)
      s += c[j] * hessians[q * n_local + j];
    return s;
  }

  template class SplineCellValues<1>;
  template class SplineCellValues<2>;
  template class SplineCellValues<3>;
} // namespace vesicle_iga
