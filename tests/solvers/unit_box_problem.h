// Shared by the solver tests: a stationary problem on the unit box with
// n^dim uniform elements of degree p (C^{p-1}), and the homogeneous clamped
// conditions (u = du/dn = 0 on the whole boundary) of the primal biharmonic
// problem.
#pragma once

#include <deal.II/base/function.h>

#include <vesicle_iga/fields/dirichlet_constraints.h>
#include <vesicle_iga/models/stationary_problem.h>

#include <memory>

template <int dim>
std::unique_ptr<vesicle_iga::StationaryProblem<dim>>
unit_box_problem(const MPI_Comm     comm,
                 const unsigned int p,
                 const unsigned int n)
{
  std::array<vesicle_iga::KnotVector, dim> kv;
  for (unsigned int d = 0; d < dim; ++d)
    kv[d] = vesicle_iga::KnotVector::uniform(p, n, 0., 1.);
  return std::make_unique<vesicle_iga::StationaryProblem<dim>>(
    comm, vesicle_iga::SplineSpace<dim>(kv), nullptr, 1);
}


template <int dim>
void
add_homogeneous_clamped_constraints(
  vesicle_iga::StationaryProblem<dim> &problem)
{
  const vesicle_iga::BoundarySelection<dim>  all("all", "boundary");
  const dealii::Functions::ZeroFunction<dim> zero;
  vesicle_iga::add_clamped_constraints<dim>(
    problem.dofs(),
    all,
    zero,
    [](const dealii::Point<dim> &, const dealii::Tensor<1, dim> &) {
      return 0.;
    },
    problem.constraints());
}
