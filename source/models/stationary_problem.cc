#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vesicle_iga/models/stationary_problem.h>
#include <vesicle_iga/solvers/spline_multigrid.h>

#include <optional>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  StationaryProblem<dim>::StationaryProblem(
    const MPI_Comm                            comm,
    const SplineSpace<dim>                   &space,
    std::shared_ptr<const NurbsGeometry<dim>> geometry,
    const unsigned int                        n_components)
    : spline_space(space)
    , geometry(geometry)
    , patch_mesh(comm, spline_space, geometry)
    , dof_handler(patch_mesh, spline_space, n_components)
    , values(dof_handler.locally_relevant_dofs())
  {}


  template <int dim>
  void
  StationaryProblem<dim>::assemble(const TrilinosWrappers::MPI::Vector &x,
                                   TrilinosWrappers::MPI::Vector *residual,
                                   const bool                     jacobian)
  {
    std::optional<TimerOutput::Scope> scope;
    if (timer)
      scope.emplace(*timer, "assembly");
    ghosted_solution = x;
    AssemblyState state;
    state.value = &ghosted_solution;
    assembler->assemble(state,
                        increments,
                        residual,
                        jacobian ? &linear->matrix() : nullptr);
  }


  template <int dim>
  LinearSolveResult
  StationaryProblem<dim>::solve(const std::vector<Term<dim> *> &terms,
                                const Quadrature<1>            &quadrature,
                                const LinearSolverParameters   &solver,
                                TimerOutput                    *timer_)
  {
    timer = timer_;
    std::optional<TimerOutput::Scope> scope;
    if (timer)
      scope.emplace(*timer, "setup");
    const MPI_Comm comm = patch_mesh.get_communicator();
    values.close();
    // The increments vanish where the values are prescribed (the entries of
    // constraints between unknowns are kept).
    increments.reinit(dof_handler.locally_relevant_dofs());
    for (const auto &line : values.get_lines())
      {
        increments.add_line(line.index);
        increments.add_entries(line.index, line.entries);
      }
    increments.close();
    assembler = std::make_unique<SystemAssembler<dim>>(dof_handler,
                                                       quadrature,
                                                       geometry);
    for (auto *t : terms)
      assembler->add_term(*t);
    TrilinosWrappers::SparsityPattern sparsity;
    dof_handler.make_sparsity_pattern(sparsity);
    linear
      = std::make_unique<JacobianSolver>(solver, increments, sparsity, timer);
    if (solver.uses_multigrid())
      linear->set_preconditioner(std::make_unique<SplineMultigrid<dim>>(
                                   dof_handler, increments, solver.multigrid),
                                 JacobianSolver::Reuse::every_matrix);
    ghosted_solution.reinit(dof_handler.locally_owned_dofs(),
                            dof_handler.locally_relevant_dofs(),
                            comm);
    TrilinosWrappers::MPI::Vector x(dof_handler.locally_owned_dofs(), comm);
    values.distribute(x);
    scope.reset();
    const NewtonSolver newton(NewtonParameters{});
    const auto         report = newton.solve_linear(*this, x);
    ghosted_solution          = x;
    return {report.krylov_iterations, report.linear_residual};
  }

  template class StationaryProblem<2>;
  template class StationaryProblem<3>;
} // namespace vesicle_iga
