#pragma once

#include <array>
#include <string>
#include <vector>

namespace vesicle_iga
{
  /**
   * A univariate spline space of degree p on the breakpoints
   * a = z_0 < z_1 < ... < z_m = b, with continuity C^{k_j} at the interior
   * breakpoint z_j (spec section 2.1: a knot of multiplicity p - k gives
   * C^k). The space is either open (first and last knot repeated p+1 times,
   * which makes the end functions interpolatory) or periodic with period b - a
   * (then the continuity across the seam z_0 = z_m is @p seam_continuity).
   *
   * Internally the space is described by an extended knot vector t and an
   * index map: on the element [z_e, z_{e+1}] exactly p+1 B-splines of t are
   * non-zero, N_{s-p}, ..., N_s with s the knot span of the element, and the
   * basis function N_i of t is the basis function (i - offset) mod n of the
   * space (no wrap for open spaces). Everything else in the spline module
   * (Bezier extraction, tensor products, refinement) is built on this class.
   */
  class KnotVector
  {
  public:
    /// An empty space (only for containers; assign before use).
    KnotVector() = default;

    /**
     * @p continuity holds one entry per interior breakpoint; an empty vector
     * means maximal continuity C^{p-1} everywhere. Throws InputError (naming
     * @p name) for an empty or non-increasing breakpoint list, a continuity
     * outside 0 <= k <= p-1, or a periodic space with too few functions.
     */
    KnotVector(const unsigned int         degree,
               const std::vector<double> &breakpoints,
               const std::vector<int>    &continuity      = {},
               const bool                 periodic        = false,
               const int                  seam_continuity = -1,
               const std::string         &name            = "knot vector");

    /// Open knot vector with @p n_elements equal elements on [a,b], C^k.
    static KnotVector
    uniform(const unsigned int degree,
            const unsigned int n_elements,
            const double       a,
            const double       b,
            const int          continuity = -1,
            const bool         periodic   = false);

    unsigned int
    degree() const
    {
      return p;
    }
    unsigned int
    n_elements() const
    {
      return z.size() - 1;
    }
    unsigned int
    n_basis() const
    {
      return n_functions;
    }
    bool
    is_periodic() const
    {
      return periodic;
    }
    const std::vector<double> &
    breakpoints() const
    {
      return z;
    }
    /// Continuity at every interior breakpoint (and the seam, if periodic).
    const std::vector<int> &
    interior_continuity() const
    {
      return k;
    }
    int
    seam_continuity() const
    {
      return k_seam;
    }
    /// The knot vector in the usual sense (open spaces only: with repeated
    /// end knots); for periodic spaces the extended, unclamped vector.
    const std::vector<double> &
    knots() const
    {
      return t;
    }

    double
    element_left(const unsigned int e) const
    {
      return z[e];
    }
    double
    element_length(const unsigned int e) const
    {
      return z[e + 1] - z[e];
    }
    /// The element that contains x (the right one on a breakpoint, the last
    /// one at b).
    unsigned int
    find_element(const double x) const;

    /// Index (in the space, 0 <= i < n_basis()) of the local function j,
    /// 0 <= j <= p, of element e.
    unsigned int
    global_index(const unsigned int e, const unsigned int j) const;

    /**
     * Bezier extraction operator of element e: row j holds the Bernstein
     * coefficients of local function j on the element, N_j = sum_a C_ja B_a
     * with B_a the Bernstein polynomials of degree p on the element
     * (Borden et al. 2011). Computed once in the constructor.
     */
    const std::vector<std::array<double, 8>> &
    extraction(const unsigned int e) const
    {
      return C[e];
    }

    /**
     * Values and derivatives up to order @p n_derivatives of the p+1
     * functions that do not vanish on element e, at x, by the Cox-de Boor
     * recursion (spec eq. of section 2.1; the derivative form of
     * Piegl and Tiller, Algorithm A2.3). Result[r][j] = d^r N_j / dx^r.
     */
    std::vector<std::vector<double>>
    evaluate_on_element(const unsigned int e,
                        const double       x,
                        const unsigned int n_derivatives) const;

    /// Greville abscissae, one per basis function (for periodic spaces
    /// reduced into [a,b)).
    std::vector<double>
    greville_points() const;

    /// Insert the midpoint of every element r times (h-refinement); the
    /// new knots get the continuity C^{p-1}.
    KnotVector
    h_refined(const unsigned int times = 1) const;

    /// Every other breakpoint removed (z_0, z_2, z_4, ... and z_m, each
    /// kept breakpoint with its continuity): a space nested in this one,
    /// the next coarser level of the spline multigrid.
    KnotVector
    coarsened() const;
    /// Raise the degree by @p by keeping the continuity at every existing
    /// breakpoint (knot multiplicities raised by @p by).
    KnotVector
    degree_elevated(const unsigned int by) const;

  private:
    void
    build();

    unsigned int        p = 0;
    std::vector<double> z;
    std::vector<int>    k;
    bool                periodic = false;
    int                 k_seam   = 0;

    std::vector<double>       t;
    std::vector<unsigned int> span; // knot span index in t, per element
    int                       offset      = 0; // t-index of function 0
    unsigned int              n_functions = 0;
    std::vector<std::vector<std::array<double, 8>>> C;
  };

  /**
   * For nested spaces (the breakpoints of @p coarse are breakpoints of
   * @p fine with at most the same continuity): P with
   * N^coarse_j = sum_i P_ij N^fine_i (knot insertion), as dense rows
   * P[i][j], computed by interpolating each coarse function at the Greville
   * points of the fine space (exact, the coarse function lies in the fine
   * space); entries below 1e-14 are set to zero.
   */
  std::vector<std::vector<double>>
  prolongation_matrix(const KnotVector &coarse, const KnotVector &fine);

  /// Maximal supported degree (the extraction rows are stored in arrays of
  /// this size + 1).
  constexpr unsigned int max_spline_degree = 7;
} // namespace vesicle_iga
