// The Newton tangent of the RBVMS flow (spec (H14), (H18)-(H21), (N4)) is
// the exact derivative of its residual: K d against central differences
// (R(a + h d) - R(a - h d)) / 2h of the residual in the unknown rates a, for
// a non-trivial state (velocity, pressure and rates all non-zero, variable
// viscosity, body force) with strong conditions on two faces and weak ones
// (with the inflow term active, u.m < 0 on part of them) on the others.
// Theory: the difference is O(h^2) for an exact tangent, so it falls by 100
// per factor 10 in h until round-off (about 1e-16 / h relative) takes over;
// an error in any term (d tau / du, the cross or Reynolds-stress term, the
// weak-boundary terms) would leave a difference that does not fall with h.
// Checked for p = 2 and 3 in 2D, p = 2 in 3D, and for both pressure time
// levels, at Re = 200 and dt = 1 so that u.G u dominates tau_M (H19).
// Measured: 6.9e-6, 6.9e-8, 6.9e-10 (2D, p = 2) and 3.7e-6, 3.7e-8,
// 3.7e-10 (3D) for h = 1e-2, 1e-3, 1e-4; with d tau_M / d u left out of the
// tangent the difference stays at 2.7e-2 (2D, p = 2), so the test fails.

#include <deal.II/base/function_lib.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>

#include <vesicle_iga/fields/natural_numbering.h>
#include <vesicle_iga/kernel/jacobian_check.h>
#include <vesicle_iga/models/incompressible_flow.h>

#include <cmath>
#include <fstream>
#include <iomanip>

#include "../root_output.h"

using namespace vesicle_iga;
using namespace dealii;

std::ofstream out;

template <int dim>
void
check(const unsigned int p, const bool pressure_at_end)
{
  std::array<KnotVector, dim> kv;
  for (unsigned int d = 0; d < dim; ++d)
    kv[d] = KnotVector::uniform(p, dim == 2 ? 4 : 2, 0., 1.);
  const SplineSpace<dim> space(kv);

  const std::string coords    = dim == 2 ? "x,y,t" : "x,y,z,t";
  auto              viscosity = std::make_shared<FunctionParser<dim>>(1);
  auto              force     = std::make_shared<FunctionParser<dim>>(dim);
  viscosity->initialize(coords, "1 + 0.5*x*y", {}, true);
  force->initialize(coords, dim == 2 ? "x; y^2" : "x; y^2; z", {}, true);
  FlowCoefficients<dim> coefficients;
  coefficients.reynolds_number = 200;
  coefficients.viscosity  = std::make_shared<FormulaViscosity<dim>>(viscosity);
  coefficients.body_force = BodyForce<dim>(force);
  coefficients.inverse_estimate_constant = 6. * std::pow(p, 4);

  // Strong on x-min and y-max, weak elsewhere with a boundary velocity
  // pointing into the domain on parts of the faces.
  auto strong = std::make_shared<FunctionParser<dim>>(dim + 1);
  auto weak   = std::make_shared<FunctionParser<dim>>(dim + 1);
  strong->initialize(coords, dim == 2 ? "y; 0; 0" : "y; 0; z; 0", {}, true);
  weak->initialize(coords,
                   dim == 2 ? "1 - 2*x; 1 - 2*y; 0" :
                              "1 - 2*x; 1 - 2*y; 0.5 - z; 0",
                   {},
                   true);
  std::vector<VelocityCondition<dim>> conditions{
    {BoundarySelection<dim>("x-min; y-max", "strong"), strong, false},
    {BoundarySelection<dim>(
       dim == 2 ? "x-max; y-min" : "x-max; y-min; z-min; z-max", "weak"),
     weak,
     true}};

  IncompressibleFlowParameters parameters;
  parameters.solver.method                     = "direct";
  parameters.quadrature_points                 = p + 2;
  parameters.time_integration.algebraic_at_end = pressure_at_end;
  TimerOutput             timer(MPI_COMM_WORLD,
                    out,
                    TimerOutput::never,
                    TimerOutput::wall_times);
  IncompressibleFlow<dim> solver(
    MPI_COMM_WORLD, space, coefficients, conditions, parameters, timer);

  // State U_n and rate_n from smooth fields with all components non-zero.
  FunctionParser<dim> state(dim + 1), rate(dim + 1);
  state.initialize(coords,
                   dim == 2 ? "sin(3*x)*cos(2*y); x*y - 0.3; cos(x + 2*y)" :
                              "sin(3*x)*cos(2*y); x*y - 0.3*z; z*x + 0.2; "
                              "cos(x + 2*y - z)",
                   {},
                   true);
  rate.initialize(coords,
                  dim == 2 ? "x - y; x*x; y" : "x - y; x*x; z*y; y",
                  {},
                  true);
  const auto interpolate = [&](const Function<dim> &f) {
    std::vector<double> values(space.n_basis() * (dim + 1));
    for (unsigned int i = 0; i < space.n_basis(); ++i)
      for (unsigned int c = 0; c <= dim; ++c)
        values[i * (dim + 1) + c] = f.value(space.greville_point(i), c);
    TrilinosWrappers::MPI::Vector v(solver.dofs().locally_owned_dofs(),
                                    MPI_COMM_WORLD);
    scatter_natural(solver.dofs(),
                    interpolate_at_greville_points(space, values, dim + 1),
                    v);
    return v;
  };
  solver.set_state(interpolate(state), interpolate(rate), 0.3);
  const double dt = 1;

  // Trial rate a and direction d, zero on the constrained unknowns.
  TrilinosWrappers::MPI::Vector a           = interpolate(rate), d(a);
  const auto                   &constraints = solver.increment_constraints();
  for (const auto i : solver.dofs().locally_owned_dofs())
    {
      a[i] = 0.3 * std::sin(1.7 * i) + 0.1;
      d[i] = constraints.is_constrained(i) ? 0. : std::cos(2.3 * i + 0.4);
    }
  a.compress(VectorOperation::insert);
  d.compress(VectorOperation::insert);
  for (const auto &c : conditions)
    c.velocity->set_time(0.3 + dt);
  const AssemblyState &stage = solver.get_stepper().stage_at(a, dt);
  const auto           check = check_jacobian(
    solver.get_assembler(), stage, constraints, d, {1e-2, 1e-3, 1e-4});
  const auto &differences = check.relative_difference;

  out << dim << "D, p = " << p << ", pressure at "
      << (pressure_at_end ? "t_n+1" : "t_n+alpha_f") << ":";
  const bool quadratic = differences[1] < 2e-2 * differences[0]
                         && differences[2] < 2e-2 * differences[1];
  out << " |FD - K d| / |K d| falls by >= 50 per factor 10 in h (0.01, "
         "0.001, 0.0001): "
      << (quadratic ? "yes" : "NO")
      << "; at h = 1e-4 below 1e-8: " << (differences[2] < 1e-8 ? "yes" : "NO")
      << std::endl;
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  out = root_output();
  check<2>(2, true);
  check<2>(3, true);
  check<2>(2, false);
  check<3>(2, true);
}
