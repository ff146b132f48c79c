// Block preconditioner of the RBVMS velocity-pressure tangent. See the
// header and doc/flow.md ("Linear solver").

#include <vesicle_iga/solvers/flow_block_preconditioner.h>
#include <vesicle_iga/solvers/interleaved_blocks.h>

#include <sstream>
#include <utility>

namespace vesicle_iga
{
  using namespace dealii;


  FlowBlockPreconditioner::FlowBlockPreconditioner(
    const unsigned int                       dim,
    const FlowBlockPreconditionerParameters &prm)
    : dim(dim)
    , prm(prm)
    , cahouet_chabard(prm.schur_approximation == "cahouet-chabard")
    , direct_control(1, 0.)
  {}


  void
  FlowBlockPreconditioner::set_velocity_preconditioner(
    std::unique_ptr<MatrixPreconditioner> velocity)
  {
    velocity_preconditioner = std::move(velocity);
  }


  void
  FlowBlockPreconditioner::set_lumped_operators(
    const TrilinosWrappers::MPI::Vector &lumped_operators)
  {
    lumped = lumped_operators;
  }


  void
  FlowBlockPreconditioner::initialize(
    const TrilinosWrappers::SparseMatrix &matrix)
  {
    if (prm.schur_approximation == "direct")
      {
        direct
          = std::make_unique<TrilinosWrappers::SolverDirect>(direct_control);
        direct->initialize(matrix);
        return;
      }
    const MPI_Comm     comm    = matrix.get_mpi_communicator();
    const IndexSet    &owned   = matrix.locally_owned_range_indices();
    const unsigned int nc      = dim + 1;
    const auto         n_basis = matrix.m() / nc;

    // Index sets of the blocks and the local positions (the maps from
    // monolithic to block indices are monotone, so local order is kept).
    velocity_owned = IndexSet(n_basis * dim);
    pressure_owned = IndexSet(n_basis);
    local_position.clear();
    long n_velocity = 0, n_pressure = 0;
    for (const auto i : owned)
      {
        const auto b = i / nc, c = i % nc;
        if (c < dim)
          {
            velocity_owned.add_index(b * dim + c);
            local_position.push_back(n_velocity++);
          }
        else
          {
            pressure_owned.add_index(b);
            local_position.push_back(-1 - n_pressure++);
          }
      }
    velocity_owned.compress();
    pressure_owned.compress();

    // Split the owned rows into the four blocks.
    std::vector<MatrixRow> rows_A(n_velocity), rows_B(n_velocity),
      rows_D(n_pressure), rows_C(n_pressure);
    std::size_t k = 0;
    for (const auto i : owned)
      {
        const long position = local_position[k++];
        for_each_row_entry(matrix, i, [&](const auto j, const double value) {
          const auto b = j / nc, c = j % nc;
          const bool column_velocity = c < dim;
          const auto column          = column_velocity ? b * dim + c : b;
          if (position >= 0)
            (column_velocity ? rows_A : rows_B)[position].emplace_back(column,
                                                                       value);
          else
            (column_velocity ? rows_D : rows_C)[-1 - position].emplace_back(
              column, value);
        });
      }
    make_distributed_matrix(velocity_owned, velocity_owned, comm, rows_A, A);
    make_distributed_matrix(velocity_owned, pressure_owned, comm, rows_B, B);
    make_distributed_matrix(pressure_owned, velocity_owned, comm, rows_D, D);

    // The diagonal that replaces A in the Schur complement: the lumped
    // velocity mass (Cahouet-Chabard) or diag(A) (SIMPLE).
    AssertThrow(!cahouet_chabard || lumped.size() == matrix.m(),
                ExcMessage("FlowBlockPreconditioner: set_lumped_operators() "
                           "was not called"));
    TrilinosWrappers::MPI::Vector minus_inverse_diagonal(velocity_owned, comm);
    inverse_viscous_mass.assign(n_pressure, 0.);
    {
      const double *l = cahouet_chabard ? lumped.begin() : nullptr;
      for (k = 0; k < local_position.size(); ++k)
        {
          const long position = local_position[k];
          if (position >= 0)
            {
              const auto   row = velocity_owned.nth_index_in_set(position);
              const double d   = cahouet_chabard ? l[k] : A.diag_element(row);
              minus_inverse_diagonal[row] = d != 0 ? -1. / d : 0.;
            }
          else if (cahouet_chabard && l[k] != 0)
            inverse_viscous_mass[-1 - position] = 1. / l[k];
        }
    }
    minus_inverse_diagonal.compress(VectorOperation::insert);

    // S = C - D diag^{-1} B: the product by Trilinos (EpetraExt), then C
    // added row by row (the patterns differ).
    TrilinosWrappers::SparseMatrix product;
    D.mmult(product, B, minus_inverse_diagonal);
    std::vector<MatrixRow> rows_S(n_pressure);
    k = 0;
    for (const auto i : pressure_owned)
      {
        MatrixRow &row = rows_S[k];
        for_each_row_entry(product, i, [&](const auto j, const double value) {
          row.emplace_back(j, value);
        });
        // Repeated columns are summed by make_distributed_matrix.
        row.insert(row.end(), rows_C[k].begin(), rows_C[k].end());
        ++k;
      }
    make_distributed_matrix(pressure_owned, pressure_owned, comm, rows_S, S);

    // One null-space vector per velocity component.
    TrilinosWrappers::PreconditionAMG::AdditionalData velocity_data;
    velocity_data.elliptic              = prm.velocity_elliptic;
    velocity_data.higher_order_elements = true;
    velocity_data.smoother_sweeps       = prm.velocity_sweeps;
    velocity_data.aggregation_threshold = 0.02;
    velocity_data.constant_modes.assign(dim,
                                        std::vector<bool>(n_velocity, false));
    k = 0;
    for (const auto i : velocity_owned)
      velocity_data.constant_modes[i % dim][k++] = true;
    if (velocity_preconditioner)
      velocity_preconditioner->initialize(A);
    else
      A_inverse.initialize(A, velocity_data);

    TrilinosWrappers::PreconditionAMG::AdditionalData schur_data;
    schur_data.elliptic              = true;
    schur_data.higher_order_elements = true;
    schur_data.smoother_sweeps       = prm.schur_sweeps;
    schur_data.aggregation_threshold = 0.02;
    S_inverse.initialize(S, schur_data);

    u.reinit(velocity_owned, comm);
    r_u.reinit(velocity_owned, comm);
    tmp_u.reinit(velocity_owned, comm);
    p.reinit(pressure_owned, comm);
    r_p.reinit(pressure_owned, comm);
  }


  void
  FlowBlockPreconditioner::split(const TrilinosWrappers::MPI::Vector &full,
                                 TrilinosWrappers::MPI::Vector       &velocity,
                                 TrilinosWrappers::MPI::Vector &pressure) const
  {
    auto       *v = velocity.begin();
    auto       *q = pressure.begin();
    const auto *f = full.begin();
    for (std::size_t k = 0; k < local_position.size(); ++k)
      if (local_position[k] >= 0)
        v[local_position[k]] = f[k];
      else
        q[-1 - local_position[k]] = f[k];
  }


  void
  FlowBlockPreconditioner::vmult(TrilinosWrappers::MPI::Vector       &dst,
                                 const TrilinosWrappers::MPI::Vector &src) const
  {
    if (direct)
      {
        direct->solve(dst, src);
        return;
      }
    // P^{-1} = [A B; 0 S]^{-1}: p = S^{-1} r_p, u = A^{-1} (r_u - B p).
    split(src, r_u, r_p);
    S_inverse.vmult(p, r_p);
    if (cahouet_chabard)
      {
        auto       *q = p.begin();
        const auto *r = r_p.begin();
        for (std::size_t k = 0; k < inverse_viscous_mass.size(); ++k)
          q[k] += inverse_viscous_mass[k] * r[k];
      }
    B.vmult(tmp_u, p);
    r_u -= tmp_u;
    if (velocity_preconditioner)
      velocity_preconditioner->vmult(u, r_u);
    else
      A_inverse.vmult(u, r_u);

    auto       *d = dst.begin();
    const auto *v = u.begin();
    const auto *q = p.begin();
    for (std::size_t k = 0; k < local_position.size(); ++k)
      d[k] = local_position[k] >= 0 ? v[local_position[k]] :
                                      q[-1 - local_position[k]];
  }


  std::string
  FlowBlockPreconditioner::description() const
  {
    std::ostringstream s;
    if (prm.schur_approximation == "direct")
      return "sparse LU of the velocity-pressure block";
    s << "block upper-triangular: "
      << (velocity_preconditioner ? velocity_preconditioner->description() :
                                    std::string("AMG"))
      << " on velocity (" << A.m() << " unknowns), " << prm.schur_approximation
      << " Schur complement approximation (" << S.m() << " unknowns)";
    return s.str();
  }
} // namespace vesicle_iga
