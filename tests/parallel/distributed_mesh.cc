// The distributed patch mesh (parallel/patch_mesh) against the mesh it
// replaces, a parallel::shared::Triangulation partitioned by METIS
// (partition_metis, artificial cells allowed) and transformed by the
// geometry, built here on every rank:
//  - the same owner of every element (the partition, and so every count
//    of the solvers on N ranks, is unchanged);
//  - the same local cells: the owned ones and the ghost layer (every cell
//    sharing a vertex with an owned one), with the same owners and the
//    same vertices (to 1e-14, after the NURBS map);
//  - the owned elements of all ranks are every element exactly once;
//  - the same largest cell diameter;
//  - on more than one rank, no rank holds the whole mesh.
// Cases: a 2D box with unequal elements (13 x 7, one direction periodic),
// a 3D box (6 x 5 x 4) and the NURBS plate with a hole (spec P2, h-refined 3
// times). Run on 1, 2 and 3 ranks; every check prints "ok" or "FAILED".

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <vesicle_iga/parallel/patch_mesh.h>
#include <vesicle_iga/studies/plate_with_hole_geometry.h>

#include <fstream>
#include <map>

#include "../root_output.h"

using namespace vesicle_iga;
using namespace dealii;

std::string
ok(const bool pass)
{
  return pass ? "ok" : "FAILED";
}

/// Owner and corners of each local cell, by element index.
template <int dim, typename Tria>
std::map<unsigned int, std::pair<unsigned int, std::vector<Point<dim>>>>
local_cells(const Tria &tria)
{
  std::map<unsigned int, std::pair<unsigned int, std::vector<Point<dim>>>>
    cells;
  for (const auto &cell : tria.active_cell_iterators())
    if (!cell->is_artificial())
      {
        std::vector<Point<dim>> corners;
        for (const unsigned int v : cell->vertex_indices())
          corners.push_back(cell->vertex(v));
        cells[cell->user_index()] = {cell->subdomain_id(), corners};
      }
  return cells;
}

template <int dim>
void
check(const std::string                        &name,
      const SplineSpace<dim>                   &space,
      std::shared_ptr<const NurbsGeometry<dim>> geometry,
      std::ostream                             &out)
{
  const MPI_Comm comm = MPI_COMM_WORLD;

  parallel::shared::Triangulation<dim> shared(
    comm,
    Triangulation<dim>::none,
    true,
    parallel::shared::Triangulation<dim>::partition_metis);
  std::vector<std::vector<double>> steps(dim);
  Point<dim>                       lower, upper;
  for (unsigned int d = 0; d < dim; ++d)
    {
      const auto &z = space.knot_vector(d).breakpoints();
      for (unsigned int i = 0; i + 1 < z.size(); ++i)
        steps[d].push_back(z[i + 1] - z[i]);
      lower[d] = z.front();
      upper[d] = z.back();
    }
  GridGenerator::subdivided_hyper_rectangle(shared, steps, lower, upper);
  for (const auto &cell : shared.active_cell_iterators())
    cell->set_user_index(space.find_element(cell->center()));
  if (geometry)
    GridTools::transform(
      [&](const Point<dim> &xi) { return geometry->point(xi); }, shared);
  double h = 0;
  for (const auto &cell : shared.active_cell_iterators())
    h = std::max(h, cell->diameter());

  const PatchMesh<dim> mesh(comm, space, geometry);

  bool same_owner = true;
  for (const auto &cell : shared.active_cell_iterators())
    same_owner
      = same_owner
        && mesh.element_owner(cell->user_index())
             == shared
                  .get_true_subdomain_ids_of_cells()[cell->active_cell_index()];

  const auto expected   = local_cells<dim>(shared);
  const auto actual     = local_cells<dim>(mesh.triangulation());
  bool       same_cells = expected.size() == actual.size();
  for (const auto &[e, cell] : actual)
    {
      const auto it = expected.find(e);
      same_cells
        = same_cells && it != expected.end() && it->second.first == cell.first;
      for (unsigned int v = 0; same_cells && v < cell.second.size(); ++v)
        same_cells = (cell.second[v] - it->second.second[v]).norm() < 1e-14;
    }

  std::vector<unsigned int> owned;
  for (const auto &cell : mesh.triangulation().active_cell_iterators())
    if (cell->is_locally_owned())
      owned.push_back(cell->user_index());
  const bool owned_listed = owned == mesh.locally_owned_elements();
  const auto all_owned    = Utilities::MPI::all_gather(comm, owned);
  std::vector<unsigned int> each(space.n_elements(), 0);
  for (const auto &rank : all_owned)
    for (const unsigned int e : rank)
      ++each[e];
  const bool once = std::all_of(each.begin(), each.end(), [](unsigned int c) {
    return c == 1;
  });

  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
  const bool         partial
    = n_ranks == 1
      || Utilities::MPI::max(mesh.triangulation().n_active_cells(), comm)
           < space.n_elements();

  out << name << " (" << space.n_elements() << " elements): owners "
      << ok(Utilities::MPI::min(int(same_owner), comm) == 1) << ", local cells "
      << ok(Utilities::MPI::min(int(same_cells && owned_listed), comm) == 1)
      << ", each element owned once " << ok(once) << ", diameter "
      << ok(std::abs(mesh.max_cell_diameter() - h) < 1e-14 * h)
      << ", no rank holds all " << ok(partial) << "\n";
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = root_output();

  const KnotVector kx(
    2,
    {0, 0.1, 0.3, 0.35, 0.6, 0.7, 0.8, 1.0, 1.2, 1.3, 1.5, 1.6, 1.9, 2.0},
    {},
    true);
  check<2>("2D box, x periodic",
           SplineSpace<2>(
             std::array<KnotVector, 2>{{kx, KnotVector::uniform(3, 7, -1, 1)}}),
           nullptr,
           out);
  check<3>("3D box",
           SplineSpace<3>(
             std::array<KnotVector, 3>{{KnotVector::uniform(2, 6, 0, 1),
                                        KnotVector::uniform(2, 5, -1, 0),
                                        KnotVector::uniform(3, 4, 0, 2)}}),
           nullptr,
           out);
  const auto plate = make_plate_with_hole_geometry();
  const auto space = plate->space().h_refined(3);
  check<2>("NURBS plate with a hole",
           space,
           std::make_shared<NurbsGeometry<2>>(plate->refined_to(space)),
           out);
}
