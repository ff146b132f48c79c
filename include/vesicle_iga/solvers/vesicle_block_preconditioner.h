#pragma once

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/solvers/flow_block_preconditioner.h>
#include <vesicle_iga/solvers/interleaved_blocks.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vesicle_iga
{
  /// Settings of the phase-field blocks of VesicleBlockPreconditioner,
  /// declared by the vesicle study only (subsection "Linear solver/Block
  /// preconditioner", next to the flow's own block settings).
  struct PhaseFieldBlockParameters
  {
    /// "spline-multigrid" or "amg" on each phase-field block.
    std::string preconditioner = "spline-multigrid";
    /// Smoother and sweeps of the phase-field spline multigrid.
    std::string  smoother = "schwarz-ilu";
    unsigned int sweeps   = 2;
    /// Largest level solved by LU (0: the SplineMultigrid default).
    unsigned int coarse_size = 0;
    /// > 0: each phase-field block by GMRES with the V-cycle to this relative
    /// residual instead of one V-cycle.
    double tolerance = 0.;

    /// Declares (parses) the entries in the current subsection.
    static void
    declare(dealii::ParameterHandler &prm);
    void
    parse(dealii::ParameterHandler &prm);
  };


  /**
   * Block preconditioner of the tangent of N vesicles in a flow (spec Part
   * H, doc/hydrodynamics.md "Linear solver"). Unknowns interleaved per
   * basis function: u (dim components), p, phi_1..phi_N, lambda_1..lambda_N.
   * With F the velocity-pressure block, Phi_ij the phase-field blocks,
   * Lambda the tension blocks and E_i the inextensibility rows of u:
   *
   *       [F       B_phi    B_lambda]           [F  B_phi  B_lambda]
   *   K = [A_phi   Phi      0       ]       P = [0  Phi_L  0       ]
   *       [E       L_phi    Lambda  ],          [0  L_phi  S       ],
   *
   * P is block triangular in the order (phi, lambda, (u, p)): the phase
   * fields first (block Gauss-Seidel over the vesicles, Phi_L the lower
   * block triangle of Phi, each diagonal block by one V-cycle of the
   * caller's spline multigrid or AMG: mass plus the fourth-order bending
   * operator of (H24)), then each tension with its Schur complement
   * S_i = Lambda_ii - E_i F^-1 B_lambda,i, then the flow by the flow's own
   * block preconditioner. Dropped: the advection rows A_phi (the flow's
   * feedback on the phase fields, of the size of the bending term at the
   * spec's parameters) and the flow's inextensibility coupling beyond S.
   *
   * S_i: -Lambda_ii = L_i = -(grad s, xi eps^2 phi^2 grad lambda) is the
   * degenerate weighted Laplacian of (H17), E_i F^-1 E_i^T adds the
   * membrane's resistance. As in Cahouet-Chabard for the pressure, the two
   * limits of F are added in the inverse:
   *   S_i^-1 ~ -(L_i + E_i M_L^-1 E_i^T)^-1 - (L_i + M_nu,i)^-1,
   * M_L the lumped velocity mass (small steps), M_nu,i the lumped mass
   * k_lambda int delta_eps(phi_i)^2 N / (mu* / Re + tau_C) (viscous limit:
   * the surface divergence of a Stokes flow with the viscosity of the
   * pressure Schur complement); each by one AMG V-cycle. Either limit alone
   * is within a factor 2 of S_i where it applies.
   *
   * The lumped operators (flow entries as for FlowBlockPreconditioner,
   * M_nu,i on the tension rows) come through set_lumped_operators() before
   * initialize().
   */
  class VesicleBlockPreconditioner : public LumpedOperatorPreconditioner
  {
  public:
    /// @p flow: the velocity-pressure preconditioner (its own layout:
    /// basis (dim + 1) + component); @p phase: one per vesicle (one
    /// component, numbered by basis; null: AMG); @p constrained: whether a
    /// monolithic unknown is a strong condition (identity row).
    VesicleBlockPreconditioner(
      const unsigned int                                          dim,
      const unsigned int                                          n_vesicles,
      const dealii::IndexSet                                     &owned,
      const MPI_Comm                                              comm,
      std::unique_ptr<FlowBlockPreconditioner>                    flow,
      std::vector<std::unique_ptr<MatrixPreconditioner>>          phase,
      const std::function<bool(dealii::types::global_dof_index)> &constrained,
      const FlowBlockPreconditionerParameters                    &parameters,
      const double phase_tolerance = 0.);

    /// Lumped operators in the monolithic layout: the flow's on velocity and
    /// pressure rows, M_nu,i on the tension rows.
    void
    set_lumped_operators(
      const dealii::TrilinosWrappers::MPI::Vector &lumped) override;
    void
    initialize(const dealii::TrilinosWrappers::SparseMatrix &matrix) override;
    void
    vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
          const dealii::TrilinosWrappers::MPI::Vector &src) const override;
    std::string
    description() const override;

  private:
    unsigned int
    phase_group(const unsigned int i) const
    {
      return 2 + i;
    }
    unsigned int
    tension_group(const unsigned int i) const
    {
      return 2 + n + i;
    }
    /// -(L_i + X) for the diagonal or matrix X: the positive operator whose
    /// inverse approximates -S_i^-1 in one limit.
    void
    initialize_tension(const unsigned int i);
    /// x_phi[i] from r_phi: one V-cycle, or GMRES with it to
    /// phase_tolerance.
    void
    solve_phase(const unsigned int i) const;

    const unsigned int                       dim, n;
    const MPI_Comm                           comm;
    const FlowBlockPreconditionerParameters  prm;
    const double                             phase_tolerance;
    const InterleavedBlocks                  blocks; // flow, u, phi_i, lambda_i
    std::unique_ptr<FlowBlockPreconditioner> flow;
    std::vector<std::unique_ptr<MatrixPreconditioner>> phase;

    dealii::TrilinosWrappers::SparseMatrix F;
    /// Per vesicle: flow rows x (phi_i, lambda_i) columns; velocity rows x
    /// lambda_i; lambda_i rows x (phi_i, lambda_i, u); phi_i rows x phi_j,
    /// j <= i.
    std::vector<dealii::TrilinosWrappers::SparseMatrix> flow_phi, flow_lambda,
      velocity_lambda, lambda_phi, lambda_lambda, lambda_velocity;
    /// The two operators of the tension Schur complement (kept: ML refers
    /// to them).
    std::vector<dealii::TrilinosWrappers::SparseMatrix> transient_schur,
      viscous_schur;
    std::vector<std::vector<dealii::TrilinosWrappers::SparseMatrix>> phi_phi;
    std::vector<dealii::TrilinosWrappers::PreconditionAMG> transient_inverse,
      viscous_inverse, phase_amg;
    std::vector<std::vector<unsigned int>> constrained_tension;
    std::vector<std::vector<double>>       constrained_diagonal;

    dealii::TrilinosWrappers::MPI::Vector              lumped_velocity;
    std::vector<dealii::TrilinosWrappers::MPI::Vector> lumped_tension;

    mutable dealii::TrilinosWrappers::MPI::Vector r_flow, x_flow, tmp_flow,
      r_lambda, tmp_lambda;
    mutable std::vector<dealii::TrilinosWrappers::MPI::Vector> x_phi, x_lambda;
    mutable dealii::TrilinosWrappers::MPI::Vector              r_phi;
  };
} // namespace vesicle_iga
