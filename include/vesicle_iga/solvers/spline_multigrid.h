#pragma once

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vesicle_iga/fields/spline_dof_handler.h>

#include <functional>
#include <memory>
#include <vector>

namespace vesicle_iga
{

  /**
   * A preconditioner that is rebuilt for every new matrix.
   */
  class MatrixPreconditioner
  {
  public:
    virtual ~MatrixPreconditioner() = default;
    virtual void
    initialize(const dealii::TrilinosWrappers::SparseMatrix &matrix)
      = 0;
    virtual void
    vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
          const dealii::TrilinosWrappers::MPI::Vector &src) const = 0;
    /// One line for logs: levels, unknowns per level, smoother.
    virtual std::string
    description() const = 0;
  };

  struct SplineMultigridParameters
  {
    std::string  smoother        = "ssor";
    unsigned int sweeps          = 2;
    unsigned int coarse_size     = 4000;
    double       ssor_relaxation = 1.0;
    /// Layers of matrix neighbours added to each rank's rows (schwarz-ilu).
    unsigned int overlap = 1;

    /// The smoother names, for Patterns::Selection wherever a spline
    /// multigrid is configured, and what each means.
    static const char *
    smoother_names();
    static std::string
    smoother_documentation();

    static void
    declare(dealii::ParameterHandler &prm,
            const std::string        &default_smoother = "ssor",
            const std::string        &default_sweeps   = "2");
    void
    parse(dealii::ParameterHandler &prm);
  };

  /**
   * Geometric multigrid on the nested spline spaces of a tensor-product
   * box (doc/solvers.md): the level spaces are obtained by removing every
   * other breakpoint per direction, the prolongation is the exact knot
   * insertion operator (Kronecker product of univariate matrices), the
   * level matrices are the Galerkin products A_{l-1} = P^T A_l P, the
   * smoother is processor-local symmetric Gauss-Seidel (SSOR), Chebyshev,
   * ILU(0) per rank or restricted additive Schwarz with ILU(0) subdomain
   * solves (RestrictedSchwarzILU), and the coarsest level is solved by
   * Amesos KLU. One V-cycle is the
   * preconditioner.
   *
   * Why: Krylov methods with ILU or algebraic multigrid need hundreds of
   * iterations for the fourth-order operators of spec Part E once the time
   * step is large (the biharmonic part dominates) and become slower with
   * every refinement; the spline hierarchy gives mesh-independent counts.
   *
   * Constraints: homogeneous Dirichlet rows (x_i = 0, no coupling) on the
   * fine level are allowed. A coarse function is kept only if its fine
   * representation avoids every constrained function, so every level space
   * is a subspace of the constrained fine space; the constrained fine rows
   * (identity-like after condensation) are handled by the smoother alone.
   */
  template <int dim>
  class SplineMultigrid : public MatrixPreconditioner
  {
  public:
    SplineMultigrid(const SplineDofHandler<dim>             &dofs,
                    const dealii::AffineConstraints<double> &zero_constraints,
                    const SplineMultigridParameters         &parameters);
    /// A vector-valued field of @p n_components components on the spline
    /// space of @p dofs: @p unknown(basis, component) gives the matrix row
    /// of each (natural basis index, component), @p owned the rows of this
    /// rank (whole basis functions, contiguous), @p constrained the rows
    /// that are homogeneous Dirichlet rows. Every component is coarsened
    /// by the same knot removal (the velocity block of the flow solver).
    SplineMultigrid(
      const SplineDofHandler<dim> &dofs,
      const unsigned int           n_components,
      const std::function<
        dealii::types::global_dof_index(unsigned int, unsigned int)> &unknown,
      const dealii::IndexSet                                         &owned,
      const std::function<bool(dealii::types::global_dof_index)> &constrained,
      const SplineMultigridParameters                            &parameters);
    ~SplineMultigrid() override;

    void
    initialize(const dealii::TrilinosWrappers::SparseMatrix &matrix) override;
    void
    vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
          const dealii::TrilinosWrappers::MPI::Vector &src) const override;
    std::string
    description() const override;

    unsigned int
    n_levels() const
    {
      return levels.size();
    }

  private:
    struct Level;
    void
    setup(
      const SplineSpace<dim> &space,
      const unsigned int      n_components,
      const std::function<
        dealii::types::global_dof_index(unsigned int, unsigned int)> &unknown,
      const dealii::IndexSet                                         &owned,
      const std::function<bool(dealii::types::global_dof_index)> &constrained);
    /// The next coarser level of @p fine (every direction that can be
    /// halved is), or nullptr if none can. Sets fine's prolongation, and
    /// turns @p constrained (per natural index of @p fine) into the flags of
    /// the coarse level: a coarse function whose fine representation
    /// touches a constrained function is not kept.
    std::unique_ptr<Level>
    coarser_level(Level &fine, std::vector<bool> &constrained) const;
    void
    v_cycle(const unsigned int                           l,
            dealii::TrilinosWrappers::MPI::Vector       &x,
            const dealii::TrilinosWrappers::MPI::Vector &b) const;

    SplineMultigridParameters           prm;
    MPI_Comm                            communicator;
    std::vector<std::unique_ptr<Level>> levels; // 0: coarsest
  };
} // namespace vesicle_iga
