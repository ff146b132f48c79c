#pragma once

#include <array>

namespace vesicle_iga
{
  /**
   * The partial derivatives of a scalar field that the weak forms use, up
   * to third order and including every mixed one, numbered 0 .. n - 1 in
   * the order: value; d/dx_k (k = 0..dim-1); the second derivatives
   * d^2/dx_k dx_l (k <= l) in lexicographic order; the third derivatives
   * (k <= l <= m) in lexicographic order. dim = 2: 1 + 2 + 3 + 4 = 10,
   * dim = 3: 1 + 3 + 6 + 10 = 20.
   *
   * A derivative of a tensor-product spline factors direction by direction,
   * D^alpha N_i = prod_d N_{d,i_d}^{(alpha_d)}, which is what makes every one
   * of them available to sum factorisation (kernel/tensor_product_kernel.h)
   * at the cost of the univariate derivatives of order alpha_d.
   *
   * Two combined derivatives are also numbered: the Laplacian (index n) and
   * the gradient of the Laplacian (n + 1 + k): a term that declares one
   * gets the sum of the pure derivatives it stands for, and a coefficient it
   * writes for one is applied to each of them.
   */
  template <int dim>
  struct Derivative
  {
    static_assert(dim == 2 || dim == 3, "Derivatives for dim = 2, 3.");

    /// Number of plain derivatives (orders 0..3).
    static constexpr unsigned int n_plain = dim == 2 ? 10 : 20;
    /// The Laplacian and the dim components of its gradient.
    static constexpr unsigned int laplacian = n_plain;
    static constexpr unsigned int
    gradient_of_laplacian(const unsigned int k)
    {
      return n_plain + 1 + k;
    }
    static constexpr unsigned int n_all = n_plain + 1 + dim;

    static constexpr unsigned int value = 0;
    static constexpr unsigned int
    gradient(const unsigned int k)
    {
      return 1 + k;
    }
    static constexpr unsigned int
    hessian(const unsigned int k, const unsigned int l)
    {
      return index_of(k < l ? k : l, k < l ? l : k, dim, 2);
    }
    static constexpr unsigned int
    third(const unsigned int k, const unsigned int l, const unsigned int m)
    {
      // Sort (k, l, m).
      unsigned int a = k, b = l, c = m, t = 0;
      if (a > b)
        t = a, a = b, b = t;
      if (b > c)
        t = b, b = c, c = t;
      if (a > b)
        t = a, a = b, b = t;
      return index_of3(a, b, c);
    }

    /// The order of derivative i along each direction (plain derivatives),
    /// from a table built at compile time.
    static std::array<unsigned int, dim>
    orders(const unsigned int i)
    {
      static constexpr auto table = make_order_table();
      return table[i];
    }

    /// Total order |alpha| of a plain derivative.
    static constexpr unsigned int
    total_order(const unsigned int i)
    {
      return i == 0 ?
               0 :
               (i <= dim ? 1 : (i < 1 + dim + dim * (dim + 1) / 2 ? 2 : 3));
    }

    /// The plain derivatives a combined one stands for (the derivative
    /// itself if it is plain); returns their number.
    static constexpr unsigned int
    expand(const unsigned int i, std::array<unsigned int, dim> &plain)
    {
      if (i < n_plain)
        {
          plain[0] = i;
          return 1;
        }
      for (unsigned int l = 0; l < dim; ++l)
        plain[l]
          = i == laplacian ? hessian(l, l) : third(i - n_plain - 1, l, l);
      return dim;
    }

  private:
    static constexpr std::array<std::array<unsigned int, dim>, n_plain>
    make_order_table()
    {
      std::array<std::array<unsigned int, dim>, n_plain> t{};
      for (unsigned int k = 0; k < dim; ++k)
        {
          t[gradient(k)][k] = 1;
          for (unsigned int l = k; l < dim; ++l)
            {
              ++t[hessian(k, l)][k];
              ++t[hessian(k, l)][l];
              for (unsigned int m = l; m < dim; ++m)
                {
                  ++t[third(k, l, m)][k];
                  ++t[third(k, l, m)][l];
                  ++t[third(k, l, m)][m];
                }
            }
        }
      return t;
    }
    static constexpr unsigned int
    index_of(const unsigned int k,
             const unsigned int l,
             const unsigned int d,
             const unsigned int)
    {
      // Second derivatives (k <= l), lexicographic, after value and
      // gradient.
      unsigned int i = 1 + d;
      for (unsigned int a = 0; a < d; ++a)
        for (unsigned int b = a; b < d; ++b, ++i)
          if (a == k && b == l)
            return i;
      return i;
    }
    static constexpr unsigned int
    index_of3(const unsigned int k, const unsigned int l, const unsigned int m)
    {
      unsigned int i = 1 + dim + dim * (dim + 1) / 2;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = a; b < dim; ++b)
          for (unsigned int c = b; c < dim; ++c, ++i)
            if (a == k && b == l && c == m)
              return i;
      return i;
    }
  };
} // namespace vesicle_iga
