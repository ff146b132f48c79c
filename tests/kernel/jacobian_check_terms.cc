// Every term of the kernel against finite differences of its own residual,
// through the one checker (kernel/jacobian_check): at a non-trivial state
// (smooth values, rates and auxiliary fields, all components non-zero) a
// variation d of the unknown changes the values by 0.7 d and the rates by
// 0.3 d (so that both kinds of Jacobian entries are tested), and K d is
// compared with (R(U + h d) - R(U - h d)) / 2h for h = 1e-2, 1e-3, 1e-4.
// Theory: for a consistent Jacobian the difference is O(h^2): it falls by
// 100 per factor 10 in h until round-off (~1e-16/h relative) takes over;
// for a term linear in the unknown it is round-off at every h. A missing
// or wrong entry leaves a difference that does not fall with h.
// "ok" requires each step to reduce the difference by at least 50, or the
// difference to be below 1e-9 at every h (linear terms). Terms whose
// residual does not depend on the unknown (volume constraint, electrolyte
// dielectric energy with psi frozen, Neumann, traction and boundary
// Laplacian data) must have K = 0 and an unchanged residual.
// Checked that the test fails: with the W g'' part of the bending Jacobian
// (E20) left out, both bending lines read FAILED. The Part H terms get their
// Jacobians by automatic differentiation (kernel/pointwise_term.h); here
// they check the wiring (inputs, outputs, which pairs are integrated):
// with the Hessian input of the bending term dropped from the probe (its
// pairs not integrated) the bending lines read FAILED.

#include <deal.II/base/function_lib.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vesicle_iga/fields/natural_numbering.h>
#include <vesicle_iga/kernel/jacobian_check.h>
#include <vesicle_iga/physics/electromechanics_material.h>
#include <vesicle_iga/terms/bending_energy.h>
#include <vesicle_iga/terms/biharmonic.h>
#include <vesicle_iga/terms/conductivity.h>
#include <vesicle_iga/terms/constraint_functionals.h>
#include <vesicle_iga/terms/dielectric_energies.h>
#include <vesicle_iga/terms/flexoelectric_energy.h>
#include <vesicle_iga/terms/global_constraint_forcing.h>
#include <vesicle_iga/terms/hydrodynamic_bending.h>
#include <vesicle_iga/terms/laplace.h>
#include <vesicle_iga/terms/linear_elasticity.h>
#include <vesicle_iga/terms/local_inextensibility.h>
#include <vesicle_iga/terms/navier_stokes_rbvms.h>
#include <vesicle_iga/terms/phase_field_advection.h>
#include <vesicle_iga/terms/phase_field_inflow.h>
#include <vesicle_iga/terms/rate.h>
#include <vesicle_iga/terms/vesicle_interaction.h>
#include <vesicle_iga/terms/viscosity_contrast.h>
#include <vesicle_iga/terms/weak_velocity_dirichlet.h>

#include <cmath>
#include <fstream>
#include <iomanip>

#include "../root_output.h"

using namespace vesicle_iga;
using namespace dealii;

std::ofstream out;

/// A field on @p dofs with smooth, different values per component.
template <int dim>
TrilinosWrappers::MPI::Vector
smooth_field(const SplineDofHandler<dim> &dofs, const double shift)
{
  const unsigned int  nc    = dofs.n_components();
  const auto         &space = dofs.get_space();
  std::vector<double> values(space.n_basis() * nc);
  for (unsigned int i = 0; i < space.n_basis(); ++i)
    for (unsigned int c = 0; c < nc; ++c)
      {
        const Point<dim> x = space.greville_point(i);
        double           v = std::sin(1.3 * x[0] + shift + 0.4 * c);
        for (unsigned int d = 1; d < dim; ++d)
          v *= std::cos(0.9 * x[d] - 0.3 * c + shift);
        values[i * nc + c] = 0.8 * v;
      }
  TrilinosWrappers::MPI::Vector owned(dofs.locally_owned_dofs(),
                                      MPI_COMM_WORLD);
  scatter_natural(dofs,
                  interpolate_at_greville_points(space, values, nc),
                  owned);
  TrilinosWrappers::MPI::Vector ghosted(dofs.locally_owned_dofs(),
                                        dofs.locally_relevant_dofs(),
                                        MPI_COMM_WORLD);
  ghosted = owned;
  return ghosted;
}


/// Checks one term on @p dofs with the auxiliary field @p aux (if any).
template <int dim>
void
check(const std::string                   &name,
      Term<dim>                           &term,
      const SplineDofHandler<dim>         &dofs,
      const SplineDofHandler<dim>         *aux_dofs = nullptr,
      const TrilinosWrappers::MPI::Vector *aux      = nullptr)
{
  SystemAssembler<dim> assembler(dofs, QGauss<1>(4));
  if (aux_dofs)
    assembler.add_auxiliary_field(*aux_dofs);
  assembler.add_term(term);
  const auto    value = smooth_field(dofs, 0.2), rate = smooth_field(dofs, 1.1);
  AssemblyState state;
  state.value = &value;
  state.rate  = &rate;
  if (aux)
    state.auxiliary = {aux};
  state.value_factor.assign(dofs.n_components(), 0.7);
  state.rate_factor.assign(dofs.n_components(), 0.3);
  state.time      = 0.4;
  state.time_step = 0.25;
  const AffineConstraints<double> none;
  const auto                      d = test_direction(dofs, none);
  const JacobianCheck             r
    = check_jacobian(assembler, state, none, d, {1e-2, 1e-3, 1e-4});
  out << dim << "D " << std::left << std::setw(32) << name << std::right;
  if (r.norm_Kd == 0)
    {
      // The residual must not change with the unknown.
      TrilinosWrappers::MPI::Vector R0(d), R1(d);
      assembler.assemble(state, none, &R0, nullptr);
      TrilinosWrappers::MPI::Vector shifted(value);
      TrilinosWrappers::MPI::Vector owned(d);
      owned = value;
      owned.add(0.1, d);
      shifted             = owned;
      AssemblyState moved = state;
      moved.value         = &shifted;
      assembler.assemble(moved, none, &R1, nullptr);
      R1 -= R0;
      out << " K = 0, residual independent of the unknown: "
          << (R1.l2_norm() <= 1e-12 * R0.l2_norm() ? "ok" : "FAILED")
          << std::endl;
      return;
    }
  const auto &e         = r.relative_difference;
  const bool  quadratic = e[1] < 2e-2 * e[0] && e[2] < 2e-2 * e[1];
  const bool  linear    = e[0] < 1e-9 && e[1] < 1e-9 && e[2] < 1e-9;
  out << " " << (quadratic || linear ? "ok" : "FAILED")
      << (linear ? " (central differences exact: at most quadratic)" : "")
      << std::endl;
}


template <int dim>
void
phase_field_terms()
{
  std::array<KnotVector, dim> kv;
  for (unsigned int d = 0; d < dim; ++d)
    kv[d] = KnotVector::uniform(3, dim == 2 ? 5 : 3, -1., 1.2);
  const SplineSpace<dim>      space(kv);
  const PatchMesh<dim>        mesh(MPI_COMM_WORLD, space, nullptr);
  const SplineDofHandler<dim> dofs(mesh, space, 1);
  const auto                  psi = smooth_field(dofs, 0.7);
  const double                eps = 0.3;

  BendingEnergy<dim> bending(0, 1.3, eps, 0.4);
  check<dim>("bending (E18)/(E20)", bending, dofs);
  AreaConstraint<dim> area(0, eps);
  area.set_multiplier(0.6);
  check<dim>("area constraint", area, dofs);
  VolumeConstraint<dim> volume(0);
  volume.set_multiplier(0.6);
  check<dim>("volume constraint", volume, dofs);
  RateTerm<dim> rate({0});
  check<dim>("rate", rate, dofs);
  FlexoelectricEnergy<dim> flexo(0, 0, 3 * 2. * 0.5 / (2 * std::sqrt(2.)), eps);
  check<dim>("flexoelectric (E6)", flexo, dofs, &dofs, &psi);
  MembraneDielectricEnergy<dim> membrane(0, 0, 0.5, 3., eps);
  check<dim>("membrane dielectric (E7)", membrane, dofs, &dofs, &psi);
  ElectrolyteDielectricEnergy<dim> electrolyte(0, 0, 2., 5.);
  check<dim>("electrolyte dielectric (E8)", electrolyte, dofs, &dofs, &psi);
  ElectromechanicsMaterial material;
  ConductivityTerm<dim>    conductivity(0, 0, material);
  check<dim>("conductivity (E17)", conductivity, dofs, &dofs, &psi);
}


template <int dim>
void
linear_terms()
{
  std::array<KnotVector, dim> kv;
  for (unsigned int d = 0; d < dim; ++d)
    kv[d] = KnotVector::uniform(2, 4, 0., 1.);
  const SplineSpace<dim>      space(kv);
  const PatchMesh<dim>        mesh(MPI_COMM_WORLD, space, nullptr);
  const SplineDofHandler<dim> scalar(mesh, space, 1), vector(mesh, space, dim);
  const Functions::CosineFunction<dim> f;
  const BoundarySelection<dim>         all("all", "boundary");

  LaplaceTerm<dim> laplace(0, f);
  check<dim>("laplace", laplace, scalar);
  NitscheDirichletTerm<dim> nitsche(0, all, f, 10.);
  check<dim>("nitsche", nitsche, scalar);
  NeumannTerm<dim> neumann(
    0,
    [](unsigned int, const Point<dim> &) { return true; },
    [&](const Point<dim> &x) { return f.gradient(x); });
  check<dim>("neumann", neumann, scalar);
  BiharmonicTerm<dim> biharmonic(0, f);
  check<dim>("biharmonic", biharmonic, scalar);
  BoundaryLaplacianTerm<dim> moment(0, all, f);
  check<dim>("boundary laplacian", moment, scalar);
  LinearElasticityTerm<dim> elasticity(0, 10., 0.3, dim == 2);
  check<dim>("linear elasticity", elasticity, vector);
  TractionTerm<dim> traction(0,
                             all,
                             [](const Point<dim> &x, const Tensor<1, dim> &n) {
                               return x[0] * n;
                             });
  check<dim>("traction", traction, vector);
}


template <int dim>
void
flow_terms()
{
  std::array<KnotVector, dim> kv;
  for (unsigned int d = 0; d < dim; ++d)
    kv[d] = KnotVector::uniform(2, dim == 2 ? 4 : 2, 0., 1.);
  const SplineSpace<dim> space(kv);
  const PatchMesh<dim>   mesh(MPI_COMM_WORLD, space, nullptr);
  FieldLayout<dim>       layout;
  layout.add_space(space);
  layout.add_field("velocity", dim, 0);
  layout.add_field("pressure", 1, 0, FieldKind::algebraic);
  const SplineDofHandler<dim> dofs(mesh, layout);

  auto viscosity = std::make_shared<Functions::CosineFunction<dim>>();
  FlowCoefficients<dim> coefficients;
  coefficients.reynolds_number = 50;
  coefficients.viscosity = std::make_shared<FormulaViscosity<dim>>(viscosity);
  NavierStokesRBVMS<dim> rbvms(0, dim, coefficients);
  check<dim>("RBVMS (H14), (H18)-(H19)", rbvms, dofs);
  // Inflow on parts of the boundary (u.m < 0) activates the inflow term.
  const Functions::ConstantFunction<dim> ub(0.3, dim + 1);
  WeakVelocityDirichlet<dim>             weak(
    0, dim, coefficients, BoundarySelection<dim>("all", "weak"), ub, 15., true);
  check<dim>("weak velocity (H20)-(H21)", weak, dofs);
}


/// The vesicle terms of Part H (spec 4.13) on u, p, phi_1, phi_2, lambda_1,
/// lambda_2 (cubic C^2: the bending term reads third derivatives). The
/// state keeps |phi| < 0.8, where the interaction (H8) is smooth.
template <int dim>
void
hydrodynamic_terms()
{
  std::array<KnotVector, dim> kv;
  for (unsigned int d = 0; d < dim; ++d)
    kv[d] = KnotVector::uniform(3, dim == 2 ? 4 : 2, 0., 1.);
  const SplineSpace<dim> space(kv);
  const PatchMesh<dim>   mesh(MPI_COMM_WORLD, space, nullptr);
  FieldLayout<dim>       layout;
  layout.add_space(space);
  layout.add_field("velocity", dim, 0);
  layout.add_field("pressure", 1, 0, FieldKind::algebraic);
  layout.add_field("phi", 2, 0);
  layout.add_field("lambda", 2, 0, FieldKind::algebraic);
  const SplineDofHandler<dim> dofs(mesh, layout);
  const unsigned int   phi_1 = dim + 1, phi_2 = dim + 2, lambda_1 = dim + 3;
  MembraneCoefficients c;
  c.epsilon          = 0.3;
  c.reynolds_number  = 0.7;
  c.capillary_number = 2;
  c.viscosity_ratio  = 4;

  PhaseFieldAdvection<dim> advection({0, phi_1});
  check<dim>("advection (H16)", advection, dofs);
  std::array<bool, dim> not_periodic{};
  PhaseFieldInflow<dim> inflow(0, phi_1, not_periodic);
  check<dim>("phase-field inflow (4.10)", inflow, dofs);
  HydrodynamicBending<dim> bending({0, phi_1, c});
  check<dim>("bending (H24)-(H25)", bending, dofs);
  GlobalConstraintForcing<dim> constraint({0, phi_1, c});
  constraint.get_formula().set_multipliers(0.7, -0.4);
  check<dim>("global multipliers (H1), (H14)", constraint, dofs);
  LocalInextensibility<dim> inextensibility({0, phi_1, lambda_1, c});
  check<dim>("inextensibility (H17), (H14)", inextensibility, dofs);
  VesicleInteraction<dim> interaction({0, phi_1, phi_2, c});
  check<dim>("interaction (H10)-(H11)", interaction, dofs);
  ViscosityContrast<dim> viscosity({0, {phi_1, phi_2}, c});
  check<dim>("viscosity contrast (H12a)", viscosity, dofs);
}


int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  out = root_output();
  phase_field_terms<2>();
  phase_field_terms<3>();
  linear_terms<2>();
  linear_terms<3>();
  flow_terms<2>();
  flow_terms<3>();
  hydrodynamic_terms<2>();
  hydrodynamic_terms<3>();
}
