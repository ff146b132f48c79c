#include <deal.II/base/function.h>

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vesicle_iga/fields/boundary_selection.h>
#include <vesicle_iga/fields/dirichlet_constraints.h>
#include <vesicle_iga/models/electric_potential.h>
#include <vesicle_iga/solvers/spline_multigrid.h>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  ElectricPotential<dim>::ElectricPotential(
    const SplineDofHandler<dim>             &dofs,
    const ElectromechanicsMaterial          &material,
    const Quadrature<1>                     &quadrature_1d,
    const LinearSolverParameters            &solver,
    TimerOutput                             &timer,
    const TrilinosWrappers::SparsityPattern *sparsity)
    : dofs(dofs)
    , timer(timer)
    , assembler(dofs, quadrature_1d)
    , conductivity(0, 0, material)
  {
    assembler.add_auxiliary_field(dofs);
    assembler.add_term(conductivity);
    const unsigned int d = material.direction();
    const auto        &z = dofs.get_space().knot_vector(d).breakpoints();
    V_E = 0.5 * material.field() * (z.back() - z.front()); // (E16)
    const std::string face = std::string(1, "xyz"[d]);
    values.reinit(dofs.locally_relevant_dofs());
    for (const double sign : {1., -1.})
      add_strong_dirichlet_constraints<dim>(
        dofs,
        nullptr,
        BoundarySelection<dim>(face + (sign > 0 ? "-min" : "-max"),
                               "Electric field/Field direction"),
        Functions::ConstantFunction<dim>(sign * V_E),
        {true},
        values);
    values.close();
    homogeneous.reinit(dofs.locally_relevant_dofs());
    for (const auto &line : values.get_lines())
      homogeneous.add_line(line.index);
    homogeneous.close();

    TrilinosWrappers::SparsityPattern own_sparsity;
    if (!sparsity)
      dofs.make_sparsity_pattern(own_sparsity);
    linear
      = std::make_unique<JacobianSolver>(solver,
                                         homogeneous,
                                         sparsity ? *sparsity : own_sparsity);
    if (solver.uses_multigrid())
      linear->set_preconditioner(std::make_unique<SplineMultigrid<dim>>(
                                   dofs, homogeneous, solver.multigrid),
                                 JacobianSolver::Reuse::every_matrix);
    const MPI_Comm comm = dofs.get_mesh().get_communicator();
    psi.reinit(dofs.locally_owned_dofs(), comm);
    ghosted_psi.reinit(dofs.locally_owned_dofs(),
                       dofs.locally_relevant_dofs(),
                       comm);
    ghosted_x.reinit(ghosted_psi);
  }


  template <int dim>
  void
  ElectricPotential<dim>::assemble(const TrilinosWrappers::MPI::Vector &x,
                                   TrilinosWrappers::MPI::Vector *residual,
                                   const bool                     jacobian)
  {
    ghosted_x = x;
    AssemblyState state;
    state.value     = &ghosted_x;
    state.auxiliary = {phi};
    assembler.assemble(state,
                       homogeneous,
                       residual,
                       jacobian ? &linear->matrix() : nullptr);
  }


  template <int dim>
  LinearSolveResult
  ElectricPotential<dim>::solve(
    const TrilinosWrappers::MPI::Vector &ghosted_phi)
  {
    TimerOutput::Scope t(timer, "potential");
    phi = &ghosted_phi;
    // From the previous potential with the electrode values (E16); the
    // problem is linear: one correction.
    values.distribute(psi);
    const NewtonSolver newton(NewtonParameters{});
    const auto         report = newton.solve_linear(*this, psi);
    ghosted_psi               = psi;
    return {report.krylov_iterations, report.linear_residual};
  }

  template class ElectricPotential<2>;
  template class ElectricPotential<3>;
} // namespace vesicle_iga
