// Set-up shared by the hydrodynamics tests: cubic uniform knot vectors of a
// box, the flow coefficients of spec Part H for cubic splines and strong
// velocity conditions on every wall.
#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <vesicle_iga/models/vesicle_hydrodynamics.h>
#include <vesicle_iga/physics/initial_vesicle.h>
#include <vesicle_iga/spline/knot_vector.h>

#include <array>
#include <cmath>
#include <fstream>
#include <memory>
#include <vector>

#include "../root_output.h"

namespace vesicle_iga
{
  /// Cubic C^2 knot vectors of [x_0, x_1] x [y_0, y_1] with n_x x n_y
  /// uniform elements.
  inline std::array<KnotVector, 2>
  cubic_box_knots(const unsigned int n_x,
                  const double       x_0,
                  const double       x_1,
                  const unsigned int n_y,
                  const double       y_0,
                  const double       y_1)
  {
    return {{KnotVector::uniform(3, n_x, x_0, x_1),
             KnotVector::uniform(3, n_y, y_0, y_1)}};
  }

  /// The same on the square [lower, upper]^2 with n x n elements.
  inline std::array<KnotVector, 2>
  cubic_box_knots(const unsigned int n, const double lower, const double upper)
  {
    return cubic_box_knots(n, lower, upper, n, lower, upper);
  }

  /// Re of (H4) from the membrane coefficients and the inverse-estimate
  /// constant C_I = 6 p^4 of (H19) for p = 3.
  inline FlowCoefficients<2>
  cubic_flow_coefficients(const MembraneCoefficients &membrane)
  {
    FlowCoefficients<2> flow;
    flow.reynolds_number           = membrane.reynolds_number;
    flow.inverse_estimate_constant = 6. * std::pow(3., 4);
    return flow;
  }

  /// @p velocity (dim velocity components and a pressure slot) strongly on
  /// every wall.
  inline std::vector<VelocityCondition<2>>
  strong_walls(std::shared_ptr<dealii::Function<2>> velocity)
  {
    return {{BoundarySelection<2>("all", "walls"), velocity, false}};
  }
  /// One vesicle (R_0 = 0.45, chi = 0.84, major axis vertical) at the
  /// centre of [-1, 1]^2 with 2 @p per_unit cubic elements per direction,
  /// eps = @p epsilon (0.125 unless given), fluid at rest, u = 0 strongly on every wall (the solver
  /// tests' set-up), in its initial state (multipliers of (H13) included).
  struct RestingVesicle
  {
    RestingVesicle(const unsigned int                  per_unit,
                   const IncompressibleFlowParameters &parameters,
                   dealii::TimerOutput                &timer,
                   const PhaseFieldBlockParameters    &phase_field_blocks
                   = PhaseFieldBlockParameters(),
                   const bool zero_normal_derivative = true,
                   const InitialVesicleBase::DistanceFormula distance
                   = InitialVesicleBase::DistanceFormula::radial,
                   const bool   mirrored_phase = false,
                   const double epsilon        = 0.125)
      : space(cubic_box_knots(2 * per_unit, -1., 1.))
      , membrane(coefficients(zero_normal_derivative, epsilon))
      , model(MPI_COMM_WORLD,
              space,
              membrane,
              cubic_flow_coefficients(membrane),
              strong_walls(
                std::make_shared<dealii::Functions::ZeroFunction<2>>(3)),
              parameters,
              1,
              timer,
              phase_field_blocks)
      , vesicle(dealii::Point<2>(0., 0.),
                0.45,
                0.84,
                90,
                InitialVesicleBase::StretchFormula::exact,
                distance)
    {
      model.set_initial_state(
        dealii::Functions::ZeroFunction<2>(2),
        {[this, mirrored_phase, epsilon](const dealii::Point<2> &x) {
          return mirrored_phase ?
                   vesicle.mirrored_phase_field(x,
                                                epsilon,
                                                dealii::Point<2>(-1., -1.),
                                                dealii::Point<2>(1., 1.),
                                                {{true, true}}) :
                   vesicle.phase_field(x, epsilon);
        }});
    }

    static MembraneCoefficients
    coefficients(const bool zero_normal_derivative, const double epsilon)
    {
      MembraneCoefficients m;
      m.epsilon                = epsilon;
      m.zero_normal_derivative = zero_normal_derivative;
      return m;
    }

    const SplineSpace<2>       space;
    const MembraneCoefficients membrane;
    VesicleHydrodynamics<2>    model;
    const InitialVesicle<2>    vesicle;
  };

  /// One step of dt of the RestingVesicle: the FGMRES count per Newton
  /// iteration and the vesicle's measures after the step.
  struct RestingVesicleStep
  {
    double          per_newton = 0;
    VesicleMeasures measures;
  };

  inline RestingVesicleStep
  step_resting_vesicle(const unsigned int                  per_unit,
                       const IncompressibleFlowParameters &parameters,
                       const double                        dt,
                       dealii::TimerOutput                &timer,
                       const PhaseFieldBlockParameters    &phase_field_blocks
                       = PhaseFieldBlockParameters(),
                       const bool zero_normal_derivative = true)
  {
    RestingVesicle resting(
      per_unit, parameters, timer, phase_field_blocks, zero_normal_derivative);
    const StepReport r = resting.model.solve_step(dt);
    resting.model.accept_step();
    return {double(r.krylov_iterations) / r.newton_iterations,
            resting.model.measure()[0]};
  }
  /// Multipliers and constraint changes of a vesicle started from rest.
  struct VesicleStart
  {
    double lambda_g = 0, lambda_v = 0, area_change = 0, volume_change = 0;
  };

  /// A vesicle of R_0 = 1 and reduced area @p chi (major axis vertical) at
  /// the centre of [-2, 2]^2 with 4 @p per_unit cubic elements per
  /// direction, eps = 0.125, phi_0 on @p distance mirrored in the walls
  /// (compatible with d phi / dn = 0), u = 0 strongly on every wall, FGMRES
  /// and Newton to 1e-8: its multipliers of (H13) at t = 0 and, if @p step
  /// > 0, the relative changes of A and V over one step of that size (the
  /// set-up of tests/hydrodynamics/circle_start and volume_indicator).
  inline VesicleStart
  start_from_rest(const double                                 chi,
                  const unsigned int                           per_unit,
                  const MembraneCoefficients::VolumeMultiplier form,
                  const InitialVesicleBase::DistanceFormula    distance,
                  const double                                 step)
  {
    IncompressibleFlowParameters parameters;
    parameters.solver.method                    = "fgmres-block";
    parameters.solver.tolerance                 = 1e-8;
    parameters.solver.max_iterations            = 400;
    parameters.solver.block.schur_approximation = "stabilized-cahouet-chabard";
    parameters.quadrature_points                = 5;
    parameters.newton.relative_tolerance        = 1e-8;
    parameters.newton.absolute_tolerance        = 1e-12;
    dealii::TimerOutput  timer(MPI_COMM_WORLD,
                              std::cout,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);
    const SplineSpace<2> space(cubic_box_knots(4 * per_unit, -2., 2.));
    MembraneCoefficients membrane;
    membrane.epsilon           = 0.125;
    membrane.volume_multiplier = form;
    VesicleHydrodynamics<2> model(
      MPI_COMM_WORLD,
      space,
      membrane,
      cubic_flow_coefficients(membrane),
      strong_walls(std::make_shared<dealii::Functions::ZeroFunction<2>>(3)),
      parameters,
      1,
      timer);
    const InitialVesicle<2> vesicle(dealii::Point<2>(),
                                    1.,
                                    chi,
                                    90,
                                    InitialVesicleBase::StretchFormula::exact,
                                    distance);
    model.set_initial_state(dealii::Functions::ZeroFunction<2>(2),
                            {[&vesicle](const dealii::Point<2> &x) {
                              return vesicle.mirrored_phase_field(
                                x,
                                0.125,
                                dealii::Point<2>(-2, -2),
                                dealii::Point<2>(2, 2),
                                {{true, true}});
                            }});
    VesicleStart s;
    s.lambda_g = model.area_multipliers()[0];
    s.lambda_v = model.volume_multipliers()[0];
    if (step > 0)
      {
        model.solve_step(step);
        model.accept_step();
        const auto m    = model.measure()[0];
        s.area_change   = std::abs(m.area / model.initial_areas()[0] - 1);
        s.volume_change = std::abs(m.volume / model.initial_volumes()[0] - 1);
      }
    return s;
  }
} // namespace vesicle_iga
