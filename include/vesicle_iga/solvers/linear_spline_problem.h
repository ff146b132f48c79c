#pragma once

#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/assembly/assembly_term.h>
#include <vesicle_iga/parallel/patch_mesh.h>
#include <vesicle_iga/parallel/spline_dof_handler.h>
#include <vesicle_iga/solvers/linear_solver.h>

#include <memory>
#include <vector>

namespace vesicle_iga
{
  /**
   * Everything a linear stationary problem on one spline patch needs,
   * in the order it is built: space -> METIS-partitioned mesh -> unknowns
   * -> constraints (filled by the caller) -> sparsity and Trilinos matrix
   * -> assembly of a list of terms -> Krylov solve -> ghosted solution.
   * The verification studies differ only in their terms and constraints.
   */
  template <int dim>
  class LinearSplineProblem
  {
  public:
    LinearSplineProblem(const MPI_Comm                            comm,
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
    std::shared_ptr<const NurbsGeometry<dim>>
    geometry() const
    {
      return geometry_;
    }
    /// Filled by the caller (strong Dirichlet conditions) before solve().
    AffineConstraints<double> &
    constraints()
    {
      return constraints_;
    }

    /// Assemble the sum of @p terms and solve; @p timer may be null.
    LinearSolveResult
    assemble_and_solve(const std::vector<const AssemblyTerm<dim> *> &terms,
                       const Quadrature<1>                          &quadrature,
                       const LinearSolverParameters                 &solver,
                       TimerOutput                                  *timer);

    /// The solution with ghost entries (all unknowns of owned elements).
    const TrilinosWrappers::MPI::Vector &
    solution() const
    {
      return ghosted_solution;
    }

  private:
    const SplineSpace<dim>                    spline_space;
    std::shared_ptr<const NurbsGeometry<dim>> geometry_;
    PatchMesh<dim>                            patch_mesh;
    SplineDofHandler<dim>                     dof_handler;
    AffineConstraints<double>                 constraints_;
    TrilinosWrappers::SparseMatrix            matrix;
    TrilinosWrappers::MPI::Vector             rhs, ghosted_solution;
  };
} // namespace vesicle_iga
