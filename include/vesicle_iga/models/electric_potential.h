#pragma once

#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/kernel/system_assembler.h>
#include <vesicle_iga/physics/electromechanics_material.h>
#include <vesicle_iga/solvers/newton.h>
#include <vesicle_iga/terms/conductivity.h>

#include <memory>

namespace vesicle_iga
{
  /**
   * The electric potential of spec section 3.6: div(sigma(phi) grad psi) =
   * 0 (E16)-(E17) on the phase field's spline space, psi = +V_E on the face
   * where the field enters (lower end of the field direction), -V_E on the
   * opposite face, V_E = E0 L / 2, insulated elsewhere. The Dirichlet
   * values are the outermost coefficient layers (exact for constants).
   * A linear problem of the engine: one term (ConductivityTerm), phi an
   * auxiliary field, one Newton correction from the previous potential.
   *
   * The matrix is SPD but sigma spans seven orders of magnitude across the
   * membrane (sigma(0) = sigma_m / 4 against sigma_out): the solver is CG
   * with the spline multigrid (Galerkin coarse operators keep the
   * coefficient jumps) or with ML AMG, chosen in "Linear solver".
   */
  template <int dim>
  class ElectricPotential : public NonlinearProblem
  {
  public:
    /// @p dofs: one component on the phase field's space (psi and phi use
    /// the same unknowns' numbering). @p sparsity: the pattern of @p dofs
    /// if the caller has made it (the phase field's Jacobian): the matrix
    /// then shares its graph, which is the size of the matrix's indices.
    ElectricPotential(const SplineDofHandler<dim>    &dofs,
                      const ElectromechanicsMaterial &material,
                      const dealii::Quadrature<1>    &quadrature_1d,
                      const LinearSolverParameters   &solver,
                      dealii::TimerOutput            &timer,
                      const dealii::TrilinosWrappers::SparsityPattern *sparsity
                      = nullptr);

    /// Solve (E17) with sigma(phi) for the ghosted phase field @p phi;
    /// returns the Krylov iterations and residual.
    LinearSolveResult
    solve(const dealii::TrilinosWrappers::MPI::Vector &phi);

    /// psi with ghost entries (zero before the first solve).
    const dealii::TrilinosWrappers::MPI::Vector &
    potential() const
    {
      return ghosted_psi;
    }
    /// psi in the owned layout, e.g. for checkpoints.
    const dealii::TrilinosWrappers::MPI::Vector &
    owned_potential() const
    {
      return psi;
    }
    /// V_E of (E16).
    double
    boundary_potential() const
    {
      return V_E;
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
    const SplineDofHandler<dim>                 &dofs;
    dealii::TimerOutput                         &timer;
    SystemAssembler<dim>                         assembler;
    ConductivityTerm<dim>                        conductivity;
    double                                       V_E = 0;
    dealii::AffineConstraints<double>            values, homogeneous;
    std::unique_ptr<JacobianSolver>              linear;
    dealii::TrilinosWrappers::MPI::Vector        psi, ghosted_psi, ghosted_x;
    const dealii::TrilinosWrappers::MPI::Vector *phi = nullptr;
  };
} // namespace vesicle_iga
