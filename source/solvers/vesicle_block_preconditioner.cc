// Block preconditioner of the coupled vesicle-flow tangent (spec Part H).
// See the header and doc/hydrodynamics.md ("Linear solver").

#include <vesicle_iga/solvers/inner_gmres.h>
#include <vesicle_iga/solvers/spline_multigrid.h>
#include <vesicle_iga/solvers/vesicle_block_preconditioner.h>

#include <sstream>

namespace vesicle_iga
{
  void
  PhaseFieldBlockParameters::declare(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;
    prm.declare_entry(
      "Phase field preconditioner",
      "spline-multigrid",
      Selection("spline-multigrid|amg"),
      "One V-cycle on each phase-field block (mass, advection and the "
      "fourth-order bending operator): the spline multigrid (smoother "
      "'Phase field smoother') or Trilinos ML AMG.");
    // schwarz-ilu, not ssor: in the extensional flows (HD2, HD5) the
    // advection of phi_i after the impulsive start dominates its block, and
    // the SSOR-smoothed V-cycle returned inf from a finite residual (the
    // second step of HD2 failed and was retried at dt / 4). Same counts and
    // cost on the shear doublet (doc/hydrodynamics.md).
    prm.declare_entry("Phase field smoother",
                      "schwarz-ilu",
                      Selection(SplineMultigridParameters::smoother_names()),
                      "Smoother of the phase-field spline multigrid: "
                        + SplineMultigridParameters::smoother_documentation());
    prm.declare_entry("Phase field sweeps",
                      "2",
                      Integer(1),
                      "Smoother sweeps (or Chebyshev degree) of the "
                      "phase-field spline multigrid.");
    prm.declare_entry("Phase field coarse size",
                      "0",
                      Integer(0),
                      "The phase-field spline multigrid coarsens until a "
                      "level has at most this many unknowns, solved by "
                      "sparse LU (0: the multigrid's default).");
    prm.declare_entry(
      "Phase field tolerance",
      "0",
      dealii::Patterns::Double(0, 1),
      "0: one V-cycle per phase-field block and application. > 0: GMRES on "
      "each phase-field block, preconditioned by that V-cycle, to this "
      "relative residual (at most 100 iterations).");
  }


  void
  PhaseFieldBlockParameters::parse(dealii::ParameterHandler &prm)
  {
    preconditioner = prm.get("Phase field preconditioner");
    smoother       = prm.get("Phase field smoother");
    sweeps         = prm.get_integer("Phase field sweeps");
    coarse_size    = prm.get_integer("Phase field coarse size");
    tolerance      = prm.get_double("Phase field tolerance");
  }


  using namespace dealii;

  namespace
  {
    /// Groups: 0 the flow (u, p), 1 the velocity, 2 + i phi_i,
    /// 2 + N + i lambda_i.
    std::vector<std::vector<unsigned int>>
    vesicle_groups(const unsigned int dim, const unsigned int n)
    {
      std::vector<std::vector<unsigned int>> groups(2);
      for (unsigned int c = 0; c <= dim; ++c)
        groups[0].push_back(c);
      for (unsigned int c = 0; c < dim; ++c)
        groups[1].push_back(c);
      for (unsigned int c = dim + 1; c < dim + 1 + 2 * n; ++c)
        groups.push_back({c});
      return groups;
    }


    /// The rows of -(M + D), D the diagonal @p diagonal (may be null).
    std::vector<MatrixRow>
    negated_rows(const TrilinosWrappers::SparseMatrix &M,
                 const TrilinosWrappers::MPI::Vector  *diagonal)
    {
      const IndexSet        &owned = M.locally_owned_range_indices();
      std::vector<MatrixRow> rows(owned.n_elements());
      std::size_t            k = 0;
      for (const auto i : owned)
        {
          for_each_row_entry(
            M, i, [&](const types::global_dof_index j, const double value) {
              rows[k].emplace_back(j, -value);
            });
          if (diagonal)
            rows[k].emplace_back(i, -(*diagonal)[i]);
          ++k;
        }
      return rows;
    }


    void
    initialize_amg(TrilinosWrappers::PreconditionAMG    &amg,
                   const TrilinosWrappers::SparseMatrix &matrix,
                   const unsigned int                    sweeps)
    {
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = true;
      data.smoother_sweeps       = sweeps;
      data.aggregation_threshold = 0.02;
      amg.initialize(matrix, data);
    }
  } // namespace


  VesicleBlockPreconditioner::VesicleBlockPreconditioner(
    const unsigned int                                  dim,
    const unsigned int                                  n_vesicles,
    const IndexSet                                     &owned,
    const MPI_Comm                                      comm,
    std::unique_ptr<FlowBlockPreconditioner>            flow_preconditioner,
    std::vector<std::unique_ptr<MatrixPreconditioner>>  phase_preconditioners,
    const std::function<bool(types::global_dof_index)> &constrained,
    const FlowBlockPreconditionerParameters            &parameters,
    const double                                        phase_tolerance)
    : dim(dim)
    , n(n_vesicles)
    , comm(comm)
    , prm(parameters)
    , phase_tolerance(phase_tolerance)
    , blocks(owned,
             dim + 1 + 2 * n_vesicles,
             vesicle_groups(dim, n_vesicles),
             comm)
    , flow(std::move(flow_preconditioner))
    , phase(std::move(phase_preconditioners))
    , flow_phi(n)
    , flow_lambda(n)
    , velocity_lambda(n)
    , lambda_phi(n)
    , lambda_lambda(n)
    , lambda_velocity(n)
    , transient_schur(n)
    , viscous_schur(n)
    , phi_phi(n)
    , transient_inverse(n)
    , viscous_inverse(n)
    , phase_amg(n)
    , constrained_tension(n)
    , constrained_diagonal(n)
    , lumped_tension(n)
  {
    AssertDimension(phase.size(), n);
    for (unsigned int i = 0; i < n; ++i)
      {
        phi_phi[i].resize(i + 1);
        constrained_tension[i]
          = blocks.local_positions(tension_group(i), constrained);
      }
    r_flow     = blocks.make_vector(0);
    x_flow     = r_flow;
    tmp_flow   = r_flow;
    r_phi      = blocks.make_vector(phase_group(0));
    r_lambda   = r_phi;
    tmp_lambda = r_phi;
    x_phi.assign(n, r_phi);
    x_lambda.assign(n, r_phi);
  }


  void
  VesicleBlockPreconditioner::set_lumped_operators(
    const TrilinosWrappers::MPI::Vector &lumped)
  {
    TrilinosWrappers::MPI::Vector lumped_flow = blocks.make_vector(0);
    blocks.extract(lumped, 0, lumped_flow);
    flow->set_lumped_operators(lumped_flow);
    lumped_velocity = blocks.make_vector(1);
    blocks.extract(lumped, 1, lumped_velocity);
    for (unsigned int i = 0; i < n; ++i)
      {
        lumped_tension[i] = blocks.make_vector(tension_group(i));
        blocks.extract(lumped, tension_group(i), lumped_tension[i]);
      }
  }


  void
  VesicleBlockPreconditioner::initialize(
    const TrilinosWrappers::SparseMatrix &matrix)
  {
    AssertThrow(lumped_velocity.size() > 0,
                ExcMessage("VesicleBlockPreconditioner: "
                           "set_lumped_operators() was not called"));
    // Flow rows: the flow block and its couplings to phi_i, lambda_i.
    {
      std::vector<unsigned int>                     columns{0};
      std::vector<TrilinosWrappers::SparseMatrix *> out{&F};
      for (unsigned int i = 0; i < n; ++i)
        {
          columns.push_back(phase_group(i));
          out.push_back(&flow_phi[i]);
          columns.push_back(tension_group(i));
          out.push_back(&flow_lambda[i]);
        }
      blocks.extract_blocks(matrix, 0, columns, out);
    }
    flow->initialize(F);
    {
      std::vector<unsigned int>                     columns;
      std::vector<TrilinosWrappers::SparseMatrix *> out;
      for (unsigned int i = 0; i < n; ++i)
        {
          columns.push_back(tension_group(i));
          out.push_back(&velocity_lambda[i]);
        }
      blocks.extract_blocks(matrix, 1, columns, out);
    }
    for (unsigned int i = 0; i < n; ++i)
      {
        std::vector<unsigned int>                     columns;
        std::vector<TrilinosWrappers::SparseMatrix *> out;
        for (unsigned int j = 0; j <= i; ++j)
          {
            columns.push_back(phase_group(j));
            out.push_back(&phi_phi[i][j]);
          }
        blocks.extract_blocks(matrix, phase_group(i), columns, out);
        if (phase[i])
          phase[i]->initialize(phi_phi[i][i]);
        else
          initialize_amg(phase_amg[i], phi_phi[i][i], 2);

        blocks.extract_blocks(matrix,
                              tension_group(i),
                              {phase_group(i), tension_group(i), 1},
                              {&lambda_phi[i],
                               &lambda_lambda[i],
                               &lambda_velocity[i]});
        initialize_tension(i);
      }
  }


  void
  VesicleBlockPreconditioner::initialize_tension(const unsigned int i)
  {
    const IndexSet &owned = blocks.owned(tension_group(i));
    // The rows of strong conditions keep their diagonal; they are solved
    // by it in vmult() and enter both operators as identity rows.
    constrained_diagonal[i].clear();
    for (const unsigned int k : constrained_tension[i])
      constrained_diagonal[i].push_back(
        lambda_lambda[i].diag_element(owned.nth_index_in_set(k)));
    const auto fix_constrained_rows = [&](std::vector<MatrixRow> &rows) {
      for (const unsigned int k : constrained_tension[i])
        rows[k] = {{owned.nth_index_in_set(k), 1.}};
    };

    // Small steps: L + E M_L^-1 E^T, the product by Trilinos.
    TrilinosWrappers::MPI::Vector minus_inverse_mass(lumped_velocity);
    for (auto &v : minus_inverse_mass)
      v = v != 0 ? -1. / v : 0.;
    TrilinosWrappers::SparseMatrix  product;
    TrilinosWrappers::SparseMatrix &transient = transient_schur[i];
    TrilinosWrappers::SparseMatrix &viscous   = viscous_schur[i];
    lambda_velocity[i].mmult(product, velocity_lambda[i], minus_inverse_mass);
    {
      std::vector<MatrixRow> rows = negated_rows(lambda_lambda[i], nullptr);
      std::size_t            k    = 0;
      for (const auto r : owned)
        {
          for_each_row_entry(product,
                             r,
                             [&](const types::global_dof_index j,
                                 const double                  value) {
                               rows[k].emplace_back(j, -value);
                             });
          ++k;
        }
      fix_constrained_rows(rows);
      make_distributed_matrix(owned, owned, comm, rows, transient);
    }
    // Viscous limit: L + M_nu,i (the lumped operator enters with the sign
    // of Lambda_ii, negative).
    {
      TrilinosWrappers::MPI::Vector minus_lumped(lumped_tension[i]);
      minus_lumped *= -1.;
      std::vector<MatrixRow> rows
        = negated_rows(lambda_lambda[i], &minus_lumped);
      fix_constrained_rows(rows);
      make_distributed_matrix(owned, owned, comm, rows, viscous);
    }
    initialize_amg(transient_inverse[i], transient, prm.schur_sweeps);
    initialize_amg(viscous_inverse[i], viscous, prm.schur_sweeps);
  }


  void
  VesicleBlockPreconditioner::vmult(
    TrilinosWrappers::MPI::Vector       &dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    blocks.extract(src, 0, r_flow);
    for (unsigned int i = 0; i < n; ++i)
      {
        // Phase fields: block Gauss-Seidel over the vesicles.
        blocks.extract(src, phase_group(i), r_phi);
        for (unsigned int j = 0; j < i; ++j)
          {
            phi_phi[i][j].vmult(tmp_lambda, x_phi[j]);
            r_phi -= tmp_lambda;
          }
        solve_phase(i);

        // Tension: S_i^-1 (r_lambda - L_phi phi_i), both limits added.
        blocks.extract(src, tension_group(i), r_lambda);
        lambda_phi[i].vmult(tmp_lambda, x_phi[i]);
        r_lambda -= tmp_lambda;
        transient_inverse[i].vmult(x_lambda[i], r_lambda);
        viscous_inverse[i].vmult(tmp_lambda, r_lambda);
        x_lambda[i] += tmp_lambda;
        x_lambda[i] *= -1.;
        const IndexSet &owned = blocks.owned(tension_group(i));
        for (std::size_t c = 0; c < constrained_tension[i].size(); ++c)
          {
            const auto row = owned.nth_index_in_set(constrained_tension[i][c]);
            x_lambda[i][row] = r_lambda[row] / constrained_diagonal[i][c];
          }

        // The flow sees the forces of phi_i and lambda_i.
        flow_phi[i].vmult(tmp_flow, x_phi[i]);
        r_flow -= tmp_flow;
        flow_lambda[i].vmult(tmp_flow, x_lambda[i]);
        r_flow -= tmp_flow;
      }
    flow->vmult(x_flow, r_flow);

    blocks.insert(x_flow, 0, dst);
    for (unsigned int i = 0; i < n; ++i)
      {
        blocks.insert(x_phi[i], phase_group(i), dst);
        blocks.insert(x_lambda[i], tension_group(i), dst);
      }
  }


  void
  VesicleBlockPreconditioner::solve_phase(const unsigned int i) const
  {
    if (phase[i])
      apply_block_inverse(
        phi_phi[i][i], *phase[i], phase_tolerance, x_phi[i], r_phi);
    else
      apply_block_inverse(
        phi_phi[i][i], phase_amg[i], phase_tolerance, x_phi[i], r_phi);
  }


  std::string
  VesicleBlockPreconditioner::description() const
  {
    std::ostringstream s;
    s << "vesicle blocks: "
      << (phase.empty() || !phase[0] ? std::string("AMG") :
                                       phase[0]->description())
      << (phase_tolerance > 0 ? " inside GMRES" : "") << " on each of " << n
      << " phase fields, two AMG V-cycles per "
      << "tension Schur complement; " << flow->description();
    return s.str();
  }
} // namespace vesicle_iga
