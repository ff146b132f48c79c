#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/solvers/interleaved_blocks.h>
#include <vesicle_iga/solvers/linear_solver.h>
#include <vesicle_iga/solvers/spline_multigrid.h>

#include <memory>
#include <string>
#include <vector>

namespace vesicle_iga
{
  /// A block preconditioner whose Schur complement approximations need
  /// lumped operators assembled at the state of each new matrix.
  class LumpedOperatorPreconditioner : public MatrixPreconditioner
  {
  public:
    /// The lumped operators of the coming matrix, in its layout.
    virtual void
    set_lumped_operators(const dealii::TrilinosWrappers::MPI::Vector &lumped)
      = 0;
  };


  /**
   * Block upper-triangular preconditioner of the RBVMS velocity-pressure
   * tangent (doc/flow.md, "Linear solver"):
   *
   *   K = [A  B]      P = [A  B]       S ~ C - D A^{-1} B,
   *       [D  C],         [0  S],
   *
   * with A the velocity block (mass, viscous, convective and fine-scale
   * terms), B and D the pressure-gradient and divergence couplings and C
   * the pressure block that the RBVMS term (grad q, tau_M grad p) of (H14)
   * makes positive definite. A^{-1} is one V-cycle of the caller's velocity
   * preconditioner (the spline multigrid of the velocity components, see
   * set_velocity_preconditioner()) or of Trilinos ML AMG with one
   * null-space vector per velocity component. Two Schur approximations:
   *
   *  - cahouet-chabard (default): S^{-1} = M_nu^{-1} + S_t^{-1}, the
   *    viscous part M_nu the lumped pressure mass weighted by
   *    k_p / (mu* / Re + tau_C) (Stokes Schur complement with the grad-div
   *    term), the transient part S_t = C - D M_L^{-1} B with M_L the lumped
   *    velocity mass k_m int N_i (a pressure Laplacian built algebraically
   *    by a Trilinos matrix product, inverted by one AMG V-cycle). Both
   *    limits (steady Stokes, small steps) are spectrally equivalent to
   *    the true Schur complement independently of h, so the Krylov count
   *    should not grow under refinement; it grows with the Reynolds number
   *    of the step, as convection is not in S.
   *  - stabilized-cahouet-chabard: S^{-1} = (M_nu + C)^{-1} + S_t^{-1}
   *    with M_nu the consistent viscous pressure mass (the pressure Gram
   *    matrix of set_pressure_mass() scaled symmetrically by the weights
   *    of the lumped one). The equal-order pressure modes near the
   *    checkerboard are controlled by C alone in the true Schur
   *    complement, while the lumped mass overestimates them (by up to 340
   *    for cubic splines in 2D) and the consistent mass underestimates
   *    them: M_nu + C sees both families. Solved by CG with AMG to a
   *    relative tolerance (or one V-cycle).
   *  - simple: S = C - D diag(A)^{-1} B, fully algebraic; in viscous flows
   *    diag(A) ~ nu / h^2 makes S too small for smooth pressures and the
   *    count doubles per refinement (measured in doc/flow.md).
   *  - direct: no block approximation, the whole matrix by sparse LU; a
   *    diagnostic of what the approximations cost (doc/hydrodynamics.md).
   *
   * The lumped operators come from RBVMSLumpedSchurOperators, in the
   * monolithic layout, through set_lumped_operators() before initialize().
   *
   * The unknowns of the monolithic matrix are interleaved per spline basis
   * function (u_1, ..., u_dim, p) and every rank owns whole basis
   * functions (SplineDofHandler), so the blocks are extracted row by row
   * without communication.
   */
  class FlowBlockPreconditioner : public LumpedOperatorPreconditioner
  {
  public:
    FlowBlockPreconditioner(const unsigned int                       dim,
                            const FlowBlockPreconditionerParameters &prm);

    /// One V-cycle of @p velocity (initialized by initialize() with the
    /// velocity block, numbered basis * dim + component) replaces AMG.
    void
    set_velocity_preconditioner(std::unique_ptr<MatrixPreconditioner> velocity);
    /// The lumped velocity mass (velocity entries) and lumped viscous
    /// pressure mass (pressure entries) of the coming matrix.
    void
    set_lumped_operators(
      const dealii::TrilinosWrappers::MPI::Vector &lumped) override;
    /// The Gram matrix of the pressure space, in the numbering of the
    /// pressure block (stabilized-cahouet-chabard).
    void
    set_pressure_mass(
      std::shared_ptr<const dealii::TrilinosWrappers::SparseMatrix> mass);
    void
    initialize(const dealii::TrilinosWrappers::SparseMatrix &matrix) override;
    void
    vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
          const dealii::TrilinosWrappers::MPI::Vector &src) const override;
    std::string
    description() const override;

  private:
    /// The blocks A, B, D of @p matrix (with the index sets and local
    /// positions of velocity and pressure); returns C's owned rows.
    std::vector<MatrixRow>
    extract_blocks(const dealii::TrilinosWrappers::SparseMatrix &matrix);
    /// S = C - D diag^{-1} B, diag the lumped velocity mass
    /// (cahouet-chabard forms) or diag(A) (simple).
    void
    initialize_schur_complement(const std::vector<MatrixRow> &rows_C);
    /// The velocity block's V-cycle, or AMG with the componentwise
    /// constant modes.
    void
    initialize_velocity_solver();
    /// M_nu + C of stabilized-cahouet-chabard and its AMG.
    void
    initialize_viscous_schur(const std::vector<MatrixRow> &rows_C);
    /// u = A^{-1} r_u: one V-cycle, or GMRES preconditioned by it to
    /// 'Velocity tolerance'.
    template <typename VCycle>
    void
    solve_velocity(const VCycle &v_cycle) const;
    void
    split(const dealii::TrilinosWrappers::MPI::Vector &full,
          dealii::TrilinosWrappers::MPI::Vector       &velocity,
          dealii::TrilinosWrappers::MPI::Vector       &pressure) const;

    const unsigned int                      dim;
    const FlowBlockPreconditionerParameters prm;

    dealii::IndexSet velocity_owned, pressure_owned;
    // For each locally owned entry of the monolithic vector: its position
    // in the local part of the velocity (>= 0) or pressure (< 0: -1 - k)
    // vector.
    std::vector<long> local_position;

    dealii::TrilinosWrappers::MPI::Vector lumped;
    std::vector<double> inverse_viscous_mass; // local pressure entries
    dealii::TrilinosWrappers::SparseMatrix    A, B, D, S;
    dealii::TrilinosWrappers::PreconditionAMG A_inverse, S_inverse;
    std::unique_ptr<MatrixPreconditioner>     velocity_preconditioner;
    std::shared_ptr<const dealii::TrilinosWrappers::SparseMatrix> pressure_mass;
    dealii::TrilinosWrappers::SparseMatrix                        V;
    dealii::TrilinosWrappers::PreconditionAMG                     V_amg;
    mutable dealii::TrilinosWrappers::MPI::Vector                 p_viscous;
    mutable dealii::TrilinosWrappers::MPI::Vector u, p, r_u, r_p, tmp_u;
    bool                                          cahouet_chabard, stabilized;
    dealii::SolverControl                         direct_control;
    std::unique_ptr<dealii::TrilinosWrappers::SolverDirect> direct;
  };
} // namespace vesicle_iga
