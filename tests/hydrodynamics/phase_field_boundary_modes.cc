// Why the Part H phase fields need d phi / dn = 0 (spec 4.10; issue 15:
// HD4a at 32 per unit with open sides failed at t = 0.015 from the corners).
//
// Linearised at the far field phi = -1, u = 0, the phase-field rows of
// (H16) with the bending pairing (H24) and the area multiplier term
// (A' of (H12c)) read M phi_t = -K phi, and a mode psi grows at the rate
//   sigma(psi) = -psi^T K psi / psi^T M psi,
//   psi^T K psi = eta (1/(Re Ca)) eps ||Delta psi - 2 psi / eps^2||^2
//                 + eta lambda_g (eps ||grad psi||^2 + (2 / eps) ||psi||^2).
// With lambda_g < 0 (HD4a at 32 per unit starts at lambda_g = -16):
// - natural conditions only: the boundary layers psi = cos(k y)
//   exp(-kappa x), kappa^2 = k^2 + 2 / eps^2, cost no bending energy, so
//   sigma = eta |lambda_g| (2 eps k^2 + 4 / eps) (for the exact layer)
//   grows without bound with k, i.e. like 1 / h^2 at the grid scale;
// - with d psi / dn = 0 the operator Delta - 2 / eps^2 is negative
//   definite and, in Fourier terms with s = eps^2 |k|^2 + 2 >= 2,
//   sigma <= max_s [eta |lambda_g| s / eps - eta s^2 / (Re Ca eps^3)]
//   = 18.4 for the values here (at s = 2). The discrete space with the
//   constraint is a subspace and the forms are integrated exactly (5 Gauss
//   points, polynomial integrands of degree <= 6), so the bound holds for
//   every function of it, in particular for the constrained layers.
// Set-up: [0, 2]^2, 64^2 cubic C^2 elements (h = 1/32), eps = 1/16,
// Re Ca = 50, eta = 0.1, lambda_g = -16, lambda_v = 0; layers k = pi m / 2,
// m = 4, 8, 16, interpolated at the Greville points. Printed to 2 digits.
// Checked: the natural rates agree with the formula for the exact layer
// to the 2 digits printed (110, 130, 230; kappa h = 0.8 to 1.1) and exceed
// the bound 18 six- to twelvefold; the constrained ones are negative (-60,
// -94, -290). With the distribute() of the constraint left out, the three
// layer lines read FAILED (tried).

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vesicle_iga/fields/dirichlet_constraints.h>
#include <vesicle_iga/fields/field_layout.h>
#include <vesicle_iga/fields/natural_numbering.h>
#include <vesicle_iga/fields/spline_dof_handler.h>
#include <vesicle_iga/kernel/system_assembler.h>
#include <vesicle_iga/parallel/patch_mesh.h>
#include <vesicle_iga/physics/hydrodynamic_membrane.h>
#include <vesicle_iga/terms/global_constraint_forcing.h>
#include <vesicle_iga/terms/hydrodynamic_bending.h>
#include <vesicle_iga/terms/phase_field_advection.h>

#include <cmath>
#include <fstream>
#include <iomanip>

#include "vesicle_flow_setup.h"

using namespace vesicle_iga;
using namespace dealii;

namespace
{
  constexpr unsigned int phi = 3;

  TrilinosWrappers::SparseMatrix
  assemble(const SplineDofHandler<2>    &dofs,
           const std::vector<Term<2> *> &terms,
           const AssemblyState          &state)
  {
    SystemAssembler<2> assembler(dofs, QGauss<1>(5));
    for (Term<2> *t : terms)
      assembler.add_term(*t);
    TrilinosWrappers::SparsityPattern sparsity;
    dofs.make_sparsity_pattern(sparsity);
    TrilinosWrappers::SparseMatrix  matrix(sparsity);
    const AffineConstraints<double> none;
    assembler.assemble(state, none, nullptr, &matrix);
    return matrix;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out  = root_output();
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const SplineSpace<2>             space(cubic_box_knots(64, 0., 2.));
  const PatchMesh<2>               mesh(comm, space, nullptr);
  FieldLayout<2>                   layout;
  layout.add_space(space);
  layout.add_field("velocity", 2, 0);
  layout.add_field("pressure", 1, 0, FieldKind::algebraic);
  layout.add_field("phi", 1, 0);
  layout.add_field("lambda", 1, 0, FieldKind::algebraic);
  const SplineDofHandler<2> dofs(mesh, layout);
  const unsigned int        nc = dofs.n_components();

  MembraneCoefficients membrane;
  membrane.epsilon            = 1. / 16;
  const double eps            = membrane.epsilon;
  const double eta            = membrane.mobility;
  const double lambda_g       = -16;
  const double bending_factor = membrane.bending_factor();

  // The far field phi = -1, u = 0 (exact in the space).
  std::vector<double> values(space.n_basis() * nc, 0.);
  for (unsigned int i = 0; i < space.n_basis(); ++i)
    values[i * nc + phi] = -1.;
  TrilinosWrappers::MPI::Vector owned(dofs.locally_owned_dofs(), comm);
  scatter_natural(dofs,
                  interpolate_at_greville_points(space, values, nc),
                  owned);
  TrilinosWrappers::MPI::Vector value(dofs.locally_owned_dofs(),
                                      dofs.locally_relevant_dofs(),
                                      comm),
    rate(value);
  value = owned;
  rate  = 0.;

  // K: the value Jacobian of bending and multipliers; M: the rate
  // Jacobian of (H16) (the mass matrix).
  HydrodynamicBending<2> bending(
    HydrodynamicBendingFormula<2>(0, phi, membrane));
  GlobalConstraintForcing<2> multipliers({0, phi, membrane});
  multipliers.get_formula().set_multipliers(lambda_g, 0.);
  PhaseFieldAdvection<2> transport({0, phi});
  AssemblyState          state;
  state.value = &value;
  state.rate  = &rate;
  state.value_factor.assign(nc, 1.);
  state.rate_factor.assign(nc, 0.);
  const auto K = assemble(dofs, {&bending, &multipliers}, state);
  state.value_factor.assign(nc, 0.);
  state.rate_factor.assign(nc, 1.);
  const auto M = assemble(dofs, {&transport}, state);

  AffineConstraints<double> neumann(dofs.locally_relevant_dofs());
  std::vector<bool>         mask(nc, false);
  mask[phi] = true;
  add_zero_normal_derivative_constraints<2>(dofs, mask, neumann);
  neumann.close();

  // Fourier bound with the constraint (s = eps^2 |k|^2 + 2 >= 2).
  double bound = -1e300;
  for (double s = 2; s < 100; s += 1e-3)
    bound = std::max(bound,
                     eta * (-lambda_g) * s / eps
                       - eta * bending_factor * s * s / (eps * eps * eps));

  const auto rate_of = [&](const TrilinosWrappers::MPI::Vector &psi) {
    TrilinosWrappers::MPI::Vector Kpsi(psi), Mpsi(psi);
    K.vmult(Kpsi, psi);
    M.vmult(Mpsi, psi);
    return -(psi * Kpsi) / (psi * Mpsi);
  };
  out << std::setprecision(2) << "bound with d phi / dn = 0: sigma <= " << bound
      << '\n';
  for (const unsigned int m : {4u, 8u, 16u})
    {
      const double        k     = numbers::PI * m / 2;
      const double        kappa = std::sqrt(k * k + 2 / (eps * eps));
      std::vector<double> layer(space.n_basis() * nc, 0.);
      for (unsigned int i = 0; i < space.n_basis(); ++i)
        {
          const Point<2> x    = space.greville_point(i);
          layer[i * nc + phi] = std::cos(k * x[1]) * std::exp(-kappa * x[0]);
        }
      TrilinosWrappers::MPI::Vector psi(dofs.locally_owned_dofs(), comm);
      scatter_natural(dofs,
                      interpolate_at_greville_points(space, layer, nc),
                      psi);
      const double natural = rate_of(psi);
      const double formula = eta * (-lambda_g) * (2 * eps * k * k + 4 / eps);
      TrilinosWrappers::MPI::Vector constrained(psi);
      neumann.distribute(constrained);
      const double with_neumann = rate_of(constrained);
      out << "layer k = pi " << m << " / 2: natural sigma = " << natural
          << " (exact layer " << formula << "), above the bound "
          << (natural > bound ? "yes" : "no")
          << "; with d phi / dn = 0 sigma = " << with_neumann << ", below "
          << (with_neumann <= bound * (1 + 1e-10) ? "ok" : "FAILED") << '\n';
    }
}
