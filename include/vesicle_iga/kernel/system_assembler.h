#pragma once

#include <deal.II/base/quadrature.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/spline_dof_handler.h>
#include <vesicle_iga/kernel/term.h>
#include <vesicle_iga/spline/nurbs_geometry.h>

#include <memory>
#include <vector>

namespace vesicle_iga
{
  /**
   * The state at which a system is assembled: the unknowns at the stage of
   * the step (ghosted), their rates (ghosted; only if a term reads rates),
   * the auxiliary fields (ghosted, in the order they were added to the
   * assembler), the factors by which a variation of the Newton unknown
   * changes the value and the rate of each component (spec (N4): alpha_f
   * gamma dt and alpha_m for a differential field; empty: 1 and 0, a
   * stationary problem), and the time of the evaluation.
   */
  struct AssemblyState
  {
    const dealii::TrilinosWrappers::MPI::Vector               *value = nullptr;
    const dealii::TrilinosWrappers::MPI::Vector               *rate  = nullptr;
    std::vector<const dealii::TrilinosWrappers::MPI::Vector *> auxiliary;
    std::vector<double> value_factor, rate_factor;
    double              time = 0, time_step = 0;
  };


  /**
   * The one assembly kernel of the program (doc/engine.md): the residual R
   * and the Jacobian K = dR/dU (with the factors of AssemblyState) of a
   * list of terms, over the locally owned elements and the boundary faces,
   * in one pass for both or in separate passes for either. Per element it
   * evaluates every declared input by sum factorisation (a table-based
   * path serves NURBS geometries), calls each term once for all quadrature
   * points, integrates the residual coefficients against the test functions
   * and every non-zero (test, trial) derivative pair of every non-zero
   * block of components against the test and trial functions, and
   * scatters through the given constraints (WorkStream, ScratchData and
   * CopyData). Terms never see a basis function.
   */
  template <int dim>
  class SystemAssembler
  {
  public:
    SystemAssembler(const SplineDofHandler<dim>              &dofs,
                    const dealii::Quadrature<1>              &quadrature_1d,
                    std::shared_ptr<const NurbsGeometry<dim>> geometry = {});
    ~SystemAssembler();

    /// A field on the same mesh that terms read but that is not an
    /// unknown; returns the number TermDeclaration::auxiliary() takes.
    unsigned int
    add_auxiliary_field(const SplineDofHandler<dim> &auxiliary_dofs);
    /// Adds a term (which declares itself now); the assembler keeps a
    /// pointer.
    void
    add_term(Term<dim> &term);
    /// Removes every term.
    void
    clear_terms();

    /// R(U) into @p residual (owned layout; not negated) and/or K into
    /// @p matrix (either may be null), through @p constraints (the
    /// homogeneous constraints of the Newton increments).
    void
    assemble(const AssemblyState                     &state,
             const dealii::AffineConstraints<double> &constraints,
             dealii::TrilinosWrappers::MPI::Vector   *residual,
             dealii::TrilinosWrappers::SparseMatrix  *matrix) const;

    /// The integrals of @p integrands over the domain, in one pass over the
    /// elements, summed over all ranks: their values one after the other.
    std::vector<double>
    integrate(const std::vector<Integrand<dim> *> &integrands,
              const AssemblyState                 &state) const;

    const SplineDofHandler<dim> &
    get_dofs() const
    {
      return dofs;
    }
    const dealii::Quadrature<1> &
    get_quadrature() const
    {
      return quadrature;
    }

    struct Plan;
    struct Scratch;

  private:
    void
    rebuild_plans();

    const SplineDofHandler<dim>               &dofs;
    const dealii::Quadrature<1>                quadrature;
    std::shared_ptr<const NurbsGeometry<dim>>  geometry;
    std::vector<const SplineDofHandler<dim> *> auxiliary_dofs;
    std::vector<Term<dim> *>                   terms;
    std::unique_ptr<Plan>                      cell_plan, face_plan;
  };
} // namespace vesicle_iga
