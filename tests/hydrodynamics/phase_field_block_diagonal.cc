// The phase-field rows of the Part H Jacobian keep a positive diagonal at
// the boundary (issue 15: HD3 failed at t = 0.088 when they did not).
//
// Set-up: [0, 2]^2, 16^2 cubic C^2 elements, the fields of Part H with one
// vesicle (u, p, phi, lambda); the state outside every vesicle, phi = -1,
// in the shear u = (10 (y - 1), 0) (divergence-free; it enters through
// x = 0 above y = 1 and through x = 2 below), lambda_g = 115 (HD3's value
// at t = 0.088), lambda_v = 0. The Jacobian of transport (H16), inflow
// (spec 4.10) and global multipliers ((H16) with A' of (H12c)) is
// assembled as the time step sees it: rate factor alpha_m = 5/6, value
// factor alpha_f gamma dt with dt = 0.02 (rho_inf = 0.5).
// Theory:
// - transport alone: (N_i, u . grad N_i) = 1/2 (u.m N_i^2) on the boundary
//   (div u = 0), so the rows of the functions at the inflow ends get
//   negative diagonal entries once alpha_f gamma dt |u.m| outweighs their
//   mass (here |u.m| = 10 near the corners, dt = 0.02): some rows <= 0;
// - with the inflow term the boundary part is 1/2 |u.m| N_i^2 >= 0: every
//   diagonal entry is positive;
// - the multiplier term is lambda_g (eps |grad N_i|^2 + W''(-1)/eps N_i^2)
//   >= 0 on the diagonal (its pointwise form -lambda_g eps (N_i, Delta N_i)
//   is negative for the boundary functions, which is what broke HD3):
//   with it every entry stays positive and none decreases.
// The counts printed are of rows (the boundary rows are a fixed set); the
// expected counts were checked against the sign argument above: the rows
// with a negative transport diagonal are those of the two inflow ends.
// Checked that the test fails: with the multiplier term of before (the
// pointwise f), the last line reads 64 rows <= 0 and 64 decreased.

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vesicle_iga/fields/field_layout.h>
#include <vesicle_iga/fields/natural_numbering.h>
#include <vesicle_iga/fields/spline_dof_handler.h>
#include <vesicle_iga/kernel/system_assembler.h>
#include <vesicle_iga/parallel/patch_mesh.h>
#include <vesicle_iga/physics/hydrodynamic_membrane.h>
#include <vesicle_iga/terms/global_constraint_forcing.h>
#include <vesicle_iga/terms/phase_field_advection.h>
#include <vesicle_iga/terms/phase_field_inflow.h>

#include <fstream>

#include "vesicle_flow_setup.h"

using namespace vesicle_iga;
using namespace dealii;

namespace
{
  struct DiagonalCount
  {
    unsigned int nonpositive = 0, decreased = 0;
  };

  /// The phi rows of the Jacobian of @p terms at @p state: how many
  /// diagonal entries are <= 0 and how many are below @p reference.
  DiagonalCount
  phi_diagonal(const SplineDofHandler<2>    &dofs,
               const std::vector<Term<2> *> &terms,
               const AssemblyState          &state,
               const std::vector<double>    &reference,
               std::vector<double>          *diagonal = nullptr)
  {
    SystemAssembler<2> assembler(dofs, QGauss<1>(5));
    for (Term<2> *t : terms)
      assembler.add_term(*t);
    TrilinosWrappers::SparsityPattern sparsity;
    dofs.make_sparsity_pattern(sparsity);
    TrilinosWrappers::SparseMatrix  K(sparsity);
    const AffineConstraints<double> none;
    assembler.assemble(state, none, nullptr, &K);
    DiagonalCount      count;
    const unsigned int nc = dofs.n_components();
    unsigned int       k  = 0;
    for (const auto g : dofs.locally_owned_dofs())
      if (g % nc == 3)
        {
          const double d = K.diag_element(g);
          count.nonpositive += d <= 0;
          if (!reference.empty())
            count.decreased += d < reference[k] * (1 - 1e-12);
          if (diagonal)
            diagonal->push_back(d);
          ++k;
        }
    count.nonpositive = Utilities::MPI::sum(count.nonpositive, MPI_COMM_WORLD);
    count.decreased   = Utilities::MPI::sum(count.decreased, MPI_COMM_WORLD);
    return count;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = root_output();
  const SplineSpace<2>             space(cubic_box_knots(16, 0., 2.));
  const PatchMesh<2>               mesh(MPI_COMM_WORLD, space, nullptr);
  FieldLayout<2>                   layout;
  layout.add_space(space);
  layout.add_field("velocity", 2, 0);
  layout.add_field("pressure", 1, 0, FieldKind::algebraic);
  layout.add_field("phi", 1, 0);
  layout.add_field("lambda", 1, 0, FieldKind::algebraic);
  const SplineDofHandler<2> dofs(mesh, layout);
  const unsigned int        nc = dofs.n_components(), phi = 3;

  // u = (10 (y - 1), 0) and phi = -1 are splines of the space: interpolated
  // exactly at the Greville points.
  std::vector<double> values(space.n_basis() * nc, 0.);
  for (unsigned int i = 0; i < space.n_basis(); ++i)
    {
      values[i * nc + 0]   = 10. * (space.greville_point(i)[1] - 1.);
      values[i * nc + phi] = -1.;
    }
  TrilinosWrappers::MPI::Vector owned(dofs.locally_owned_dofs(),
                                      MPI_COMM_WORLD);
  scatter_natural(dofs,
                  interpolate_at_greville_points(space, values, nc),
                  owned);
  TrilinosWrappers::MPI::Vector value(dofs.locally_owned_dofs(),
                                      dofs.locally_relevant_dofs(),
                                      MPI_COMM_WORLD),
    rate(value);
  value            = owned;
  rate             = 0.;
  const double rho = 0.5, alpha_m = (3 - rho) / (2 * (1 + rho)),
               alpha_f = 1 / (1 + rho), gamma = 0.5 + alpha_m - alpha_f;
  AssemblyState state;
  state.value = &value;
  state.rate  = &rate;
  state.value_factor.assign(nc, alpha_f * gamma * 0.02);
  state.rate_factor.assign(nc, alpha_m);
  state.time_step = 0.02;

  MembraneCoefficients membrane;
  membrane.epsilon = 0.125;
  PhaseFieldAdvection<2>     transport({0, phi});
  PhaseFieldInflow<2>        inflow(0, phi, {{false, false}});
  GlobalConstraintForcing<2> multipliers({0, phi, membrane});
  multipliers.get_formula().set_multipliers(115., 0.);

  const DiagonalCount alone = phi_diagonal(dofs, {&transport}, state, {});
  std::vector<double> with_inflow;
  const DiagonalCount upwind
    = phi_diagonal(dofs, {&transport, &inflow}, state, {}, &with_inflow);
  const DiagonalCount all = phi_diagonal(dofs,
                                         {&transport, &inflow, &multipliers},
                                         state,
                                         with_inflow);
  out << "transport alone: rows with diagonal <= 0: "
      << (alone.nonpositive > 0 ? "some (inflow ends)" : "none") << '\n'
      << "transport and inflow term: rows with diagonal <= 0: "
      << upwind.nonpositive << '\n'
      << "with the multipliers (lambda_g = 115): rows with diagonal <= 0: "
      << all.nonpositive << ", rows whose diagonal decreased: " << all.decreased
      << '\n';
}
