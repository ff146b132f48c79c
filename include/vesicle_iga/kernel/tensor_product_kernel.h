#pragma once

#include <vesicle_iga/kernel/derivative.h>
#include <vesicle_iga/spline/tensor_product_factors.h>

#include <array>
#include <cstddef>
#include <vector>

namespace vesicle_iga
{
  /**
   * Sum factorisation on an axis-aligned element (doc/engine.md, "The
   * kernel"): evaluation of the plain derivatives of a field at the
   * quadrature points, integration of a residual against derivatives of
   * the test functions, and integration of a matrix block
   *   A_ij = sum_q D^a N_i(q) C_ab(q) D^b M_j(q)
   * for a list of derivative pairs (a, b), with N the test and M the trial
   * basis (their spaces may differ). A derivative D^a of the tensor-product
   * basis is the product of univariate derivatives of orders a_d, so each
   * operation is a sequence of one-dimensional contractions: an element
   * matrix costs O((p+1)^{2 dim} n_q1) per distinct derivative pair instead
   * of O((p+1)^{2 dim} n_q1^dim) with full basis tables. Derivatives that
   * share the orders of the later contractions share them: pairs are sorted
   * so that the expensive last contraction is done once per distinct pair of
   * orders of direction 0.
   *
   * No allocation happens per element once a Workspace has grown to the
   * largest element.
   */
  template <int dim>
  class TensorProductKernel
  {
  public:
    /// Buffers reused from element to element (one per thread).
    struct Workspace
    {
      std::array<std::vector<double>, dim + 1>             stage;
      std::vector<double>                                  accumulated, product;
      std::array<std::array<std::vector<double>, 16>, dim> products;
      std::array<unsigned int, dim>                        product_valid{};
    };

    /// out[k][q] = sum_i u_i D^{derivatives[k]} N_i(q) for plain derivatives.
    static void
    evaluate(const TensorProductFactors<dim> &f,
             const double                    *u,
             const std::vector<unsigned int> &derivatives,
             double *const                   *out,
             Workspace                       &ws);

    /// One term of a residual: the coefficient c(q) (quadrature weight
    /// included) of the plain derivative D^derivative of the test function.
    struct Atom
    {
      unsigned int  derivative;
      const double *coefficient;
    };
    /// rhs_i += sum_atoms sum_q D^a N_i(q) c_a(q).
    static void
    integrate(const TensorProductFactors<dim> &f,
              std::vector<Atom>               &atoms,
              double                          *rhs,
              Workspace                       &ws);

    /// One term of a matrix block: C(q) (quadrature weight included) of
    /// the plain derivatives (test, trial).
    struct Pair
    {
      unsigned int  test, trial;
      const double *coefficient;
    };
    /// A(i, j) += sum over pairs of sum_q D^a N_i C(q) D^b M_j, A stored
    /// row-major with @p row_stride. With @p symmetric (same space on both
    /// sides and every pair (a, b, C) has its partner (b, a, C)) only the
    /// blocks on and above the diagonal are contracted and then mirrored.
    static void
    integrate_matrix(const TensorProductFactors<dim> &test,
                     const TensorProductFactors<dim> &trial,
                     std::vector<Pair>               &pairs,
                     const bool                       symmetric,
                     double                          *A,
                     const std::size_t                row_stride,
                     Workspace                       &ws);

    /// Quadrature weight times element measure at every point.
    static void
    weights(const TensorProductFactors<dim> &f, std::vector<double> &JxW);
  };
} // namespace vesicle_iga
