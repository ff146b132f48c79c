#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <vesicle_iga/parallel/patch_mesh.h>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  PatchMesh<dim>::PatchMesh(const MPI_Comm                            comm,
                            const SplineSpace<dim>                   &space,
                            std::shared_ptr<const NurbsGeometry<dim>> geometry)
    : tria(comm,
           Triangulation<dim>::none,
           false,
           parallel::shared::Triangulation<dim>::partition_metis)
  {
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
    GridGenerator::subdivided_hyper_rectangle(tria, steps, lower, upper);

    owner.resize(space.n_elements());
    for (const auto &cell : tria.active_cell_iterators())
      {
        const unsigned int e = space.find_element(cell->center());
        cell->set_user_index(e);
        owner[e] = cell->subdomain_id();
        if (cell->is_locally_owned())
          owned_elements.push_back(e);
      }
    std::sort(owned_elements.begin(), owned_elements.end());

    if (geometry)
      GridTools::transform(
        [&](const Point<dim> &xi) { return geometry->point(xi); }, tria);
  }


  template <int dim>
  double
  PatchMesh<dim>::max_cell_diameter() const
  {
    double h = 0;
    for (const auto &cell : tria.active_cell_iterators())
      h = std::max(h, cell->diameter());
    return h;
  }

  template class PatchMesh<1>;
  template class PatchMesh<2>;
  template class PatchMesh<3>;
} // namespace vesicle_iga
