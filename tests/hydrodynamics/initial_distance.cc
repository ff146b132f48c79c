// The initial distance of the vesicles (Initial distance = radial |
// level-set | exact, issue 15), and why phi_0 must be smooth and compatible with
// the boundary condition: the bending energy of a discrete phi_0 converges
// under refinement only if phi_0 is in H^2 with d phi_0 / dn = 0 where
// that is imposed.
//
// Geometry (an ellipse of R_0 = 0.45, chi = 0.84 and a prolate spheroid of
// v = 0.7, eps = 0.125):
// - the level-set distance F / |grad F| vanishes on the outline (1e-12),
//   has unit slope there (central differences, 1e-6) and phi_0 -> 1 at the
//   centre from every direction;
// - the radial distance of (H23) jumps at the centre: phi_0 just off the
//   centre along the major axis minus along the minor axis equals
//   centre_jump() = tanh(c / (sqrt2 eps)) - tanh(a / (sqrt2 eps));
// - the radial distance's slope on the outline is sqrt(1 + (rho' /
//   rho)^2) (outline_slope(), against the polar form), the level-set
//   distance's 1, in 2D and 3D.
// Convergence (the solver tests' RestingVesicle: that vesicle at the centre
// of [-1, 1]^2, 8 to 64 cubic elements per unit, eps = 0.125 fixed):
// initial bending energy and lambda_g(0), lambda_v(0) of (H13).
// - radial: the jump (0.052 here) makes |Delta phi_0|^2 ~ r^-4 near the
//   centre, the energy grows like h^-2 (its differences grow about
//   fourfold per halving of h) and lambda_g(0) with it;
// - level-set with natural conditions: the energy converges (differences
//   fall at least fivefold: 0.0154, 0.0029, 0.00014); lambda_g(0) does
//   not (-5.23, -6.62, -10.7, -24.7; -5.6, -7.19, -11.8, -27.4 with
//   'membrane'): (H13), taken from the discrete
//   equations, sees the boundary layers of the natural conditions
//   (phase_field_boundary_modes). With the pointwise f_i of before it
//   converged (-6.73, -6.25, -5.92, -5.80) but held the area only to a
//   drift of constant rate (doc/hydrodynamics.md, "(H13) from the discrete
//   equations");
// - level-set with d phi / dn = 0: the membrane is 0.37 = 3 eps from the
//   top and bottom walls, where d phi_0 / dn = 0.34; the constraint cuts
//   that slope in a layer of width h, and the energy (s^2 / h per unit
//   length) does not converge: its last difference exceeds the one before.
// - level-set with d phi / dn = 0 and the mirrored phase
//   (mirrored_phase_field): compatible with the constraint, the energy
//   converges again (differences 0.0155, 0.0029, 0.0001), and lambda_g(0)
//   with it (-4.81, -5.2, -5.24, -5.24 with the default 'Volume multiplier
//   = indicator'; -5.19, -5.64, -5.69, -5.69 with 'membrane').
// - exact (the true distance to the ellipse), d phi / dn = 0, mirrored: at
//   eps = 0.125 the minor semi-axis a is 2.5 eps and the kink of the
//   distance on the medial axis (weight sech^2(l / (sqrt2 eps)), l >= a^2 /
//   c = 1.3 eps from the outline) is resolved under refinement: the energy
//   grows (0.31, 0.37, 0.49, 0.78) and lambda_g(0) like h^-2. At eps =
//   0.0625 (a = 5.1 eps) and the spec's eps = 2 h (32 per unit) its energy
//   0.219 is 11 % above the sharp ellipse's 0.19722 (the eps-error of the
//   HD1 runs, doc/hydrodynamics.md), where the radial and level-set
//   distances start at 0.575 and 0.682: the exact distance gives the
//   equilibrium tanh profile on the outline, the others do not (slope, and
//   level sets not parallel to it). Refined at that eps the kink shows
//   again: lambda_g(0) -3.14, -8.28, -38.5 at 16, 32, 64 per unit
//   (-4.1, -11.6, -54.7 with 'membrane').
// Checked that it can fail: with the level-set distance replaced by the
// radial one, the unit slope, the centre value and both "fall fivefold"
// verdicts read FAILED (tried).
// Values printed to 3-4 digits (they come from projections of analytic
// data, no iteration); the verdicts are the checks.

#include <deal.II/base/mpi.h>

#include <cmath>
#include <fstream>
#include <iomanip>

#include "vesicle_flow_setup.h"

using namespace vesicle_iga;
using namespace dealii;

namespace
{
  using Distance = InitialVesicleBase::DistanceFormula;

  /// Zero set, unit slope and the value at the centre of the level-set
  /// distance of @p vesicle.
  template <int dim>
  void
  check_level_set(std::ostream              &out,
                  const InitialVesicle<dim> &vesicle,
                  const Point<dim>          &centre)
  {
    double off = 0, slope = 0;
    for (const auto &x : vesicle.outline(dim == 2 ? 360 : 400))
      {
        off = std::max(off, std::abs(vesicle.signed_distance(x)));
        Tensor<1, dim> grad;
        for (unsigned int k = 0; k < dim; ++k)
          {
            Point<dim> plus = x, minus = x;
            plus[k] += 1e-6;
            minus[k] -= 1e-6;
            grad[k]
              = (vesicle.signed_distance(plus) - vesicle.signed_distance(minus))
                / 2e-6;
          }
        slope = std::max(slope, std::abs(grad.norm() - 1));
      }
    double centre_error = 0;
    for (unsigned int k = 0; k < dim; ++k)
      for (const double s : {-1e-9, 1e-9})
        {
          Point<dim> x = centre;
          x[k] += s;
          centre_error = std::max(centre_error,
                                  std::abs(vesicle.phase_field(x, 0.125) - 1));
        }
    out << dim << "D level-set distance: zero on the outline "
        << verdict(off < 1e-12) << ", unit slope there "
        << verdict(slope < 1e-6) << ", phi_0 = 1 at the centre "
        << verdict(centre_error < 1e-12) << '\n';
  }

  struct Sequence
  {
    std::vector<double> energy, lambda_g, lambda_v;
  };

  Sequence
  refine(const Distance                   distance,
         const bool                       zero_normal_derivative,
         const bool                       mirrored = false,
         const double                     epsilon  = 0.125,
         const std::vector<unsigned int> &levels   = {8, 16, 32, 64})
  {
    Sequence                     s;
    IncompressibleFlowParameters parameters;
    TimerOutput                  timer(MPI_COMM_WORLD,
                      std::cout,
                      TimerOutput::never,
                      TimerOutput::wall_times);
    for (const unsigned int per_unit : levels)
      {
        const RestingVesicle r(per_unit,
                               parameters,
                               timer,
                               PhaseFieldBlockParameters(),
                               zero_normal_derivative,
                               distance,
                               mirrored,
                               epsilon);
        s.energy.push_back(r.model.measure()[0].bending_energy);
        s.lambda_g.push_back(r.model.area_multipliers()[0]);
        s.lambda_v.push_back(r.model.volume_multipliers()[0]);
      }
    return s;
  }

  /// The sequence, and the ratios of successive differences of the energy.
  std::vector<double>
  print(std::ostream                    &out,
        const std::string               &name,
        const Sequence                  &s,
        const std::vector<unsigned int> &per_unit = {8, 16, 32, 64})
  {
    out << name << "\n  per unit, bending energy, lambda_g(0), lambda_v(0)\n";
    for (unsigned int k = 0; k < s.energy.size(); ++k)
      out << "  " << per_unit[k] << ", " << std::setprecision(4) << s.energy[k]
          << ", " << std::setprecision(3) << s.lambda_g[k] << ", "
          << s.lambda_v[k] << '\n';
    std::vector<double> ratios;
    for (unsigned int k = 2; k < s.energy.size(); ++k)
      ratios.push_back((s.energy[k] - s.energy[k - 1])
                       / (s.energy[k - 1] - s.energy[k - 2]));
    return ratios;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = root_output();

  // The ellipse (R_0 = 0.45, chi = 0.84, vertical) and the spheroid (v =
  // 0.7, at 30 degrees) of the geometry checks, with the distance given.
  const Point<2> c2(0.1, -0.2);
  const Point<3> c3(0.1, -0.2, 0.3);
  const auto     ellipse_with = [&](const Distance distance) {
    return InitialVesicle<2>(
      c2, 0.45, 0.84, 90, InitialVesicleBase::StretchFormula::exact, distance);
  };
  const auto spheroid_with = [&](const Distance distance) {
    return InitialVesicle<3>(
      c3, 0.45, 0.7, 30, InitialVesicleBase::StretchFormula::exact, distance);
  };
  const InitialVesicle<2> ellipse = ellipse_with(Distance::level_set);
  check_level_set(out, ellipse, c2);
  const InitialVesicle<3> spheroid = spheroid_with(Distance::level_set);
  check_level_set(out, spheroid, c3);

  const InitialVesicle<2> radial(c2, 0.45, 0.84, 90);
  const double jump = radial.phase_field(c2 + Point<2>(0, 1e-9), 0.125)
                      - radial.phase_field(c2 + Point<2>(1e-9, 0), 0.125);
  out << "radial distance (H23): phi_0 jumps at the centre by "
      << std::setprecision(2) << jump << ", centre_jump() "
      << verdict(std::abs(jump - radial.centre_jump(0.125)) < 1e-6)
      << "; a circle: "
      << verdict(InitialVesicle<2>(c2, 0.45, 1, 90).centre_jump(0.125) == 0)
      << '\n';
  // The largest sqrt(1 + (rho' / rho)^2) on the outline, from the polar
  // form of the ellipse (computed apart: 1.25217 for chi = 0.84, gamma_e
  // 1.41626, and 1.87143 for chi = 0.6, gamma_e 1.8583).
  const InitialVesicle<2> thin(c2, 0.45, 0.6, 90);
  out << "outline slope: radial "
      << verdict(std::abs(radial.outline_slope() - 1.25217) < 1e-4
                 && std::abs(thin.outline_slope() - 1.87143) < 1e-4)
      << ", level-set 1 "
      << verdict(std::abs(ellipse.outline_slope() - 1) < 1e-6
                 && std::abs(spheroid.outline_slope() - 1) < 1e-6)
      << ", a circle 1 "
      << verdict(
           std::abs(InitialVesicle<2>(c2, 0.45, 1, 90).outline_slope() - 1)
           < 1e-6)
      << '\n';
  // The exact distance: unit slope on the outline, and along the minor
  // axis (whose points, but for the centre, all have the minor vertex as
  // their closest point) d = s - a exactly, inside and outside.
  const InitialVesicle<2> exact            = ellipse_with(Distance::exact);
  const InitialVesicle<3> exact_3d         = spheroid_with(Distance::exact);
  const double            a                = 0.45 / exact.stretch();
  double                  minor_axis_error = 0;
  for (const double s : {0.2 * a, 0.7 * a, 1.3 * a, 3 * a})
    minor_axis_error
      = std::max(minor_axis_error,
                 std::abs(exact.signed_distance(c2 + Point<2>(s, 0))
                          - (s - a)));
  out << "exact distance: slope 1 on the outline "
      << verdict(std::abs(exact.outline_slope() - 1) < 1e-6
                 && std::abs(exact_3d.outline_slope() - 1) < 1e-6)
      << ", d = s - a along the minor axis "
      << verdict(minor_axis_error < 1e-12) << '\n';

  const auto grows
    = print(out, "radial, natural", refine(Distance::radial, false));
  out << "  differences grow: " << verdict(grows[0] > 2 && grows[1] > 2)
      << '\n';
  const auto converges
    = print(out, "level-set, natural", refine(Distance::level_set, false));
  out << "  differences fall fivefold: "
      << verdict(converges[0] < 0.2 && converges[1] < 0.2) << '\n';
  const auto layer = print(out,
                           "level-set, d phi / dn = 0, 3 eps from the walls",
                           refine(Distance::level_set, true));
  out << "  last difference above the one before: " << verdict(layer[1] > 1)
      << '\n';
  const auto mirrored = print(out,
                              "level-set, d phi / dn = 0, mirrored",
                              refine(Distance::level_set, true, true));
  out << "  differences fall fivefold: "
      << verdict(mirrored[0] < 0.2 && mirrored[1] < 0.2) << '\n';
  const auto kinked
    = print(out,
            "exact, d phi / dn = 0, mirrored, eps = 0.125 (a = 2.5 eps)",
            refine(Distance::exact, true, true));
  out << "  differences grow: " << verdict(kinked[0] > 1 && kinked[1] > 1)
      << '\n';
  // At a = 5.1 eps and eps = 2 h (32 per unit), the spec's resolution:
  // the three starts against the sharp ellipse's kappa_s / 2 int k^2 ds =
  // 0.19722 (kappa_s = (2 sqrt2 / 3) / (Re Ca), computed apart by
  // quadrature of the ellipse; the HD1 value 0.10284 for R_0 = 0.863 scaled
  // by 0.863 / 0.45). Under refinement at this eps the exact distance's
  // kink is resolved: lambda_g(0) grows.
  const Sequence resolved
    = refine(Distance::exact, true, true, 0.0625, {16, 32, 64});
  print(out,
        "exact, d phi / dn = 0, mirrored, eps = 0.0625 (a = 5.1 eps)",
        resolved,
        {16, 32, 64});
  const double sharp = 0.19722;
  out << "  within 15 % of the sharp ellipse's energy at 32 and 64 per unit: "
      << verdict(std::abs(resolved.energy[1] / sharp - 1) < 0.15
                 && std::abs(resolved.energy[2] / sharp - 1) < 0.15)
      << "\n  lambda_g(0) grows from 32 to 64 per unit (the kink): "
      << verdict(resolved.lambda_g[2] < 2 * resolved.lambda_g[1]) << '\n';
  for (const auto distance : {Distance::radial, Distance::level_set})
    {
      const auto start = refine(distance, true, true, 0.0625, {32});
      out << (distance == Distance::radial ? "radial" : "level-set")
          << ", eps = 0.0625, 32 per unit: bending energy "
          << std::setprecision(4) << start.energy[0]
          << ", above the exact distance's by more than 50 %: "
          << verdict(start.energy[0] > 1.5 * resolved.energy[1]) << '\n';
    }
}
