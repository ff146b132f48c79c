#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/assembly/assembly_term.h>
#include <vesicle_iga/parallel/spline_dof_handler.h>
#include <vesicle_iga/physics/phase_field_term.h>

#include <functional>
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
    bool
    needs_shape_tables() const override
    {
      return false;
    }
    void
    assemble_cell(const SplineCellValues<dim> &values,
                  FullMatrix<double>          &matrix,
                  Vector<double>              &rhs) const override;

    /// phi, grad phi and Delta phi at quadrature point q from the full
    /// basis tables (reference for the sum-factorised path).
    static PhaseFieldPoint<dim>
    point(const SplineCellValues<dim> &values,
          const unsigned int           q,
          const std::vector<double>   &coefficients);

    /// The electric potential psi^n whose gradient enters the points
    /// (ghosted, on the same dofs; nullptr: no field).
    void
    set_potential(const TrilinosWrappers::MPI::Vector *ghosted_psi)
    {
      psi = ghosted_psi;
    }

    /// phi, grad phi and Delta phi (and grad psi if @p psi_coefficients
    /// is not empty) at all quadrature points of an element by sum
    /// factorisation.
    static void
    evaluate_points(const SumFactorization<dim>       &kernel,
                    const std::vector<double>         &phi_coefficients,
                    const std::vector<double>         &psi_coefficients,
                    std::vector<PhaseFieldPoint<dim>> &points);

    /// Sum over the locally owned elements and all ranks of
    /// integrand(point, JxW, sums) at every quadrature point (n_sums
    /// values), with the potential of set_potential().
    std::vector<double>
    integrate(
      const TrilinosWrappers::MPI::Vector              &ghosted_phi,
      const Quadrature<1>                              &quadrature_1d,
      const unsigned int                                n_sums,
      const std::function<void(const PhaseFieldPoint<dim> &,
                               const double,
                               std::vector<double> &)> &integrand) const;

    /// As above with the points of a second field (no potential) at the
    /// same quadrature points, e.g. a state and its change over a step:
    /// integrand(point of phi, point of other, JxW, sums).
    std::vector<double>
    integrate(
      const TrilinosWrappers::MPI::Vector              *ghosted_phi,
      const TrilinosWrappers::MPI::Vector              *ghosted_other,
      const Quadrature<1>                              &quadrature_1d,
      const unsigned int                                n_sums,
      const std::function<void(const PhaseFieldPoint<dim> &,
                               const PhaseFieldPoint<dim> &,
                               const double,
                               std::vector<double> &)> &integrand) const;

    /// The functional of every term (energies, A, V), integrated at once.
    std::vector<double>
    integrate_terms(const std::vector<const PhaseFieldTerm<dim> *> &terms,
                    const TrilinosWrappers::MPI::Vector            &ghosted_phi,
                    const Quadrature<1> &quadrature_1d) const;

  private:
    const SplineDofHandler<dim>             &dofs;
    std::vector<const PhaseFieldTerm<dim> *> terms;
    const TrilinosWrappers::MPI::Vector     *phi     = nullptr;
    const TrilinosWrappers::MPI::Vector     *phi_dot = nullptr;
    const TrilinosWrappers::MPI::Vector     *psi     = nullptr;
    double mass_factor = 1, stiffness_factor = 1;
    bool   with_matrix = true;
  };
} // namespace vesicle_iga
