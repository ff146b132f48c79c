// The Gram matrix of a scalar spline field and the L2 projection onto its
// constrained space.

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vesicle_iga/kernel/system_assembler.h>
#include <vesicle_iga/solvers/gram_solver.h>
#include <vesicle_iga/terms/rate.h>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  void
  assemble_gram_matrix(const SplineDofHandler<dim>     &dofs,
                       const Quadrature<1>             &quadrature,
                       const AffineConstraints<double> &constraints,
                       TrilinosWrappers::SparseMatrix  &matrix)
  {
    TrilinosWrappers::SparsityPattern sparsity;
    dofs.make_sparsity_pattern(sparsity);
    matrix.reinit(sparsity);
    SystemAssembler<dim> assembler(dofs, quadrature);
    RateTerm<dim>        rate({0});
    assembler.add_term(rate);
    const TrilinosWrappers::MPI::Vector zero(
      dofs.locally_owned_dofs(),
      dofs.locally_relevant_dofs(),
      dofs.get_mesh().get_communicator());
    AssemblyState state;
    state.value        = &zero;
    state.rate         = &zero;
    state.value_factor = {0.};
    state.rate_factor  = {1.};
    assembler.assemble(state, constraints, nullptr, &matrix);
  }


  template <int dim>
  GramSolver<dim>::GramSolver(
    const PatchMesh<dim>                                   &mesh,
    const SplineSpace<dim>                                 &space,
    const Quadrature<1>                                    &quadrature,
    const std::function<void(const SplineDofHandler<dim> &,
                             AffineConstraints<double> &)> &conditions)
    : dofs(mesh, space, 1)
  {
    constraints.reinit(dofs.locally_relevant_dofs());
    conditions(dofs, constraints);
    constraints.close();
    assemble_gram_matrix(dofs, quadrature, constraints, mass);
    ilu.initialize(mass);
  }


  template <int dim>
  void
  GramSolver<dim>::solve(const TrilinosWrappers::MPI::Vector &b,
                         TrilinosWrappers::MPI::Vector       &y) const
  {
    y.reinit(b, false);
    SolverControl                           control(1000, 1e-12 * b.l2_norm());
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    cg.solve(mass, y, b, ilu);
  }


#define INSTANTIATE(dim)                                                \
  template void assemble_gram_matrix(const SplineDofHandler<dim> &,     \
                                     const Quadrature<1> &,             \
                                     const AffineConstraints<double> &, \
                                     TrilinosWrappers::SparseMatrix &); \
  template class GramSolver<dim>;
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace vesicle_iga
