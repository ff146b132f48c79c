#pragma once

#include <array>
#include <vector>

namespace vesicle_iga
{
  /**
   * The univariate factors of a tensor-product spline basis on one element
   * (or face) of an axis-aligned box (no geometry map): for every direction
   * d the r-th physical derivative (r = 0..max_order) of the p_d + 1
   * univariate B-splines of the element at the n_d quadrature abscissae,
   * and the quadrature weights times the element length. The basis
   * function with local multi-index (i_0, .., i_{dim-1}) is
   * prod_d N_{d, i_d}; local indices and quadrature points are
   * lexicographic, first direction fastest (as in SplineCellValues). On a
   * face the normal direction has one abscissa (0 or 1) of weight 1.
   */
  template <int dim>
  struct TensorProductFactors
  {
    unsigned int                         max_order = 0;
    std::array<unsigned int, dim>        n_basis{}, n_points{};
    std::array<std::vector<double>, dim> shape;   // [(r n_d + q) (p+1) + j]
    std::array<std::vector<double>, dim> weights; // w_q h_d
    /// Physical coordinate of every abscissa along each direction.
    std::array<std::vector<double>, dim> points;

    double
    operator()(const unsigned int d,
               const unsigned int r,
               const unsigned int q,
               const unsigned int j) const
    {
      return shape[d][(r * n_points[d] + q) * n_basis[d] + j];
    }
    /// The n_points[d] x n_basis[d] table of the r-th derivatives along d.
    const double *
    table(const unsigned int d, const unsigned int r) const
    {
      return shape[d].data() + r * n_points[d] * n_basis[d];
    }
    unsigned int
    n_quadrature_points() const
    {
      unsigned int n = 1;
      for (unsigned int d = 0; d < dim; ++d)
        n *= n_points[d];
      return n;
    }
    unsigned int
    n_basis_functions() const
    {
      unsigned int n = 1;
      for (unsigned int d = 0; d < dim; ++d)
        n *= n_basis[d];
      return n;
    }
  };
} // namespace vesicle_iga
