#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/kernel/system_assembler.h>

#include <vector>

namespace vesicle_iga
{
  /// The result of a finite-difference check of a Jacobian.
  struct JacobianCheck
  {
    /// |K d| and |K_value d| (the part of K from the value factors, without
    /// the rate factors).
    double norm_Kd = 0, norm_value_part = 0;
    /// For each step h: |(R(U + h d) - R(U - h d)) / 2h - K d| / |K d|.
    std::vector<double> relative_difference;
  };

  /**
   * The one finite-difference check of a Jacobian, usable on any list of
   * terms (tests check every term with it): at @p state, a variation d of
   * the unknown changes the values by value_factor d and the rates by
   * rate_factor d (the factors of the state, per component), and K d is
   * compared with central differences of the residual of @p assembler for
   * each of @p steps. For a consistent Jacobian the difference falls as
   * h^2 until round-off (~1e-16 / h relative) takes over; a missing or
   * wrong derivative leaves a difference that does not fall with h.
   * @p direction is zero on the constrained entries (owned layout).
   */
  template <int dim>
  JacobianCheck
  check_jacobian(const SystemAssembler<dim>                  &assembler,
                 const AssemblyState                         &state,
                 const dealii::AffineConstraints<double>     &constraints,
                 const dealii::TrilinosWrappers::MPI::Vector &direction,
                 const std::vector<double>                   &steps);

  /// A smooth, non-trivial direction defined in the natural numbering (the
  /// same on any number of ranks), zero on constrained entries.
  template <int dim>
  dealii::TrilinosWrappers::MPI::Vector
  test_direction(const SplineDofHandler<dim>             &dofs,
                 const dealii::AffineConstraints<double> &constraints);
} // namespace vesicle_iga
