// Sum factorisation (kernel/tensor_product_kernel) against direct
// quadrature with the full basis tables of SplineCellValues, for every
// plain derivative up to third order including the mixed ones
// (Derivative<dim>), on an interior and a boundary element and on a
// boundary face of non-uniform knot vectors, p = 2 and 3, in 2D and 3D:
//  - evaluate: D^a u(q) for all derivatives a at once;
//  - integrate: sum_q sum_a D^a N_i(q) c_a(q) with random c for all a;
//  - integrate_matrix: sum_q D^a N_i C_ab(q) D^b M_j with random C for
//    random pairs (a, b), with N and M of different spaces (degree p and
//    p + 1 on the same breakpoints), the same on one space, and a
//    symmetric set on one space with the symmetric shortcut.
// With p + 1 and p + 2 Gauss points per direction: on one space these are
// the sizes of the kernel's fixed-size (unrolled) stages, between two
// spaces and on faces those of the general stages.
// Both sides compute the same sums in another order: they must agree to
// round-off ("ok" below 1e-12 relative to the largest entry). A wrong
// factor of any derivative, a wrong index map between the two spaces or
// a wrong grouping of shared contractions gives differences of order one.

#include <deal.II/base/quadrature_lib.h>

#include <vesicle_iga/kernel/tensor_product_kernel.h>
#include <vesicle_iga/spline/spline_cell_values.h>

#include <cmath>
#include <fstream>
#include <random>

using namespace vesicle_iga;
using namespace dealii;

std::ofstream out("output");

template <int dim>
double
derivative(const SplineCellValues<dim> &v,
           const unsigned int           a,
           const unsigned int           i,
           const unsigned int           q)
{
  const auto                  o = Derivative<dim>::orders(a);
  std::array<unsigned int, 3> k{};
  unsigned int                n = 0;
  for (unsigned int d = 0; d < dim; ++d)
    for (unsigned int r = 0; r < o[d]; ++r)
      k[n++] = d;
  if (n == 0)
    return v.shape_value(i, q);
  if (n == 1)
    return v.shape_grad(i, q)[k[0]];
  if (n == 2)
    return v.shape_hessian(i, q)[k[0]][k[1]];
  return v.shape_3rd_derivative(i, q)[k[0]][k[1]][k[2]];
}

std::string
verdict(const double difference, const double scale)
{
  return difference <= 1e-12 * scale ? "ok" : "FAILED";
}

/// The verdict on sum_q D^a N_i C(q) D^b M_j by the kernel (@p pairs, on
/// the factors of @p v and @p w) against the full basis tables.
template <int dim>
std::string
check_matrix(const SplineCellValues<dim>                         &v,
             const SplineCellValues<dim>                         &w,
             std::vector<typename TensorProductKernel<dim>::Pair> pairs,
             const bool                                           symmetric,
             typename TensorProductKernel<dim>::Workspace        &ws)
{
  const auto          reference = pairs;
  const unsigned int  n = v.n_basis_per_element(), m = w.n_basis_per_element();
  std::vector<double> A(n * m, 0.);
  TensorProductKernel<dim>::integrate_matrix(v.tensor_product_factors(),
                                             w.tensor_product_factors(),
                                             pairs,
                                             symmetric,
                                             A.data(),
                                             m,
                                             ws);
  double difference = 0, scale = 0;
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < m; ++j)
      {
        double s = 0;
        for (const auto &pair : reference)
          for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
            s += derivative(v, pair.test, i, q) * pair.coefficient[q]
                 * derivative(w, pair.trial, j, q);
        difference = std::max(difference, std::abs(s - A[i * m + j]));
        scale      = std::max(scale, std::abs(s));
      }
  return verdict(difference, scale);
}

template <int dim>
void
check(const unsigned int p,
      const unsigned int element_choice,
      const int          face,
      const unsigned int n_points)
{
  using K = TensorProductKernel<dim>;
  using D = Derivative<dim>;
  std::mt19937                           rng(17 + p + dim);
  std::uniform_real_distribution<double> U(-1., 1.);
  std::array<KnotVector, dim>            kv, kv2;
  for (unsigned int d = 0; d < dim; ++d)
    {
      const std::vector<double> z{0., 0.3, 0.45, 0.7, 1.2, 1.5 + 0.1 * d};
      kv[d]  = KnotVector(p, z);
      kv2[d] = KnotVector(p + 1, z);
    }
  const SplineSpace<dim> space(kv), space2(kv2);
  SplineCellValues<dim>  v(space, nullptr, QGauss<1>(n_points), 3);
  SplineCellValues<dim>  w(space2, nullptr, QGauss<1>(n_points), 3);
  const unsigned int     e = element_choice == 0 ? 0 : space.n_elements() / 2;
  if (face < 0)
    {
      v.reinit(e);
      w.reinit(e);
    }
  else
    {
      v.reinit_face(e, face);
      w.reinit_face(e, face);
    }
  const auto           &f  = v.tensor_product_factors();
  const unsigned int    n  = v.n_basis_per_element();
  const unsigned int    nq = v.n_quadrature_points();
  typename K::Workspace ws;

  // evaluate, all plain derivatives at once
  std::vector<double> u(n);
  for (auto &c : u)
    c = U(rng);
  std::vector<unsigned int> all;
  for (unsigned int a = 0; a < D::n_plain; ++a)
    all.push_back(a);
  std::vector<std::vector<double>> values(D::n_plain, std::vector<double>(nq));
  std::vector<double *>            pointers;
  for (auto &x : values)
    pointers.push_back(x.data());
  K::evaluate(f, u.data(), all, pointers.data(), ws);
  double diff = 0, scale = 0;
  for (unsigned int a = 0; a < D::n_plain; ++a)
    for (unsigned int q = 0; q < nq; ++q)
      {
        double s = 0;
        for (unsigned int i = 0; i < n; ++i)
          s += u[i] * derivative(v, a, i, q);
        diff  = std::max(diff, std::abs(s - values[a][q]));
        scale = std::max(scale, std::abs(s));
      }
  out << dim << "D p=" << p << " q=" << n_points << " element " << e
      << (face >= 0 ? " face " + std::to_string(face) : std::string())
      << ": evaluate " << verdict(diff, scale);

  // integrate
  std::vector<std::vector<double>> c(D::n_plain, std::vector<double>(nq));
  std::vector<typename K::Atom>    atoms;
  for (unsigned int a = 0; a < D::n_plain; ++a)
    {
      for (auto &x : c[a])
        x = U(rng);
      atoms.push_back({a, c[a].data()});
    }
  std::vector<double> rhs(n, 0.);
  K::integrate(f, atoms, rhs.data(), ws);
  diff = scale = 0;
  for (unsigned int i = 0; i < n; ++i)
    {
      double s = 0;
      for (unsigned int a = 0; a < D::n_plain; ++a)
        for (unsigned int q = 0; q < nq; ++q)
          s += derivative(v, a, i, q) * c[a][q];
      diff  = std::max(diff, std::abs(s - rhs[i]));
      scale = std::max(scale, std::abs(s));
    }
  out << ", integrate " << verdict(diff, scale);

  // integrate_matrix: random pairs between the two spaces
  std::vector<typename K::Pair>    pairs;
  std::vector<std::vector<double>> C;
  for (unsigned int k = 0; k < 3 * D::n_plain; ++k)
    {
      C.emplace_back(nq);
      for (auto &x : C.back())
        x = U(rng);
    }
  for (unsigned int k = 0; k < C.size(); ++k)
    pairs.push_back({static_cast<unsigned int>(rng() % D::n_plain),
                     static_cast<unsigned int>(rng() % D::n_plain),
                     C[k].data()});
  out << ", matrix " << check_matrix(v, w, pairs, false, ws)
      << ", one-space matrix " << check_matrix(v, v, pairs, false, ws);

  // symmetric set on one space: (a, b, C) and (b, a, C)
  pairs.clear();
  for (unsigned int k = 0; k < 8; ++k)
    {
      const unsigned int a = rng() % D::n_plain, b = rng() % D::n_plain;
      pairs.push_back({a, b, C[k].data()});
      if (a != b)
        pairs.push_back({b, a, C[k].data()});
    }
  out << ", symmetric matrix " << check_matrix(v, v, pairs, true, ws)
      << std::endl;
}

int
main()
{
  for (const unsigned int p : {2u, 3u})
    for (const unsigned int extra : {1u, 2u})
      for (const unsigned int e : {0u, 1u})
        {
          check<2>(p, e, -1, p + extra);
          check<3>(p, e, -1, p + extra);
        }
  check<2>(3, 0, 1, 5);
  check<3>(2, 0, 4, 4);
  check<3>(3, 0, 0, 5);
}
