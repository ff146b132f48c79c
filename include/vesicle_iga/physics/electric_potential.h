#pragma once

#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/assembly/assembly_term.h>
#include <vesicle_iga/parallel/spline_dof_handler.h>
#include <vesicle_iga/physics/electromechanics_material.h>
#include <vesicle_iga/solvers/linear_solver.h>

#include <memory>

namespace vesicle_iga
{
  /**
   * The conductivity-weighted Laplacian (sigma(phi) grad psi, grad v) of
   * (E17), sigma from (E10) evaluated at the given phase field, assembled by
   * sum factorisation.
   */
  template <int dim>
  class ConductivityTerm : public AssemblyTerm<dim>
  {
  public:
    ConductivityTerm(const SplineDofHandler<dim>    &dofs,
                     const ElectromechanicsMaterial &material)
      : dofs(dofs)
      , material(material)
    {}
    /// The ghosted phase field phi_n of sigma(phi_n).
    void
    set_phase_field(const TrilinosWrappers::MPI::Vector &ghosted_phi)
    {
      phi = &ghosted_phi;
    }
    unsigned int
    derivative_order() const override
    {
      return 2;
    }
    bool
    needs_shape_tables() const override
    {
      return false;
    }
    void
    assemble_cell(const SplineCellValues<dim> &values,
                  FullMatrix<double>          &matrix,
                  Vector<double>              &rhs) const override;

  private:
    const SplineDofHandler<dim>         &dofs;
    const ElectromechanicsMaterial      &material;
    const TrilinosWrappers::MPI::Vector *phi = nullptr;
  };

  /**
   * The electric potential of spec section 3.6: div(sigma(phi) grad psi) =
   * 0 (E16)-(E17) on the phase field's spline space, psi = +V_E on the face
   * where the field enters (lower end of the field direction), -V_E on the
   * opposite face, V_E = E0 L / 2, insulated elsewhere. The Dirichlet
   * values are the outermost coefficient layers (exact for constants).
   *
   * The matrix is SPD but sigma spans seven orders of magnitude across the
   * membrane (sigma(0) = sigma_m / 4 against sigma_out): the solver is CG
   * with the spline multigrid (Galerkin coarse operators keep the
   * coefficient jumps) or with ML AMG, chosen in "Linear solver".
   */
  template <int dim>
  class ElectricPotential
  {
  public:
    ElectricPotential(const SplineDofHandler<dim>    &dofs,
                      const ElectromechanicsMaterial &material,
                      const Quadrature<1>            &quadrature_1d,
                      const LinearSolverParameters   &solver,
                      TimerOutput                    &timer);

    /// Solve (E17) with sigma(phi); returns the Krylov iterations.
    LinearSolveResult
    solve(const TrilinosWrappers::MPI::Vector &ghosted_phi);

    /// psi with ghost entries (zero before the first solve).
    const TrilinosWrappers::MPI::Vector &
    potential() const
    {
      return ghosted_psi;
    }
    /// psi in the owned layout, e.g. for checkpoints.
    const TrilinosWrappers::MPI::Vector &
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

  private:
    const SplineDofHandler<dim>          &dofs;
    const Quadrature<1>                   quadrature;
    const LinearSolverParameters          solver;
    TimerOutput                          &timer;
    ConductivityTerm<dim>                 term;
    double                                V_E = 0;
    AffineConstraints<double>             constraints, homogeneous;
    TrilinosWrappers::SparseMatrix        matrix;
    std::unique_ptr<SplineMultigrid<dim>> multigrid;
    TrilinosWrappers::MPI::Vector         psi, rhs, ghosted_psi;
  };
} // namespace vesicle_iga
