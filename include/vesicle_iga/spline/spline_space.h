#pragma once

#include <deal.II/base/point.h>

#include <vesicle_iga/spline/knot_vector.h>

#include <array>
#include <vector>

namespace vesicle_iga
{

  /**
   * The tensor-product spline space S = S_1 x ... x S_dim over the
   * parametric box formed by the breakpoints of the univariate spaces
   * (spec section 2.1). Elements and basis functions are numbered
   * lexicographically with the first direction running fastest; this
   * numbering is only the "natural" one, the parallel numbering of the
   * unknowns lives in SplineDofHandler.
   */
  template <int dim>
  class SplineSpace
  {
  public:
    explicit SplineSpace(const std::array<KnotVector, dim> &knot_vectors);

    const KnotVector &
    knot_vector(const unsigned int d) const
    {
      return kv[d];
    }
    const std::array<KnotVector, dim> &
    knot_vectors() const
    {
      return kv;
    }

    unsigned int
    n_basis() const
    {
      return n_functions;
    }
    unsigned int
    n_elements() const
    {
      return n_elems;
    }
    /// Number of basis functions that do not vanish on one element.
    unsigned int
    n_basis_per_element() const
    {
      return n_per_element;
    }

    std::array<unsigned int, dim>
    element_multi_index(const unsigned int e) const;
    unsigned int
    element_index(const std::array<unsigned int, dim> &multi_index) const;

    std::array<unsigned int, dim>
    basis_multi_index(const unsigned int i) const;
    unsigned int
    basis_index(const std::array<unsigned int, dim> &multi_index) const;

    /// The natural indices of the basis functions on element e, local
    /// numbering lexicographic (first direction fastest).
    void
    element_basis_indices(const unsigned int         e,
                          std::vector<unsigned int> &indices) const;

    /// Lower corner and lengths of element e in parametric coordinates.
    dealii::Point<dim>
    element_lower_corner(const unsigned int e) const;
    dealii::Tensor<1, dim>
    element_lengths(const unsigned int e) const;

    /// The element that contains the parametric point xi.
    unsigned int
    find_element(const dealii::Point<dim> &xi) const;

    /// Greville point of basis function i (tensor of univariate abscissae).
    dealii::Point<dim>
    greville_point(const unsigned int i) const;

    /// Whether element e touches the boundary face with deal.II face number
    /// f = 2*direction + side of the parametric box (never for periodic
    /// directions).
    bool
    element_at_face(const unsigned int e, const unsigned int face) const;

    /// Whether basis function i belongs to the layer-th layer (0: the
    /// functions whose trace on the face is non-zero, 1: the next one inward)
    /// at the face f of an open direction.
    bool
    basis_in_face_layer(const unsigned int i,
                        const unsigned int face,
                        const unsigned int layer) const;

    /// Evaluate sum_i c_i N_i at a parametric point (Cox-de Boor), with the
    /// coefficients in natural numbering and n_components values per basis
    /// function (component fastest). Used for geometry, not in assembly.
    void
    evaluate(const std::vector<double> &coefficients,
             const unsigned int         n_components,
             const dealii::Point<dim>  &xi,
             std::vector<double>       &values) const;

    /// The same sum on element @p e only, from the element's own
    /// coefficients (one component, local numbering of
    /// element_basis_indices()): what a rank can evaluate on its own
    /// elements without the whole field. @p xi may lie on the element's
    /// boundary.
    double
    evaluate_on_element(const unsigned int         e,
                        const std::vector<double> &element_coefficients,
                        const dealii::Point<dim>  &xi) const;

    /// Same knot vectors in every direction?
    bool
    operator==(const SplineSpace<dim> &other) const;

    /// The space with every direction h-refined, degree-elevated...
    SplineSpace<dim>
    h_refined(const unsigned int times = 1) const;
    SplineSpace<dim>
    degree_elevated(const unsigned int by) const;

  private:
    std::array<KnotVector, dim> kv;
    /// The Greville abscissae of every direction (greville_point() is
    /// called once per basis function by the set-up of every field).
    std::array<std::vector<double>, dim> greville;
    unsigned int                         n_functions;
    unsigned int                         n_elems;
    unsigned int                         n_per_element;
  };

  /**
   * Coefficients (natural numbering, n_components per function, component
   * fastest) of the interpolant in @p space of a field given by its values
   * at the tensor grid of Greville points (same ordering as the basis).
   * Schoenberg-Whitney holds at the Greville abscissae, so the collocation
   * matrices are invertible; a field that lies in the space is reproduced
   * exactly (to round-off). Solved direction by direction.
   */
  template <int dim>
  std::vector<double>
  interpolate_at_greville_points(const SplineSpace<dim>    &space,
                                 const std::vector<double> &values,
                                 const unsigned int         n_components);
} // namespace vesicle_iga
