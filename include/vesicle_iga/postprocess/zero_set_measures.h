#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/spline_dof_handler.h>
#include <vesicle_iga/spline/spline_space.h>

#include <vector>

namespace vesicle_iga
{
  /**
   * Sharp measures of the zero level set of a scalar spline field: the
   * size of the set {phi = 0} (a surface area in 3D, a length in 2D) and the
   * size of the region {phi < 0} that it encloses (a volume in 3D, an area
   * in 2D). These are what the diffuse functionals A and V of (E9)
   * approximate; issue 16, item 1 compares the two.
   */
  struct ZeroSetMeasures
  {
    /// Area of {phi = 0} in 3D, its length in 2D.
    double boundary = 0;
    /// Volume of {phi < 0} in 3D, its area in 2D.
    double inside = 0;

    /// 3D: 6 sqrt(pi) V / A^(3/2) (1 for a sphere); 2D: 4 pi A / L^2 (1 for
    /// a circle). 0 without a boundary.
    double
    reduced(const unsigned int dim) const;
  };


  /**
   * The measures of component @p component of a spline field (natural
   * coefficients, @p n_components per basis function, component fastest)
   * on a box space whose parametric coordinates are the physical ones.
   *
   * Elements whose coefficients of the component all have one sign lie
   * wholly inside or outside (a B-spline lies in the convex hull of its
   * coefficients) and are counted without sampling. Every other element is
   * cut into @p samples_per_element^dim sub-boxes, each into dim! simplices
   * (Kuhn's triangulation, conforming between neighbours); the zero of the
   * spline on every cut simplex edge is found on the spline itself (Illinois
   * regula falsi), and the simplex's part {phi < 0} is the polytope through
   * those points. So the surface is inscribed in the spline's zero set, and
   * both measures converge at second order in the sample spacing.
   */
  template <int dim>
  ZeroSetMeasures
  zero_set_measures(const SplineSpace<dim>    &space,
                    const std::vector<double> &natural,
                    const unsigned int         n_components,
                    const unsigned int         component,
                    const unsigned int         samples_per_element = 4);

  /**
   * The same measures of component @p component of a distributed field
   * (@p ghosted: the locally relevant coefficients in the numbering of
   * @p dofs), each rank cutting its own elements with their own
   * coefficients; summed over the ranks (collective). No rank holds the
   * whole field.
   */
  template <int dim>
  ZeroSetMeasures
  zero_set_measures(const SplineDofHandler<dim>                 &dofs,
                    const dealii::TrilinosWrappers::MPI::Vector &ghosted,
                    const unsigned int                           component,
                    const unsigned int samples_per_element = 4);
} // namespace vesicle_iga
