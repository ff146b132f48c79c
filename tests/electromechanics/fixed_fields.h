// Shared by the flexoelectric tests: spline fields of given functions and
// the potential problem (E16) on a 2D box, with what ElectricPotential
// refers to kept alive next to it.
#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <vesicle_iga/fields/natural_numbering.h>
#include <vesicle_iga/models/electric_potential.h>

#include <functional>
#include <ostream>

// The spline interpolant (Greville points) of f, ghosted.
template <int dim>
dealii::TrilinosWrappers::MPI::Vector
ghosted_interpolant(const vesicle_iga::SplineDofHandler<dim> &dofs,
                    const vesicle_iga::SplineSpace<dim>      &space,
                    const std::function<double(const dealii::Point<dim> &)> &f)
{
  std::vector<double> values(space.n_basis());
  for (unsigned int i = 0; i < space.n_basis(); ++i)
    values[i] = f(space.greville_point(i));
  dealii::TrilinosWrappers::MPI::Vector owned(dofs.locally_owned_dofs(),
                                              MPI_COMM_WORLD);
  vesicle_iga::scatter_natural(
    dofs, vesicle_iga::interpolate_at_greville_points(space, values, 1), owned);
  dealii::TrilinosWrappers::MPI::Vector ghosted(dofs.locally_owned_dofs(),
                                                dofs.locally_relevant_dofs(),
                                                MPI_COMM_WORLD);
  ghosted = owned;
  return ghosted;
}

// The potential of (E16) at field strength E0 (V/m), solved by CG with the
// spline multigrid to @p tolerance, 6 Gauss points.
struct PotentialProblem
{
  PotentialProblem(const vesicle_iga::SplineDofHandler<2> &dofs,
                   const double                            field_strength,
                   const double                            tolerance,
                   std::ostream                           &out)
    : material(with_field(field_strength))
    , solver(cg_mg(tolerance))
    , timer(MPI_COMM_WORLD,
            out,
            dealii::TimerOutput::never,
            dealii::TimerOutput::wall_times)
    , quadrature(6)
    , potential(dofs, material, quadrature, solver, timer)
  {}

  static vesicle_iga::ElectromechanicsMaterial
  with_field(const double field_strength)
  {
    vesicle_iga::ElectromechanicsMaterial m;
    m.field_strength = field_strength;
    return m;
  }
  static vesicle_iga::LinearSolverParameters
  cg_mg(const double tolerance)
  {
    vesicle_iga::LinearSolverParameters p;
    p.method    = "cg-mg";
    p.tolerance = tolerance;
    return p;
  }

  const vesicle_iga::ElectromechanicsMaterial material;
  const vesicle_iga::LinearSolverParameters   solver;
  dealii::TimerOutput                         timer;
  const dealii::QGauss<1>                     quadrature;
  vesicle_iga::ElectricPotential<2>           potential;
};
