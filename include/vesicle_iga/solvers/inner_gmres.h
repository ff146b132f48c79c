#pragma once

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_vector.h>

namespace vesicle_iga
{
  /**
   * One block of a block preconditioner applied inside the outer FGMRES:
   * with @p tolerance 0 one application of @p v_cycle; otherwise GMRES(50)
   * on @p matrix preconditioned by @p v_cycle to that relative residual, at
   * most 100 iterations. A variable preconditioner is allowed inside FGMRES,
   * so the iterate serves if the limit is reached. Used on the velocity
   * block ('Velocity tolerance') and on the phase-field blocks ('Phase field
   * tolerance'), doc/hydrodynamics.md.
   */
  template <typename Matrix, typename VCycle>
  void
  apply_block_inverse(const Matrix                                &matrix,
                      const VCycle                                &v_cycle,
                      const double                                 tolerance,
                      dealii::TrilinosWrappers::MPI::Vector       &x,
                      const dealii::TrilinosWrappers::MPI::Vector &r)
  {
    if (tolerance == 0)
      {
        v_cycle.vmult(x, r);
        return;
      }
    x = 0;
    dealii::SolverControl control(100, tolerance * r.l2_norm());
    typename dealii::SolverGMRES<
      dealii::TrilinosWrappers::MPI::Vector>::AdditionalData   data(50);
    dealii::SolverGMRES<dealii::TrilinosWrappers::MPI::Vector> gmres(control,
                                                                     data);
    try
      {
        gmres.solve(matrix, x, r, v_cycle);
      }
    catch (const dealii::SolverControl::NoConvergence &)
      {}
  }
} // namespace vesicle_iga
