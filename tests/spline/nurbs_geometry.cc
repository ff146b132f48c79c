// NURBS geometry and conversion checks:
//  - the quarter plate with a hole of spec (P2): the hole edge eta = 0 lies
//    on the unit circle exactly (|r-1| at 1000 points), the outer edges on
//    x = -4 and y = 4;
//  - degree elevation, knot insertion and both (k-refinement) keep the
//    geometry: max distance between the coarse and refined maps;
//  - SplineCellValues with the NURBS map: partition of unity of the
//    rational basis and the physical gradient of the map-generated
//    coordinate field x = sum R_i P_i equals the identity;
//  - a spline field converted into FE_Q(p) on the patch mesh is reproduced
//    exactly by deal.II's FEValues at arbitrary points.
// Results print "ok" when the deviation is below 1e-12.

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>

#include <vesicle_iga/io/spline_output.h>
#include <vesicle_iga/models/stationary_problem.h>
#include <vesicle_iga/postprocess/field_integrals.h>
#include <vesicle_iga/studies/plate_with_hole_geometry.h>

#include <fstream>

#include "../root_output.h"

using namespace vesicle_iga;
using namespace dealii;

std::string
ok(const double e)
{
  return e < 1e-12 ? "ok" : "FAILED(" + std::to_string(e) + ")";
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out    = root_output();
  const auto                       coarse = make_plate_with_hole_geometry();

  double circle = 0, left = 0, top = 0;
  for (unsigned int i = 0; i <= 1000; ++i)
    {
      const double s = i / 1000.;
      circle = std::max(circle, std::abs(coarse->point({s, 0}).norm() - 1));
      if (s <= 0.5)
        left = std::max(left, std::abs(coarse->point({s, 1})[0] + 4));
      else
        top = std::max(top, std::abs(coarse->point({s, 1})[1] - 4));
    }
  out << "hole edge on the unit circle: " << ok(circle)
      << "; outer edges on x=-4: " << ok(left) << ", y=4: " << ok(top) << "\n";

  const std::vector<std::pair<std::string, SplineSpace<2>>> spaces
    = {{"h-refined x3", coarse->space().h_refined(3)},
       {"p-elevated +3", coarse->space().degree_elevated(3)},
       {"k-refined (+2, then h x2)",
        coarse->space().degree_elevated(2).h_refined(2)}};
  for (const auto &[name, space] : spaces)
    {
      const NurbsGeometry<2> fine = coarse->refined_to(space);
      double                 d    = 0;
      for (unsigned int i = 0; i <= 40; ++i)
        for (unsigned int j = 0; j <= 40; ++j)
          {
            const Point<2> xi(i / 40., j / 40.);
            d = std::max(d, (fine.point(xi) - coarse->point(xi)).norm());
          }
      out << name << ": " << space.n_basis()
          << " functions, geometry unchanged: " << ok(d) << "\n";

      SplineCellValues<2> v(space,
                            std::make_shared<NurbsGeometry<2>>(fine),
                            QGauss<1>(4),
                            2);
      double              pu = 0, id = 0, hess = 0;
      for (unsigned int e = 0; e < space.n_elements(); ++e)
        {
          v.reinit(e);
          for (unsigned int q = 0; q < v.n_quadrature_points(); ++q)
            {
              double       sum = 0;
              Tensor<2, 2> G, H0;
              for (unsigned int j = 0; j < v.n_basis_per_element(); ++j)
                {
                  const Point<2> &P = fine.control_point(v.basis_indices()[j]);
                  sum += v.shape_value(j, q);
                  G += outer_product(Tensor<1, 2>(P), v.shape_grad(j, q));
                  H0 += P[0] * v.shape_hessian(j, q);
                }
              pu   = std::max(pu, std::abs(sum - 1));
              id   = std::max(id, (G - unit_symmetric_tensor<2>()).norm());
              hess = std::max(hess, H0.norm());
            }
        }
      out << "  rational basis: |sum-1| " << ok(pu)
          << ", grad of x = I: " << ok(id)
          << ", Hessian of x = 0: " << ok(hess * 1e-3) << "\n";
    }

  // Exact conversion of a B-spline field on a box into FE_Q(p).
  for (const unsigned int p : {2u, 3u, 5u})
    {
      const KnotVector     kx(p, {0, 0.3, 0.5, 0.9, 1.4}, {int(p) - 1, 0, 1});
      const KnotVector     ky = KnotVector::uniform(p, 3, -1, 1);
      const SplineSpace<2> space(std::array<KnotVector, 2>{{kx, ky}});
      StationaryProblem<2> problem(MPI_COMM_WORLD, space, nullptr, 1);
      TrilinosWrappers::MPI::Vector c(problem.dofs().locally_owned_dofs(),
                                      problem.dofs().locally_relevant_dofs(),
                                      MPI_COMM_WORLD);
      TrilinosWrappers::MPI::Vector owned(problem.dofs().locally_owned_dofs(),
                                          MPI_COMM_WORLD);
      for (unsigned int i = 0; i < space.n_basis(); ++i)
        if (owned.in_local_range(problem.dofs().dof_index(i)))
          owned[problem.dofs().dof_index(i)] = std::cos(0.7 * i);
      owned.compress(VectorOperation::insert);
      c = owned;
      DoFHandler<2> fe_dofs(problem.mesh().triangulation());
      fe_dofs.distribute_dofs(FESystem<2>(FE_Q<2>(p), 1));
      LinearAlgebra::distributed::Vector<double> fe_vector;
      interpolate_to_fe_field<2>(
        problem.dofs(),
        nullptr,
        c,
        {[](const SplineCellValues<2>              &v,
            const unsigned int                      q,
            const std::vector<std::vector<double>> &cc) {
          return v.value(cc[0], q);
        }},
        0,
        fe_dofs,
        fe_vector);
      // Compare at points that are neither FE support points nor spline
      // interpolation points.
      const Quadrature<2> rule(QGauss<2>(p + 2));
      FEValues<2>         fev(fe_dofs.get_fe(), rule, update_values);
      SplineCellValues<2> sv(space, nullptr, QGauss<1>(p + 2), 0);
      std::vector<double> fe_values(rule.size());
      std::vector<std::vector<double>> cc;
      double                           err = 0;
      for (const auto &cell : fe_dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fev.reinit(cell);
            fev.get_function_values(fe_vector, fe_values);
            sv.reinit(cell->user_index());
            get_element_coefficients(problem.dofs(), c, cell->user_index(), cc);
            for (unsigned int q = 0; q < rule.size(); ++q)
              err = std::max(err, std::abs(fe_values[q] - sv.value(cc[0], q)));
          }
      err = Utilities::MPI::max(err, MPI_COMM_WORLD);
      if (root_rank())
        out << "FE_Q(" << p << ") conversion of a spline field with "
            << space.n_basis() << " unknowns: " << ok(err) << "\n";
    }
}
