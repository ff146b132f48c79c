#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/assembly/assembly_term.h>
#include <vesicle_iga/parallel/spline_dof_handler.h>
#include <vesicle_iga/physics/phase_field_term.h>

#include <vector>

namespace vesicle_iga
{
  /**
   * The generalized-alpha Newton system of the phase-field gradient flow
   * (E12) in the primal H^2 form (E18): residual
   *   R(w) = (w, phidot_{n+alpha_m}) + sum over energy terms of their first
   *          variation at phi_{n+alpha_f},
   * and tangent (N4) K = alpha_m M + alpha_f gamma dt DR (DR from (E20)).
   * As an AssemblyTerm it adds K to the matrix and -R to the right-hand
   * side, so Newton solves K d(phidot) = -R. The energy terms are a list of
   * PhaseFieldTerm objects: a new term (flexoelectric, dielectric) is added
   * to the list, nothing here changes.
   */
  template <int dim>
  class PhaseFieldOperator : public AssemblyTerm<dim>
  {
  public:
    PhaseFieldOperator(const SplineDofHandler<dim>                    &dofs,
                       const std::vector<const PhaseFieldTerm<dim> *> &terms);

    /// Ghosted vectors phi_{n+alpha_f} and phidot_{n+alpha_m}, the factors
    /// alpha_m and alpha_f gamma dt of (N4), and whether the matrix is
    /// wanted (false: residual only).
    void
    set_state(const TrilinosWrappers::MPI::Vector &phi,
              const TrilinosWrappers::MPI::Vector &phi_dot,
              const double                         mass_factor,
              const double                         stiffness_factor,
              const bool                           with_matrix);

    unsigned int
    derivative_order() const override
    {
      return 2;
    }
    void
    assemble_cell(const SplineCellValues<dim> &values,
                  FullMatrix<double>          &matrix,
                  Vector<double>              &rhs) const override;

    /// phi, grad phi and Delta phi at quadrature point q.
    static PhaseFieldPoint<dim>
    point(const SplineCellValues<dim> &values,
          const unsigned int           q,
          const std::vector<double>   &coefficients);

  private:
    const SplineDofHandler<dim>             &dofs;
    std::vector<const PhaseFieldTerm<dim> *> terms;
    const TrilinosWrappers::MPI::Vector     *phi     = nullptr;
    const TrilinosWrappers::MPI::Vector     *phi_dot = nullptr;
    double mass_factor = 1, stiffness_factor = 1;
    bool   with_matrix = true;
  };
} // namespace vesicle_iga
