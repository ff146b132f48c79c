#pragma once

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace vesicle_iga
{
  using namespace dealii;

  /**
   * The univariate factors of a tensor-product spline basis on one element
   * of an axis-aligned box (no geometry map): for every direction d the
   * r-th physical derivative (r = 0..max_order) of the p_d + 1 univariate
   * B-splines of the element at the n_d quadrature abscissae, and the
   * quadrature weights times the element length. The basis function with
   * local multi-index (i_0, .., i_{dim-1}) is prod_d N_{d, i_d}; local
   * indices and quadrature points are lexicographic, first direction
   * fastest (as in SplineCellValues).
   */
  template <int dim>
  struct TensorProductFactors
  {
    unsigned int                         max_order = 0;
    std::array<unsigned int, dim>        n_basis{}, n_points{};
    std::array<std::vector<double>, dim> shape;   // [(r n_d + q) (p+1) + j]
    std::array<std::vector<double>, dim> weights; // w_q h_d

    double
    operator()(const unsigned int d,
               const unsigned int r,
               const unsigned int q,
               const unsigned int j) const
    {
      return shape[d][(r * n_points[d] + q) * n_basis[d] + j];
    }
  };

  /**
   * Sum factorisation on the factors above (doc/splines.md, "Assembly by
   * sum factorisation"). A quantity of the weak forms of spec Parts E and H
   * is built from "atoms", the separable derivatives of a basis function
   * N_i: its value, its first derivative along x_d and its second
   * derivative along x_d (the Laplacian is the sum of the last dim atoms).
   * With these, an element matrix sum_q D^a N_i(q) C_ab(q) D^b N_j(q)
   * costs O((p+1)^{2 dim} n_q1) per atom pair instead of
   * O((p+1)^{2 dim} n_q1^dim): for cubic splines in 3D with 6^3 points, 13
   * times less for the Willmore tangent. Pairs that share the derivative
   * orders of the outer directions share the outer contractions.
   */
  template <int dim>
  class SumFactorization
  {
  public:
    static constexpr unsigned int n_atoms    = 1 + 2 * dim;
    static constexpr unsigned int value_atom = 0;
    static constexpr unsigned int
    gradient_atom(const unsigned int d)
    {
      return 1 + d;
    }
    static constexpr unsigned int
    second_derivative_atom(const unsigned int d)
    {
      return 1 + dim + d;
    }
    /// Derivative order of atom a along direction d.
    static unsigned int
    order(const unsigned int a, const unsigned int d);

    /// Values of the atoms of a field (or coefficients of a functional),
    /// [atom][quadrature point].
    using AtomValues = std::array<std::vector<double>, n_atoms>;

    /// One term of an element matrix: sum_q D^a N_i C(q) D^b N_j, with
    /// the quadrature weight included in C.
    struct AtomPair
    {
      unsigned int        test_atom, trial_atom;
      std::vector<double> coefficient;
    };

    explicit SumFactorization(const TensorProductFactors<dim> &factors);

    unsigned int
    n_quadrature_points() const;
    unsigned int
    n_basis() const;
    /// Quadrature weight (times the element volume) of point q.
    double
    JxW(const unsigned int q) const;

    /// out[a][q] = sum_i u_i D^a N_i(q) for the atoms with wanted[a].
    void
    evaluate(const std::vector<double>       &local,
             const std::array<bool, n_atoms> &wanted,
             AtomValues                      &out) const;

    /// rhs_i += sum_q sum_a D^a N_i(q) c[a][q] over the atoms with
    /// used[a] (c contains the quadrature weights).
    void
    integrate(const AtomValues                &c,
              const std::array<bool, n_atoms> &used,
              Vector<double>                  &rhs) const;

    /// matrix_ij += sum over the pairs of sum_q D^a N_i C(q) D^b N_j.
    /// With @p symmetric (the caller knows that the sum is a symmetric
    /// matrix: every pair (a, b, C) has its partner (b, a, C)) only the
    /// blocks on and above the diagonal are contracted and then mirrored.
    void
    integrate_matrix(const std::vector<const AtomPair *> &pairs,
                     FullMatrix<double>                  &matrix,
                     const bool symmetric = false) const;

  private:
    const TensorProductFactors<dim> &f;
  };
} // namespace vesicle_iga
