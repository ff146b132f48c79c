// Sum factorisation (spline/sum_factorization) against the direct
// quadrature with the full basis tables of SplineCellValues, on an interior
// and a boundary element of non-uniform knot vectors, p = 2 and 3, in 2D
// and 3D:
//  - evaluate: D^a u(q) for all atoms a (value, d/dx_d, d^2/dx_d^2);
//  - integrate: sum_q sum_a D^a N_i(q) c_a(q) with random c;
//  - integrate_matrix: sum_q D^a N_i C_ab(q) D^b N_j for all atom pairs
//    with random C (non-symmetric), and a symmetric set with the
//    symmetric shortcut.
// Both sides compute the same sums in another order: they must agree to
// round-off ("ok" below 1e-12 relative to the largest entry).

#include <deal.II/base/quadrature_lib.h>

#include <vesicle_iga/spline/spline_cell_values.h>
#include <vesicle_iga/spline/sum_factorization.h>

#include <cmath>
#include <fstream>
#include <random>

using namespace vesicle_iga;

std::ofstream out("output");

template <int dim>
double
atom(const SplineCellValues<dim> &v,
     const unsigned int           a,
     const unsigned int           i,
     const unsigned int           q)
{
  using SF = SumFactorization<dim>;
  if (a == SF::value_atom)
    return v.shape_value(i, q);
  if (a <= dim)
    return v.shape_grad(i, q)[a - 1];
  return v.shape_hessian(i, q)[a - 1 - dim][a - 1 - dim];
}

std::string
verdict(const double difference, const double scale)
{
  return difference <= 1e-12 * scale ? "ok" : "FAILED";
}

template <int dim>
void
check(const unsigned int p, const unsigned int element_choice)
{
  using SF = SumFactorization<dim>;
  std::mt19937                           rng(17 + p + dim);
  std::uniform_real_distribution<double> U(-1., 1.);
  std::array<KnotVector, dim>            kv;
  for (unsigned int d = 0; d < dim; ++d)
    kv[d] = KnotVector(p, {0., 0.3, 0.45, 0.7, 1.2, 1.5 + 0.1 * d});
  const SplineSpace<dim> space(kv);
  SplineCellValues<dim>  v(space, nullptr, QGauss<1>(p + 2), 2);
  const unsigned int     e = element_choice == 0 ? 0 : space.n_elements() / 2;
  v.reinit(e);
  const SF           kernel(v.tensor_product_factors());
  const unsigned int n = v.n_basis_per_element(), nq = v.n_quadrature_points();

  std::vector<double> u(n);
  for (auto &x : u)
    x = U(rng);
  typename SF::AtomValues       values;
  std::array<bool, SF::n_atoms> all;
  all.fill(true);
  kernel.evaluate(u, all, values);
  double diff = 0, scale = 0;
  for (unsigned int a = 0; a < SF::n_atoms; ++a)
    for (unsigned int q = 0; q < nq; ++q)
      {
        double direct = 0;
        for (unsigned int i = 0; i < n; ++i)
          direct += u[i] * atom(v, a, i, q);
        diff  = std::max(diff, std::abs(direct - values[a][q]));
        scale = std::max(scale, std::abs(direct));
      }
  out << dim << "D p=" << p << " element " << e << ": evaluate "
      << verdict(diff, scale);

  typename SF::AtomValues c;
  for (auto &ca : c)
    {
      ca.resize(nq);
      for (auto &x : ca)
        x = U(rng);
    }
  Vector<double> rhs(n);
  kernel.integrate(c, all, rhs);
  diff = scale = 0;
  for (unsigned int i = 0; i < n; ++i)
    {
      double direct = 0;
      for (unsigned int q = 0; q < nq; ++q)
        for (unsigned int a = 0; a < SF::n_atoms; ++a)
          direct += atom(v, a, i, q) * c[a][q];
      diff  = std::max(diff, std::abs(direct - rhs(i)));
      scale = std::max(scale, std::abs(direct));
    }
  out << ", integrate " << verdict(diff, scale);

  for (const bool symmetric : {false, true})
    {
      std::vector<typename SF::AtomPair> pairs;
      for (unsigned int a = 0; a < SF::n_atoms; ++a)
        for (unsigned int b = 0; b < SF::n_atoms; ++b)
          {
            typename SF::AtomPair pair{a, b, std::vector<double>(nq)};
            for (auto &x : pair.coefficient)
              x = U(rng);
            pairs.push_back(pair);
          }
      if (symmetric)
        for (unsigned int a = 0; a < SF::n_atoms; ++a)
          for (unsigned int b = 0; b < a; ++b)
            pairs[a * SF::n_atoms + b].coefficient
              = pairs[b * SF::n_atoms + a].coefficient;
      std::vector<const typename SF::AtomPair *> pointers;
      for (const auto &pr : pairs)
        pointers.push_back(&pr);
      FullMatrix<double> A(n, n);
      kernel.integrate_matrix(pointers, A, symmetric);
      diff = scale = 0;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            double direct = 0;
            for (const auto &pr : pairs)
              for (unsigned int q = 0; q < nq; ++q)
                direct += atom(v, pr.test_atom, i, q) * pr.coefficient[q]
                          * atom(v, pr.trial_atom, j, q);
            diff  = std::max(diff, std::abs(direct - A(i, j)));
            scale = std::max(scale, std::abs(direct));
          }
      out << (symmetric ? ", symmetric matrix " : ", matrix ")
          << verdict(diff, scale);
    }
  out << std::endl;
}

int
main()
{
  for (unsigned int p = 2; p <= 3; ++p)
    for (unsigned int e = 0; e < 2; ++e)
      {
        check<2>(p, e);
        check<3>(p, e);
      }
}
