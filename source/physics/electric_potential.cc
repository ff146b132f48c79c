#include <deal.II/base/function.h>

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vesicle_iga/assembly/assembler.h>
#include <vesicle_iga/assembly/boundary_selection.h>
#include <vesicle_iga/assembly/dirichlet_constraints.h>
#include <vesicle_iga/physics/electric_potential.h>
#include <vesicle_iga/spline/sum_factorization.h>

namespace vesicle_iga
{
  template <int dim>
  void
  ConductivityTerm<dim>::assemble_cell(const SplineCellValues<dim> &v,
                                       FullMatrix<double>          &A,
                                       Vector<double> &) const
  {
    // (E17): sum_d (sigma(phi) d_d psi, d_d v).
    using SF = SumFactorization<dim>;
    const SF                         kernel(v.tensor_product_factors());
    const unsigned int               nq = kernel.n_quadrature_points();
    std::vector<std::vector<double>> c;
    get_element_coefficients(dofs, *phi, v.element(), c);
    typename SF::AtomValues       u;
    std::array<bool, SF::n_atoms> value_only{};
    value_only[SF::value_atom] = true;
    kernel.evaluate(c[0], value_only, u);
    std::vector<double> coefficient(nq);
    for (unsigned int q = 0; q < nq; ++q)
      coefficient[q]
        = material.conductivity(u[SF::value_atom][q]) * kernel.JxW(q);
    std::vector<typename SF::AtomPair> pairs;
    for (unsigned int d = 0; d < dim; ++d)
      pairs.push_back(
        {SF::gradient_atom(d), SF::gradient_atom(d), coefficient});
    std::vector<const typename SF::AtomPair *> pointers;
    for (const auto &p : pairs)
      pointers.push_back(&p);
    kernel.integrate_matrix(pointers, A, true);
  }


  template <int dim>
  ElectricPotential<dim>::ElectricPotential(
    const SplineDofHandler<dim>    &dofs,
    const ElectromechanicsMaterial &material,
    const Quadrature<1>            &quadrature_1d,
    const LinearSolverParameters   &solver,
    TimerOutput                    &timer)
    : dofs(dofs)
    , quadrature(quadrature_1d)
    , solver(solver)
    , timer(timer)
    , term(dofs, material)
  {
    const unsigned int d = material.direction();
    const auto        &z = dofs.get_space().knot_vector(d).breakpoints();
    const double       L = z.back() - z.front();
    V_E                  = 0.5 * material.field() * L; // (E16): E0 = 2 V_E / L
    const std::string face = std::string(1, "xyz"[d]);
    constraints.reinit(dofs.locally_relevant_dofs());
    add_strong_dirichlet_constraints<dim>(
      dofs,
      nullptr,
      BoundarySelection<dim>(face + "-min", "Electric field/Field direction"),
      Functions::ConstantFunction<dim>(V_E),
      {true},
      constraints);
    add_strong_dirichlet_constraints<dim>(
      dofs,
      nullptr,
      BoundarySelection<dim>(face + "-max", "Electric field/Field direction"),
      Functions::ConstantFunction<dim>(-V_E),
      {true},
      constraints);
    constraints.close();
    homogeneous.reinit(dofs.locally_relevant_dofs());
    for (const auto &line : constraints.get_lines())
      homogeneous.add_line(line.index);
    homogeneous.close();

    TrilinosWrappers::SparsityPattern sparsity;
    dofs.make_sparsity_pattern(sparsity);
    matrix.reinit(sparsity);
    const MPI_Comm comm = dofs.get_mesh().get_communicator();
    psi.reinit(dofs.locally_owned_dofs(), comm);
    rhs.reinit(psi);
    ghosted_psi.reinit(dofs.locally_owned_dofs(),
                       dofs.locally_relevant_dofs(),
                       comm);
    if (solver.uses_multigrid())
      multigrid = std::make_unique<SplineMultigrid<dim>>(dofs,
                                                         homogeneous,
                                                         solver.multigrid);
  }


  template <int dim>
  LinearSolveResult
  ElectricPotential<dim>::solve(const TrilinosWrappers::MPI::Vector &phi)
  {
    TimerOutput::Scope t(timer, "potential");
    term.set_phase_field(phi);
    assemble_linear_system<dim>(
      dofs, nullptr, quadrature, {&term}, constraints, matrix, rhs);
    if (multigrid)
      multigrid->initialize(matrix);
    // The previous potential is a good initial guess (relative tolerance).
    const auto result = solve_linear_system(
      solver, matrix, psi, rhs, constraints, multigrid.get());
    ghosted_psi = psi;
    return result;
  }

  template class ConductivityTerm<2>;
  template class ConductivityTerm<3>;
  template class ElectricPotential<2>;
  template class ElectricPotential<3>;
} // namespace vesicle_iga
