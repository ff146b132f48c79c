#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/spline_dof_handler.h>
#include <vesicle_iga/io/checkpoint.h>

#include <string>

namespace vesicle_iga
{
  /// Store a distributed vector of @p dofs in the natural numbering
  /// (collective).
  template <int dim>
  void
  save_field(Checkpoint                                  &checkpoint,
             const std::string                           &name,
             const SplineDofHandler<dim>                 &dofs,
             const dealii::TrilinosWrappers::MPI::Vector &v);

  /// Read it back into the owned layout of @p dofs (any number of ranks);
  /// InputError naming "Restart from" if the checkpoint lacks it or it was
  /// written for another number of unknowns (another mesh, degree or number
  /// of fields).
  template <int dim>
  void
  load_field(const Checkpoint                      &checkpoint,
             const std::string                     &name,
             const SplineDofHandler<dim>           &dofs,
             dealii::TrilinosWrappers::MPI::Vector &v);
} // namespace vesicle_iga
