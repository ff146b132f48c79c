#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>

#include <vesicle_iga/spline/nurbs_geometry.h>
#include <vesicle_iga/spline/spline_space.h>
#include <vesicle_iga/spline/tensor_product_factors.h>

#include <array>
#include <memory>
#include <vector>

namespace vesicle_iga
{
  /**
   * The FEValues of a spline space: values, gradients, Hessians and third
   * derivatives of the basis functions that live on one element, in physical
   * coordinates, at the points of a tensor-product rule.
   *
   * How they are built (doc/splines.md): on element e the local B-splines are
   * N_j = sum_a C^e_ja B_a with B_a the Bernstein polynomials (taken from
   * deal.II's FE_Bernstein<1>) and C^e the element's Bezier extraction
   * operator, which for a tensor-product space is the Kronecker product of
   * the univariate operators; it is applied direction by direction (sum
   * factorisation) rather than as a (p+1)^d x (p+1)^d matrix. With a NURBS
   * geometry on the same space the rational basis R_j = w_j N_j / W and the
   * map x = sum R_j P_j follow by the quotient rule, and physical
   * derivatives by the chain rule up to third order. Without a geometry the
   * parametric coordinates are the physical ones (axis-aligned boxes, the
   * case of spec Parts E and H, graded or not): then the chain rule is the
   * identity and costs nothing.
   *
   * One object serves cells (reinit), faces (reinit_face: the quadrature of
   * the other directions with the normal coordinate fixed) and arbitrary
   * tensor grids of points (reinit_points, for output and point values).
   */
  template <int dim>
  class SplineCellValues
  {
  public:
    /**
     * @p max_derivative: 0..3, the highest derivative order that is needed;
     * higher orders cost more. @p geometry may be null (identity map); if it
     * is given it must be defined on @p space. Without @p with_shape_tables
     * (and without geometry) only the univariate factors and JxW are
     * computed: the input of sum factorisation, a small fraction of the
     * cost of the full tables.
     */
    SplineCellValues(const SplineSpace<dim>                   &space,
                     std::shared_ptr<const NurbsGeometry<dim>> geometry,
                     const dealii::Quadrature<1>              &quadrature_1d,
                     const unsigned int                        max_derivative,
                     const bool with_shape_tables = true);

    void
    reinit(const unsigned int element);
    void
    reinit_face(const unsigned int element, const unsigned int face);
    /// Points given per direction in unit coordinates [0,1] of the element;
    /// the weights are set to one.
    void
    reinit_points(const unsigned int                          element,
                  const std::array<std::vector<double>, dim> &unit_points);

    unsigned int
    n_quadrature_points() const
    {
      return n_q;
    }
    unsigned int
    n_basis_per_element() const
    {
      return n_local;
    }
    unsigned int
    element() const
    {
      return current_element;
    }
    /// Natural indices of the local basis functions.
    const std::vector<unsigned int> &
    basis_indices() const
    {
      return indices;
    }

    double
    shape_value(const unsigned int i, const unsigned int q) const
    {
      return values[q * n_local + i];
    }
    const dealii::Tensor<1, dim> &
    shape_grad(const unsigned int i, const unsigned int q) const
    {
      return grads[q * n_local + i];
    }
    const dealii::Tensor<2, dim> &
    shape_hessian(const unsigned int i, const unsigned int q) const
    {
      return hessians[q * n_local + i];
    }
    const dealii::Tensor<3, dim> &
    shape_3rd_derivative(const unsigned int i, const unsigned int q) const
    {
      return thirds[q * n_local + i];
    }
    double
    shape_laplacian(const unsigned int i, const unsigned int q) const
    {
      return trace(hessians[q * n_local + i]);
    }

    double
    JxW(const unsigned int q) const
    {
      return jxw[q];
    }
    const dealii::Point<dim> &
    quadrature_point(const unsigned int q) const
    {
      return points[q];
    }
    /// Parametric point of quadrature point q.
    const dealii::Point<dim> &
    parametric_point(const unsigned int q) const
    {
      return xi[q];
    }
    /// Outward unit normal (faces only).
    const dealii::Tensor<1, dim> &
    normal_vector(const unsigned int q) const
    {
      return normals[q];
    }
    /// The univariate factors of the basis on the current element (axis-
    /// aligned boxes only: without a geometry the tensor-product basis and
    /// its physical derivatives factor direction by direction).
    const TensorProductFactors<dim> &
    tensor_product_factors() const
    {
      Assert(!geometry,
             dealii::ExcMessage(
               "The basis factors only without a geometry map."));
      return univariate;
    }

    /// Element metric tensor G of spec eq. (N1), parent element [-1,1]^d.
    const dealii::Tensor<2, dim> &
    metric_tensor(const unsigned int q) const
    {
      return metric[q];
    }
    /// Element size normal to the current face, h_n = 2/sqrt(n.G.n)
    /// (the element width in the normal direction on a box).
    double
    normal_element_size(const unsigned int q) const;

    /// Field values and derivatives from local coefficients (one per local
    /// basis function, ordered as basis_indices()).
    double
    value(const std::vector<double> &local, const unsigned int q) const;
    dealii::Tensor<1, dim>
    gradient(const std::vector<double> &local, const unsigned int q) const;
    dealii::Tensor<2, dim>
    hessian(const std::vector<double> &local, const unsigned int q) const;

  private:
    struct BernsteinTable
    {
      std::vector<double>              points;
      std::vector<std::vector<double>> table; // [r][q*(p+1)+a]
    };
    BernsteinTable
    make_table(const unsigned int d, const std::vector<double> &pts) const;

    void
    compute(const unsigned int                                  element,
            const std::array<const BernsteinTable *, dim>      &tables,
            const std::array<const std::vector<double> *, dim> &weights,
            const int                                           face);
    /// The univariate B-spline derivatives N = C B / h^r of the element.
    void
    compute_univariate(const std::array<const BernsteinTable *, dim>      &tab,
                       const std::array<const std::vector<double> *, dim> &wts,
                       const int face);
    /// Parametric derivatives (orders 0..3) of the tensor-product basis at
    /// the point with multi-index @p qm into v, g, H, T.
    void
    parametric_derivatives(const std::array<unsigned int, dim> &qm);
    /// The rational basis R_j = w_j N_j / W by the quotient rule (order 3),
    /// in place on v, g, H, T.
    void
    apply_weights();
    /// The physical derivatives at point q from the parametric ones through
    /// the geometry map (chain rule up to third order); returns J^{-1} and
    /// det J.
    double
    map_to_physical(const unsigned int q, dealii::Tensor<2, dim> &Jinv);
    /// Per-point scratch: parametric derivatives of the local basis.
    std::vector<double>                 v;
    std::vector<dealii::Tensor<1, dim>> g;
    std::vector<dealii::Tensor<2, dim>> H;
    std::vector<dealii::Tensor<3, dim>> T;

    const SplineSpace<dim>                   &space;
    std::shared_ptr<const NurbsGeometry<dim>> geometry;
    const unsigned int                        order;
    const bool                                shape_tables;
    TensorProductFactors<dim>                 univariate;
    std::vector<double>                       q_weights;
    std::vector<double>                       unit_weight{1.};

    // Per direction: quadrature points, the point 0 and the point 1.
    std::array<std::array<BernsteinTable, 3>, dim> tables;
    std::array<BernsteinTable, dim>                custom;

    unsigned int              n_local;
    unsigned int              n_q             = 0;
    unsigned int              current_element = 0;
    std::vector<unsigned int> indices;

    std::vector<double>                 values;
    std::vector<dealii::Tensor<1, dim>> grads;
    std::vector<dealii::Tensor<2, dim>> hessians;
    std::vector<dealii::Tensor<3, dim>> thirds;
    std::vector<double>                 jxw;
    std::vector<dealii::Point<dim>>     points, xi;
    std::vector<dealii::Tensor<1, dim>> normals;
    std::vector<dealii::Tensor<2, dim>> metric;
  };
} // namespace vesicle_iga
