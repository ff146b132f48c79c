#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/spline_dof_handler.h>
#include <vesicle_iga/physics/electromechanics_material.h>

#include <string>
#include <vector>

namespace vesicle_iga
{
  /**
   * VTU/PVTU of a vesicle state (spec section 3.11): phi, and with a
   * potential psi also psi, |grad psi| and sigma(phi) of (E10). Both fields
   * live on the same spline unknowns; they are written through one
   * two-component spline field.
   */
  template <int dim>
  void
  write_vesicle_vtu(const SplineDofHandler<dim>                 &dofs,
                    const dealii::TrilinosWrappers::MPI::Vector &phi,
                    const dealii::TrilinosWrappers::MPI::Vector *psi,
                    const ElectromechanicsMaterial              &material,
                    const std::string                           &directory,
                    const std::string                           &basename);

  /**
   * Profiles of phi and sigma(phi) (and psi, |grad psi| with a potential)
   * along the coordinate axes through @p center, 50 points per element, as
   * CSV with the columns axis, s (the coordinate along the axis), phi,
   * sigma[, psi, grad_psi_norm]; written by rank 0 from complete natural
   * coefficient vectors.
   */
  template <int dim>
  void
  write_axis_profiles(const SplineSpace<dim>         &space,
                      const std::vector<double>      &phi_natural,
                      const std::vector<double>      *psi_natural,
                      const ElectromechanicsMaterial &material,
                      const dealii::Point<dim>       &center,
                      const std::string              &filename);

  /**
   * phi on a uniform grid (4 points per element and direction) in the
   * coordinate plane spanned by @p first_axis and @p second_axis through
   * @p center: the whole domain in 2D, a mid-plane section in 3D. CSV with
   * the columns named after the two axes and phi; the zero-level contours
   * in the plane containing the field axis (spec 3.11) are drawn from it by
   * tools/plot-contours.py. Written by rank 0.
   */
  template <int dim>
  void
  write_plane_section(const SplineSpace<dim>    &space,
                      const std::vector<double> &phi_natural,
                      const dealii::Point<dim>  &center,
                      const unsigned int         first_axis,
                      const unsigned int         second_axis,
                      const std::string         &filename);
} // namespace vesicle_iga
