#include <vesicle_iga/assembly/assembler.h>
#include <vesicle_iga/solvers/linear_spline_problem.h>

#include <optional>

namespace vesicle_iga
{
  template <int dim>
  LinearSplineProblem<dim>::LinearSplineProblem(
    const MPI_Comm                            comm,
    const SplineSpace<dim>                   &space,
    std::shared_ptr<const NurbsGeometry<dim>> geometry,
    const unsigned int                        n_components)
    : spline_space(space)
    , geometry_(geometry)
    , patch_mesh(comm, spline_space, geometry)
    , dof_handler(patch_mesh, spline_space, n_components)
    , constraints_(dof_handler.locally_relevant_dofs())
  {}


  template <int dim>
  LinearSolveResult
  LinearSplineProblem<dim>::assemble_and_solve(
    const std::vector<const AssemblyTerm<dim> *> &terms,
    const Quadrature<1>                          &quadrature,
    const LinearSolverParameters                 &solver,
    TimerOutput                                  *timer)
  {
    const MPI_Comm                    comm = patch_mesh.get_communicator();
    std::optional<TimerOutput::Scope> scope;
    if (timer)
      scope.emplace(*timer, "setup");
    constraints_.close();
    TrilinosWrappers::SparsityPattern sparsity;
    dof_handler.make_sparsity_pattern(sparsity);
    matrix.reinit(sparsity);
    rhs.reinit(dof_handler.locally_owned_dofs(), comm);
    if (timer)
      {
        scope.reset();
        scope.emplace(*timer, "assembly");
      }
    assemble_linear_system<dim>(
      dof_handler, geometry_, quadrature, terms, constraints_, matrix, rhs);
    if (timer)
      {
        scope.reset();
        scope.emplace(*timer, "solve");
      }
    TrilinosWrappers::MPI::Vector x(dof_handler.locally_owned_dofs(), comm);
    std::unique_ptr<SplineMultigrid<dim>> multigrid;
    if (solver.uses_multigrid())
      {
        // The multigrid works on the homogeneous version of the
        // constraints (the increments of a Dirichlet problem).
        AffineConstraints<double> homogeneous(
          dof_handler.locally_relevant_dofs());
        for (const auto &line : constraints_.get_lines())
          {
            homogeneous.add_line(line.index);
            homogeneous.add_entries(line.index, line.entries);
          }
        homogeneous.close();
        multigrid = std::make_unique<SplineMultigrid<dim>>(dof_handler,
                                                           homogeneous,
                                                           solver.multigrid);
        multigrid->initialize(matrix);
      }
    const auto result = solve_linear_system(
      solver, matrix, x, rhs, constraints_, multigrid.get());
    ghosted_solution.reinit(dof_handler.locally_owned_dofs(),
                            dof_handler.locally_relevant_dofs(),
                            comm);
    ghosted_solution = x;
    return result;
  }

  template class LinearSplineProblem<2>;
  template class LinearSplineProblem<3>;
} // namespace vesicle_iga
