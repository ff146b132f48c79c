#pragma once

#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/spline_dof_handler.h>
#include <vesicle_iga/kernel/system_assembler.h>
#include <vesicle_iga/parallel/patch_mesh.h>
#include <vesicle_iga/solvers/newton.h>

#include <memory>
#include <vector>

namespace vesicle_iga
{
  /**
   * A stationary linear problem on one spline patch, the verification
   * studies' model: space -> METIS-partitioned mesh -> unknowns ->
   * constraints (the strong Dirichlet values, filled by the caller) -> the
   * engine's assembler with the caller's terms -> one Newton correction
   * from the Dirichlet lifting (the problem is linear) with the Krylov
   * method of LinearSolverParameters -> ghosted solution.
   */
  template <int dim>
  class StationaryProblem : public NonlinearProblem
  {
  public:
    StationaryProblem(const MPI_Comm                            comm,
                      const SplineSpace<dim>                   &space,
                      std::shared_ptr<const NurbsGeometry<dim>> geometry,
                      const unsigned int                        n_components);

    const SplineSpace<dim> &
    space() const
    {
      return spline_space;
    }
    const PatchMesh<dim> &
    mesh() const
    {
      return patch_mesh;
    }
    const SplineDofHandler<dim> &
    dofs() const
    {
      return dof_handler;
    }
    /// The strong Dirichlet values, filled by the caller before solve().
    dealii::AffineConstraints<double> &
    constraints()
    {
      return values;
    }

    /// Assemble the sum of @p terms and solve; @p timer may be null.
    LinearSolveResult
    solve(const std::vector<Term<dim> *> &terms,
          const dealii::Quadrature<1>    &quadrature,
          const LinearSolverParameters   &solver,
          dealii::TimerOutput            *timer);

    /// The solution with ghost entries (all unknowns of owned elements).
    const dealii::TrilinosWrappers::MPI::Vector &
    solution() const
    {
      return ghosted_solution;
    }

    void
    assemble(const dealii::TrilinosWrappers::MPI::Vector &x,
             dealii::TrilinosWrappers::MPI::Vector       *residual,
             const bool                                   jacobian) override;
    JacobianSolver &
    jacobian_solver() override
    {
      return *linear;
    }

  private:
    const SplineSpace<dim>                    spline_space;
    std::shared_ptr<const NurbsGeometry<dim>> geometry;
    PatchMesh<dim>                            patch_mesh;
    SplineDofHandler<dim>                     dof_handler;
    dealii::AffineConstraints<double>         values, increments;
    std::unique_ptr<SystemAssembler<dim>>     assembler;
    std::unique_ptr<JacobianSolver>           linear;
    dealii::TimerOutput                      *timer = nullptr;
    dealii::TrilinosWrappers::MPI::Vector     ghosted_solution;
  };
} // namespace vesicle_iga
