// Properties of the spline spaces that must hold exactly (to round-off),
// for p = 1..6, uniform and non-uniform open knot vectors with reduced
// continuity, and periodic ones, in 2D (and one 3D case):
//  - partition of unity and non-negativity of the basis at quadrature points;
//  - agreement of the Bernstein/extraction evaluation (SplineCellValues)
//    with a direct Cox-de Boor recursion (spec section 2.1, with 0/0 := 0)
//    for values, and of derivatives with central differences of it;
//  - continuity: the jump of every derivative of order <= k (C^k) across
//    every interior face, each side evaluated on its own element;
//  - spec SP1: at xi = 0.625 only N_2, N_3, N_4 are non-zero.
// Each check prints "ok" when the worst deviation is below 1e-12 (1e-6 for
// the finite-difference comparison, whose truncation error is ~1e-9), and
// FAILED with the value otherwise.

#include <deal.II/base/quadrature_lib.h>

#include <vesicle_iga/spline/spline_cell_values.h>

#include <cmath>
#include <fstream>
#include <iomanip>

using namespace vesicle_iga;
using namespace dealii;

std::ofstream out("output");

// Naive Cox-de Boor recursion on a knot vector (spec section 2.1).
double
cox_de_boor(const std::vector<double> &t, int i, int p, double x)
{
  if (p == 0)
    {
      // Half-open spans; at the right end the last non-empty span is closed.
      if (t[i] <= x && x < t[i + 1])
        return 1;
      if (x == t.back() && t[i] < t[i + 1] && t[i + 1] == t.back())
        return 1;
      return 0;
    }
  double a = 0, b = 0;
  if (t[i + p] > t[i])
    a = (x - t[i]) / (t[i + p] - t[i]) * cox_de_boor(t, i, p - 1, x);
  if (t[i + p + 1] > t[i + 1])
    b = (t[i + p + 1] - x) / (t[i + p + 1] - t[i + 1])
        * cox_de_boor(t, i + 1, p - 1, x);
  return a + b;
}

// "ok" when the deviation is round-off (below tol), else the value: numdiff
// then sees a changed word, whatever its tolerances.
std::string
bound(const double e, const double tol = 1e-12)
{
  if (e < tol)
    return "ok";
  std::ostringstream s;
  s << "FAILED(" << e << ")";
  return s.str();
}

void
check_1d_open(const KnotVector &kv, const std::string &name)
{
  // Values against Cox-de Boor at points inside every element.
  const SplineSpace<1> space(std::array<KnotVector, 1>{{kv}});
  SplineCellValues<1>  v(space, nullptr, QGauss<1>(kv.degree() + 2), 3);
  double               err_value = 0, err_d1 = 0, pu = 0, negative = 0;
  const auto          &t = kv.knots();
  for (unsigned int e = 0; e < kv.n_elements(); ++e)
    {
      v.reinit(e);
      for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
        {
          const double x = v.quadrature_point(q)[0], h = 1e-6;
          double       sum = 0;
          for (unsigned int j = 0; j <= kv.degree(); ++j)
            {
              const int i = v.basis_indices()[j];
              sum += v.shape_value(j, q);
              negative = std::min(negative, v.shape_value(j, q));
              err_value
                = std::max(err_value,
                           std::abs(v.shape_value(j, q)
                                    - cox_de_boor(t, i, kv.degree(), x)));
              const double fd = (cox_de_boor(t, i, kv.degree(), x + h)
                                 - cox_de_boor(t, i, kv.degree(), x - h))
                                / (2 * h);
              err_d1 = std::max(err_d1,
                                std::abs(v.shape_grad(j, q)[0] - fd)
                                  / (1 + std::abs(fd)));
            }
          pu = std::max(pu, std::abs(sum - 1));
        }
    }
  out << name << ": p=" << kv.degree() << " functions=" << kv.n_basis()
      << " |sum-1| " << bound(pu) << ", min value " << bound(-negative)
      << ", values vs Cox-de Boor " << bound(err_value)
      << ", derivative vs central difference of Cox-de Boor "
      << bound(err_d1, 1e-6) << "\n";
}

template <int dim>
void
check_continuity(const SplineSpace<dim> &space, const std::string &name)
{
  // For every interior face: evaluate a field with pseudo-random
  // coefficients from both sides; derivatives of order r <= k must agree.
  std::vector<double> c(space.n_basis());
  for (unsigned int i = 0; i < c.size(); ++i)
    c[i] = std::sin(1.7 * i + 0.3);
  SplineCellValues<dim> a(space, nullptr, QGauss<1>(3), 3),
    b(space, nullptr, QGauss<1>(3), 3);
  std::array<double, 4> jump{};
  std::array<double, 4> size{};
  unsigned int          min_k = 100;
  for (unsigned int d = 0; d < dim; ++d)
    {
      const KnotVector &kv = space.knot_vector(d);
      for (unsigned int e = 0; e < space.n_elements(); ++e)
        {
          auto m = space.element_multi_index(e);
          if (m[d] + 1 == kv.n_elements() && !kv.is_periodic())
            continue;
          const int k = (m[d] + 1 == kv.n_elements()) ?
                          kv.seam_continuity() :
                          kv.interior_continuity()[m[d]];
          min_k       = std::min<unsigned int>(min_k, k);
          auto mn     = m;
          mn[d]       = (m[d] + 1) % kv.n_elements();
          a.reinit_face(e, 2 * d + 1);
          b.reinit_face(space.element_index(mn), 2 * d);
          std::vector<double> ca, cb;
          for (auto i : a.basis_indices())
            ca.push_back(c[i]);
          for (auto i : b.basis_indices())
            cb.push_back(c[i]);
          for (unsigned int q = 0; q < a.n_quadrature_points(); ++q)
            {
              double         va = 0, vb = 0;
              Tensor<1, dim> ga, gb;
              Tensor<2, dim> ha, hb;
              Tensor<3, dim> ta, tb;
              for (unsigned int j = 0; j < ca.size(); ++j)
                {
                  va += ca[j] * a.shape_value(j, q);
                  vb += cb[j] * b.shape_value(j, q);
                  ga += ca[j] * a.shape_grad(j, q);
                  gb += cb[j] * b.shape_grad(j, q);
                  ha += ca[j] * a.shape_hessian(j, q);
                  hb += cb[j] * b.shape_hessian(j, q);
                  ta += ca[j] * a.shape_3rd_derivative(j, q);
                  tb += cb[j] * b.shape_3rd_derivative(j, q);
                }
              const std::array<double, 4> diff = {std::abs(va - vb),
                                                  (ga - gb).norm(),
                                                  (ha - hb).norm(),
                                                  (ta - tb).norm()};
              const std::array<double, 4> scale
                = {std::abs(va), ga.norm(), ha.norm(), ta.norm()};
              for (int r = 0; r < 4; ++r)
                if (r <= k)
                  {
                    jump[r] = std::max(jump[r], diff[r]);
                    size[r] = std::max(size[r], scale[r]);
                  }
            }
        }
    }
  out << name << ": smallest continuity C^" << min_k
      << "; relative jumps of derivatives of order r <= k (C^k at that face)"
      << " across every interior face, r = 0.." << std::min(min_k, 3u) << ":";
  for (unsigned int r = 0; r <= std::min(min_k, 3u); ++r)
    out << ' ' << bound(jump[r] / size[r]);
  out << "\n";
}

int
main()
{
  for (unsigned int p = 1; p <= 6; ++p)
    check_1d_open(KnotVector::uniform(p, 5, 0, 1), "uniform open");
  for (unsigned int p = 2; p <= 6; ++p)
    {
      std::vector<int> k = {int(p) - 1, 0, int(p) / 2, int(p) - 2};
      check_1d_open(KnotVector(p, {0, 0.1, 0.35, 0.4, 0.8, 1.0}, k),
                    "non-uniform, C^(p-1),C^0,C^(p/2),C^(p-2)");
    }

  // Spec SP1.
  const KnotVector sp1(2, {0, 0.25, 0.5, 0.75, 1});
  const auto       values = sp1.evaluate_on_element(2, 0.625, 0)[0];
  out << "SP1: non-zero functions at 0.625:";
  for (unsigned int j = 0; j < 3; ++j)
    out << " N_" << sp1.global_index(2, j) << "=" << values[j];
  out << "\n";

  for (unsigned int p = 1; p <= 6; ++p)
    {
      const KnotVector x = KnotVector::uniform(p, 4, 0, 1);
      const KnotVector y(p, {0, 0.2, 0.5, 0.6, 1}, {int(p) - 1, 0, int(p) - 1});
      check_continuity<2>(SplineSpace<2>(std::array<KnotVector, 2>{{x, y}}),
                          "2D open, p=" + std::to_string(p));
      const KnotVector z = KnotVector::uniform(p, p + 2, 0, 2, -1, true);
      check_continuity<2>(SplineSpace<2>(std::array<KnotVector, 2>{{z, x}}),
                          "2D periodic in x, p=" + std::to_string(p));
    }
  const KnotVector c3 = KnotVector::uniform(3, 3, 0, 1);
  check_continuity<3>(SplineSpace<3>(std::array<KnotVector, 3>{{c3, c3, c3}}),
                      "3D cubic");

  // Partition of unity in 2D with a periodic direction, at quadrature points.
  {
    const KnotVector     z = KnotVector::uniform(3, 5, 0, 1, -1, true);
    const KnotVector     x(3, {0, 0.3, 0.5, 1.0}, {2, 1});
    const SplineSpace<2> s(std::array<KnotVector, 2>{{z, x}});
    SplineCellValues<2>  v(s, nullptr, QGauss<1>(4), 1);
    double               pu = 0, g = 0;
    for (unsigned int e = 0; e < s.n_elements(); ++e)
      {
        v.reinit(e);
        for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
          {
            double       sum = 0;
            Tensor<1, 2> gs;
            for (unsigned int j = 0; j < v.n_basis_per_element(); ++j)
              {
                sum += v.shape_value(j, q);
                gs += v.shape_grad(j, q);
              }
            pu = std::max(pu, std::abs(sum - 1));
            g  = std::max(g, gs.norm());
          }
      }
    out << "2D periodic x open: functions " << s.n_basis() << " (= 5 x 6), "
        << "|sum-1| " << bound(pu) << ", |sum grad| " << bound(g) << "\n";
  }
}
