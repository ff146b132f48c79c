// The block preconditioner of the coupled vesicle-flow tangent
// (VesicleBlockPreconditioner, Linear solver/Method = fgmres-block) on
// three vesicles in a shear flow with a viscosity contrast, against the
// direct solver. Set-up: [0, 2.25] x [0, 1.5], 36 x 24 cubic C^2 elements,
// eps = 2 h = 0.125, u = (y - 0.75, 0) at t = 0 and strongly on every wall,
// beta_mu = 4, interaction on, vesicles of R_0 = 0.25, chi = 0.84 (major
// axis vertical) at (0.5, 0.85), (1.125, 0.75), (1.75, 0.65); dt = 1e-3,
// 2 steps,
// Newton to 1e-10, Krylov to 1e-11. Checks:
// - every measure of every vesicle (centroid, angle, area, volume, bending
//   energy) and the interaction energy equal the direct run's to 1e-7
//   relative (the preconditioner changes the iterates, not the solution);
// - the FGMRES count per Newton iteration stays below 60 (37 measured;
//   with the tension Schur complements left out of the preconditioner,
//   lambda = 0 in P, the first solve does not converge in 400 iterations,
//   residual 0.05, and the test stops with the solver's error);
// - both pressure Schur approximations, cahouet-chabard (lumped viscous
//   mass, the default) and stabilized-cahouet-chabard (consistent viscous
//   mass + C), give the direct run's measures (the second measured
//   at 16.6 FGMRES iterations per Newton iteration against 36.1);
// - point symmetry: the flow, the mesh and the vesicles are symmetric
//   under x -> (2.25, 1.5) - x, so the middle vesicle stays at (1.125,
//   0.75) and the outer ones mirror each other (x_1 + x_3 = 2.25,
//   y_1 + y_3 = 1.5, equal
//   angles and areas), to 1e-8, in both runs.
// The same output on 1 and 2 ranks.

#include <deal.II/base/function.h>
#include <deal.II/base/timer.h>

#include <vesicle_iga/models/vesicle_hydrodynamics.h>
#include <vesicle_iga/physics/initial_vesicle.h>

#include <cmath>
#include <fstream>
#include <iostream>

#include "vesicle_flow_setup.h"

using namespace vesicle_iga;
using namespace dealii;

namespace
{
  /// u = (y - 0.75, 0) (and a pressure slot).
  class Shear : public Function<2>
  {
  public:
    Shear(const unsigned int n)
      : Function<2>(n)
    {}
    double
    value(const Point<2> &x, const unsigned int c) const override
    {
      return c == 0 ? x[1] - 0.75 : 0;
    }
  };

  struct Outcome
  {
    std::vector<VesicleMeasures> measures;
    double                       interaction = 0;
    unsigned int                 newton = 0, krylov = 0;
  };

  Outcome
  run(const std::string &method,
      const std::string &schur_approximation,
      TimerOutput       &timer)
  {
    const SplineSpace<2> space(cubic_box_knots(36, 0., 2.25, 24, 0., 1.5));
    MembraneCoefficients membrane;
    membrane.epsilon                = 0.125;
    membrane.viscosity_ratio        = 4;
    const FlowCoefficients<2> flow  = cubic_flow_coefficients(membrane);
    const auto                walls = strong_walls(std::make_shared<Shear>(3));
    IncompressibleFlowParameters parameters;
    parameters.solver.method                    = method;
    parameters.solver.block.schur_approximation = schur_approximation;
    parameters.solver.tolerance                 = 1e-11;
    parameters.solver.max_iterations            = 400;
    parameters.quadrature_points                = 5;
    parameters.newton.relative_tolerance        = 1e-10;
    parameters.newton.absolute_tolerance        = 1e-12;

    VesicleHydrodynamics<2> model(
      MPI_COMM_WORLD, space, membrane, flow, walls, parameters, 3, timer);
    const std::vector<InitialVesicle<2>> vesicles{
      InitialVesicle<2>(Point<2>(0.5, 0.85), 0.25, 0.84, 90),
      InitialVesicle<2>(Point<2>(1.125, 0.75), 0.25, 0.84, 90),
      InitialVesicle<2>(Point<2>(1.75, 0.65), 0.25, 0.84, 90)};
    std::vector<std::function<double(const Point<2> &)>> phases;
    for (const auto &v : vesicles)
      phases.push_back(
        [&v](const Point<2> &x) { return v.phase_field(x, 0.125); });
    model.set_initial_state(Shear(2), phases);

    Outcome o;
    for (unsigned int step = 0; step < 2; ++step)
      {
        const StepReport r = model.solve_step(1e-3);
        model.accept_step();
        o.newton += r.newton_iterations;
        o.krylov += r.krylov_iterations;
      }
    o.measures    = model.measure();
    o.interaction = model.interaction_energy();
    return o;
  }


  /// Largest relative difference of the measures of @p a and @p b.
  double
  difference(const Outcome &a, const Outcome &b)
  {
    const auto rel = [](const double x, const double y) {
      return std::abs(x - y) / std::max(std::abs(y), 1e-12);
    };
    double d = rel(a.interaction, b.interaction);
    for (unsigned int i = 0; i < a.measures.size(); ++i)
      {
        const VesicleMeasures &p = a.measures[i], &q = b.measures[i];
        d = std::max({d,
                      rel(p.centroid[0], q.centroid[0]),
                      rel(p.centroid[1], q.centroid[1]),
                      rel(p.angle, q.angle),
                      rel(p.area, q.area),
                      rel(p.volume, q.volume),
                      rel(p.bending_energy, q.bending_energy)});
      }
    return d;
  }


  /// Largest deviation from the point symmetry about (1.125, 0.75).
  double
  asymmetry(const Outcome &o)
  {
    const auto &m = o.measures;
    return std::max({m[1].centroid.distance(Point<3>(1.125, 0.75, 0)),
                     std::abs(m[0].centroid[0] + m[2].centroid[0] - 2.25),
                     std::abs(m[0].centroid[1] + m[2].centroid[1] - 1.5),
                     std::abs(m[0].angle - m[2].angle),
                     std::abs(m[0].area / m[2].area - 1)});
  }
} // namespace


int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = root_output();
  std::ostringstream               quiet;
  TimerOutput timer(quiet, TimerOutput::never, TimerOutput::wall_times);

  const Outcome direct = run("direct", "cahouet-chabard", timer);
  const Outcome block  = run("fgmres-block", "cahouet-chabard", timer);
  const Outcome stabilized
    = run("fgmres-block", "stabilized-cahouet-chabard", timer);
  const double per_newton = double(block.krylov) / block.newton;
  const double per_newton_stabilized
    = double(stabilized.krylov) / stabilized.newton;

  out << "block-preconditioned run equals the direct run (1e-7): "
      << verdict(difference(block, direct) < 1e-7) << '\n'
      << "FGMRES iterations per Newton iteration < 60: "
      << verdict(per_newton < 60) << '\n'
      << "point symmetry, direct run (1e-8): "
      << verdict(asymmetry(direct) < 1e-8) << '\n'
      << "point symmetry, block run (1e-8): "
      << verdict(asymmetry(block) < 1e-8) << '\n'
      << "stabilized Schur approximation equals the direct run (1e-7): "
      << verdict(difference(stabilized, direct) < 1e-7) << '\n'
      << "stabilized: FGMRES iterations per Newton iteration < 30: "
      << verdict(per_newton_stabilized < 30) << '\n';
  if (root_rank())
    std::cout << "difference " << difference(block, direct) << " krylov/newton "
              << per_newton << " (" << block.newton << " Newton) asymmetry "
              << asymmetry(direct) << ' ' << asymmetry(block)
              << " stabilized: difference " << difference(stabilized, direct)
              << " krylov/newton " << per_newton_stabilized << " E_int "
              << direct.interaction << std::endl;
}
