#include <deal.II/lac/full_matrix.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/spline/knot_vector.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    std::string
    to_string(const std::vector<double> &v)
    {
      std::ostringstream s;
      for (unsigned int i = 0; i < v.size(); ++i)
        s << (i ? ", " : "") << v[i];
      return s.str();
    }

    double
    binomial(const unsigned int n, const unsigned int r)
    {
      double b = 1;
      for (unsigned int i = 1; i <= r; ++i)
        b = b * (n - r + i) / i;
      return b;
    }
  } // namespace


  KnotVector::KnotVector(const unsigned int         degree,
                         const std::vector<double> &breakpoints,
                         const std::vector<int>    &continuity,
                         const bool                 periodic_,
                         const int                  seam_continuity_,
                         const std::string         &name)
    : p(degree)
    , z(breakpoints)
    , periodic(periodic_)
    , k_seam(seam_continuity_ < 0 ? int(degree) - 1 : seam_continuity_)
  {
    check_input(p >= 1 && p <= max_spline_degree,
                name + " degree",
                std::to_string(p),
                "1 <= p <= " + std::to_string(max_spline_degree));
    check_input(z.size() >= 2,
                name + " breakpoints",
                to_string(z),
                "at least two breakpoints (one element)");
    for (unsigned int i = 1; i < z.size(); ++i)
      check_input(z[i] > z[i - 1] && std::isfinite(z[i])
                    && std::isfinite(z[i - 1]),
                  name + " breakpoints",
                  to_string(z),
                  "a finite, strictly increasing list");
    if (continuity.empty())
      k.assign(z.size() - 2, int(p) - 1);
    else
      {
        check_input(continuity.size() == z.size() - 2,
                    name + " continuity",
                    std::to_string(continuity.size()) + " values",
                    "one value per interior breakpoint ("
                      + std::to_string(z.size() - 2) + ") or none");
        k = continuity;
      }
    for (const int kj : k)
      check_input(kj >= 0 && kj <= int(p) - 1,
                  name + " continuity",
                  std::to_string(kj),
                  "0 <= k <= p-1 = " + std::to_string(int(p) - 1)
                    + " (C^k at a knot of multiplicity p-k; a continuity not "
                      "below the degree would make the space a single "
                      "polynomial)");
    check_input(k_seam >= 0 && k_seam <= int(p) - 1,
                name + " continuity",
                std::to_string(k_seam),
                "0 <= k <= p-1 = " + std::to_string(int(p) - 1));
    build();
  }


  KnotVector
  KnotVector::uniform(const unsigned int degree,
                      const unsigned int n_elements,
                      const double       a,
                      const double       b,
                      const int          continuity,
                      const bool         periodic)
  {
    check_input(n_elements >= 1,
                "number of elements",
                std::to_string(n_elements),
                "at least 1");
    std::vector<double> z(n_elements + 1);
    for (unsigned int i = 0; i <= n_elements; ++i)
      z[i] = a + (b - a) * i / n_elements;
    z.back()     = b;
    const int kk = continuity < 0 ? int(degree) - 1 : continuity;
    return KnotVector(
      degree, z, std::vector<int>(n_elements - 1, kk), periodic, kk);
  }


  void
  KnotVector::build()
  {
    const unsigned int m = z.size() - 1;
    t.clear();
    span.resize(m);
    if (!periodic)
      {
        t.assign(p + 1, z[0]);
        span[0] = p;
        for (unsigned int j = 1; j < m; ++j)
          {
            for (int r = 0; r < int(p) - k[j - 1]; ++r)
              t.push_back(z[j]);
            span[j] = t.size() - 1;
          }
        for (unsigned int r = 0; r <= p; ++r)
          t.push_back(z[m]);
        offset      = 0;
        n_functions = t.size() - p - 1;
      }
    else
      {
        // One period of knots, then three copies shifted by -L, 0, +L: enough
        // room for the p+1 spans on either side of every element.
        std::vector<double>       period;
        std::vector<unsigned int> last_in_period(m);
        for (unsigned int j = 0; j < m; ++j)
          {
            const int mult = int(p) - (j == 0 ? k_seam : k[j - 1]);
            for (int r = 0; r < mult; ++r)
              period.push_back(z[j]);
            last_in_period[j] = period.size() - 1;
          }
        const unsigned int M = period.size();
        check_input(M >= p + 1,
                    "periodic knot vector",
                    std::to_string(m) + " elements",
                    "at least p+1 = " + std::to_string(p + 1)
                      + " basis functions per period (add elements)");
        const double L = z[m] - z[0];
        for (int s = -1; s <= 1; ++s)
          for (const double x : period)
            t.push_back(x + s * L);
        t.push_back(z[0] + 2 * L);
        for (unsigned int j = 0; j < m; ++j)
          span[j] = M + last_in_period[j];
        offset      = M;
        n_functions = M;
      }

    // Bezier extraction: match the derivatives 0..p of every local B-spline
    // at the left end of the element with those of the Bernstein
    // polynomials, a lower-triangular system (d^r B_a/ds^r (0) = 0 for a > r).
    C.assign(m, std::vector<std::array<double, 8>>(p + 1));
    double                           falling = 1; // p!/(p-r)!
    std::vector<std::vector<double>> D(p + 1, std::vector<double>(p + 1, 0));
    for (unsigned int r = 0; r <= p; ++r)
      {
        if (r > 0)
          falling *= (p - r + 1);
        for (unsigned int a = 0; a <= r; ++a)
          D[r][a] = falling * ((r - a) % 2 ? -1. : 1.) * binomial(r, a);
      }
    for (unsigned int e = 0; e < m; ++e)
      {
        const auto   ders = evaluate_on_element(e, z[e], p);
        const double h    = z[e + 1] - z[e];
        for (unsigned int j = 0; j <= p; ++j)
          {
            C[e][j].fill(0.);
            double hr = 1;
            for (unsigned int r = 0; r <= p; ++r, hr *= h)
              {
                double rhs = hr * ders[r][j];
                for (unsigned int a = 0; a < r; ++a)
                  rhs -= D[r][a] * C[e][j][a];
                C[e][j][r] = rhs / D[r][r];
              }
          }
      }
  }


  unsigned int
  KnotVector::find_element(const double x) const
  {
    if (std::isnan(x))
      throw std::invalid_argument(
        "KnotVector::find_element: the coordinate is not a number");
    if (x <= z.front())
      return 0;
    if (x >= z.back())
      return n_elements() - 1;
    return std::upper_bound(z.begin(), z.end(), x) - z.begin() - 1;
  }


  unsigned int
  KnotVector::global_index(const unsigned int e, const unsigned int j) const
  {
    const int i = int(span[e]) - int(p) + int(j) - offset;
    if (!periodic)
      return i;
    return ((i % int(n_functions)) + int(n_functions)) % int(n_functions);
  }


  std::vector<std::vector<double>>
  KnotVector::evaluate_on_element(const unsigned int e,
                                  const double       x,
                                  const unsigned int n) const
  {
    // Piegl & Tiller, The NURBS Book, Algorithm A2.3.
    const unsigned int               s = span[e];
    std::vector<std::vector<double>> ndu(p + 1, std::vector<double>(p + 1));
    std::vector<double>              left(p + 1), right(p + 1);
    ndu[0][0] = 1.;
    for (unsigned int j = 1; j <= p; ++j)
      {
        left[j]      = x - t[s + 1 - j];
        right[j]     = t[s + j] - x;
        double saved = 0.;
        for (unsigned int r = 0; r < j; ++r)
          {
            ndu[j][r]         = right[r + 1] + left[j - r];
            const double temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j]         = saved + right[r + 1] * temp;
            saved             = left[j - r] * temp;
          }
        ndu[j][j] = saved;
      }
    std::vector<std::vector<double>> ders(n + 1, std::vector<double>(p + 1, 0));
    for (unsigned int j = 0; j <= p; ++j)
      ders[0][j] = ndu[j][p];
    std::vector<std::vector<double>> a(2, std::vector<double>(p + 1));
    for (int r = 0; r <= int(p); ++r)
      {
        int s1 = 0, s2 = 1;
        a[0][0] = 1.;
        for (int kk = 1; kk <= int(n) && kk <= int(p); ++kk)
          {
            double    d  = 0.;
            const int rk = r - kk, pk = int(p) - kk;
            if (r >= kk)
              {
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
                d        = a[s2][0] * ndu[rk][pk];
              }
            const int j1 = rk >= -1 ? 1 : -rk;
            const int j2 = (r - 1 <= pk) ? kk - 1 : int(p) - r;
            for (int j = j1; j <= j2; ++j)
              {
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
                d += a[s2][j] * ndu[rk + j][pk];
              }
            if (r <= pk)
              {
                a[s2][kk] = -a[s1][kk - 1] / ndu[pk + 1][r];
                d += a[s2][kk] * ndu[r][pk];
              }
            ders[kk][r] = d;
            std::swap(s1, s2);
          }
      }
    double factor = p;
    for (unsigned int kk = 1; kk <= n && kk <= p; ++kk)
      {
        for (unsigned int j = 0; j <= p; ++j)
          ders[kk][j] *= factor;
        factor *= (p - kk);
      }
    return ders;
  }


  std::vector<double>
  KnotVector::greville_points() const
  {
    std::vector<double> g(n_functions);
    const double        L = z.back() - z.front();
    for (unsigned int i = 0; i < n_functions; ++i)
      {
        double s = 0;
        for (unsigned int r = 1; r <= p; ++r)
          s += t[i + offset + r];
        s /= p;
        if (periodic)
          {
            while (s >= z.back())
              s -= L;
            while (s < z.front())
              s += L;
          }
        g[i] = s;
      }
    return g;
  }


  KnotVector
  KnotVector::h_refined(const unsigned int times) const
  {
    std::vector<double> nz = z;
    std::vector<int>    nk = k;
    for (unsigned int r = 0; r < times; ++r)
      {
        std::vector<double> zz{nz[0]};
        std::vector<int>    kk;
        for (unsigned int e = 0; e + 1 < nz.size(); ++e)
          {
            if (e > 0)
              kk.push_back(nk[e - 1]);
            zz.push_back(0.5 * (nz[e] + nz[e + 1]));
            kk.push_back(int(p) - 1);
            zz.push_back(nz[e + 1]);
          }
        nz = zz;
        nk = kk;
      }
    return KnotVector(p, nz, nk, periodic, k_seam);
  }


  KnotVector
  KnotVector::coarsened() const
  {
    std::vector<double> nz{z[0]};
    std::vector<int>    nk;
    for (unsigned int j = 2; j < z.size() - 1; j += 2)
      {
        nz.push_back(z[j]);
        nk.push_back(k[j - 1]);
      }
    nz.push_back(z.back());
    return KnotVector(p, nz, nk, periodic, k_seam);
  }


  std::vector<std::vector<double>>
  prolongation_matrix(const KnotVector &coarse, const KnotVector &fine)
  {
    const unsigned int nf = fine.n_basis(), nc = coarse.n_basis();
    const auto         g = fine.greville_points();
    // Collocation matrix of the fine space and the coarse functions at the
    // fine Greville points.
    dealii::FullMatrix<double> G(nf, nf), V(nf, nc);
    for (unsigned int r = 0; r < nf; ++r)
      {
        const unsigned int ef = fine.find_element(g[r]);
        const auto         vf = fine.evaluate_on_element(ef, g[r], 0)[0];
        for (unsigned int j = 0; j <= fine.degree(); ++j)
          G(r, fine.global_index(ef, j)) += vf[j];
        const unsigned int ec = coarse.find_element(g[r]);
        const auto         vc = coarse.evaluate_on_element(ec, g[r], 0)[0];
        for (unsigned int j = 0; j <= coarse.degree(); ++j)
          V(r, coarse.global_index(ec, j)) += vc[j];
      }
    G.gauss_jordan();
    dealii::FullMatrix<double> P(nf, nc);
    G.mmult(P, V);
    std::vector<std::vector<double>> rows(nf, std::vector<double>(nc, 0.));
    for (unsigned int i = 0; i < nf; ++i)
      for (unsigned int j = 0; j < nc; ++j)
        if (std::abs(P(i, j)) > 1e-14)
          rows[i][j] = P(i, j);
    return rows;
  }


  KnotVector
  KnotVector::degree_elevated(const unsigned int by) const
  {
    return KnotVector(p + by, z, k, periodic, k_seam);
  }
} // namespace vesicle_iga
