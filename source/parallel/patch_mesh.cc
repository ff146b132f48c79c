#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <deal.II/grid/cell_id.h>
#include <deal.II/grid/tria_description.h>

#include <vesicle_iga/parallel/patch_mesh.h>

#include <algorithm>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    std::array<unsigned int, dim>
    elements_per_direction(const SplineSpace<dim> &space)
    {
      std::array<unsigned int, dim> n;
      for (unsigned int d = 0; d < dim; ++d)
        n[d] = space.knot_vector(d).n_elements();
      return n;
    }


    /// The owner of every element: METIS on the graph of the elements that
    /// share a face (periodic directions not wrapped), with the diagonal,
    /// as GridTools::partition_triangulation builds it for a box mesh whose
    /// active cells are numbered as the elements (lexicographic, x
    /// fastest).
    template <int dim>
    std::vector<types::subdomain_id>
    partition_elements(const SplineSpace<dim> &space,
                       const unsigned int      n_parts)
    {
      const unsigned int               n = space.n_elements();
      std::vector<types::subdomain_id> owner(n, 0);
      if (n_parts == 1)
        return owner;
      const auto             n_dir = elements_per_direction(space);
      DynamicSparsityPattern faces(n, n);
      for (unsigned int e = 0; e < n; ++e)
        {
          faces.add(e, e);
          const auto m = space.element_multi_index(e);
          for (unsigned int d = 0; d < dim; ++d)
            for (const int step : {-1, 1})
              if (int(m[d]) + step >= 0 && int(m[d]) + step < int(n_dir[d]))
                {
                  auto neighbour = m;
                  neighbour[d] += step;
                  faces.add(e, space.element_index(neighbour));
                }
        }
      SparsityPattern graph;
      graph.copy_from(faces);
      std::vector<unsigned int> parts(n);
      SparsityTools::partition(graph,
                               std::vector<unsigned int>(),
                               n_parts,
                               parts,
                               SparsityTools::Partitioner::metis);
      std::copy(parts.begin(), parts.end(), owner.begin());
      return owner;
    }


    /// The owned elements and the ghost layer: every element that shares a
    /// vertex with an owned one, in increasing order.
    template <int dim>
    std::vector<unsigned int>
    relevant_elements(const SplineSpace<dim>          &space,
                      const std::vector<unsigned int> &owned)
    {
      const auto                n_dir = elements_per_direction(space);
      std::vector<unsigned int> relevant;
      for (const unsigned int e : owned)
        {
          const auto m = space.element_multi_index(e);
          for (unsigned int k = 0; k < Utilities::pow(3u, dim); ++k)
            {
              auto neighbour = m;
              bool inside    = true;
              for (unsigned int d = 0, r = k; d < dim; ++d, r /= 3)
                {
                  const int j  = int(m[d]) + int(r % 3) - 1;
                  inside       = inside && j >= 0 && j < int(n_dir[d]);
                  neighbour[d] = j;
                }
              if (inside)
                relevant.push_back(space.element_index(neighbour));
            }
        }
      std::sort(relevant.begin(), relevant.end());
      relevant.erase(std::unique(relevant.begin(), relevant.end()),
                     relevant.end());
      return relevant;
    }


    /// The description of the local part of the mesh: the relevant elements
    /// as coarse cells (coarse cell id = element index), their corners as
    /// vertices, the owners as subdomains.
    template <int dim>
    TriangulationDescription::Description<dim, dim>
    describe_local_mesh(const SplineSpace<dim>                 &space,
                        const NurbsGeometry<dim>               *geometry,
                        const std::vector<types::subdomain_id> &owner,
                        const std::vector<unsigned int>        &relevant,
                        const MPI_Comm                          comm)
    {
      const auto n_dir = elements_per_direction(space);
      // Global number of the vertex with multi-index v (lexicographic).
      const auto vertex_number = [&](const std::array<unsigned int, dim> &v) {
        std::uint64_t i = 0;
        for (int d = dim - 1; d >= 0; --d)
          i = i * (n_dir[d] + 1) + v[d];
        return i;
      };
      // Corner c (deal.II's lexicographic vertex order) of element e.
      const auto corner = [&](const unsigned int e, const unsigned int c) {
        auto v = space.element_multi_index(e);
        for (unsigned int d = 0; d < dim; ++d)
          v[d] += (c >> d) & 1;
        return v;
      };
      const unsigned int n_corners = GeometryInfo<dim>::vertices_per_cell;

      std::vector<std::uint64_t> vertices;
      for (const unsigned int e : relevant)
        for (unsigned int c = 0; c < n_corners; ++c)
          vertices.push_back(vertex_number(corner(e, c)));
      std::sort(vertices.begin(), vertices.end());
      vertices.erase(std::unique(vertices.begin(), vertices.end()),
                     vertices.end());

      TriangulationDescription::Description<dim, dim> description;
      description.comm      = comm;
      description.settings  = TriangulationDescription::default_setting;
      description.smoothing = Triangulation<dim>::none;
      for (const std::uint64_t i : vertices)
        {
          Point<dim>    xi;
          std::uint64_t r = i;
          for (unsigned int d = 0; d < dim; ++d)
            {
              xi[d] = space.knot_vector(d).breakpoints()[r % (n_dir[d] + 1)];
              r /= n_dir[d] + 1;
            }
          description.coarse_cell_vertices.push_back(
            geometry ? geometry->point(xi) : xi);
        }

      description.cell_infos.resize(1);
      for (const unsigned int e : relevant)
        {
          CellData<dim> cell(n_corners);
          for (unsigned int c = 0; c < n_corners; ++c)
            cell.vertices[c] = std::lower_bound(vertices.begin(),
                                                vertices.end(),
                                                vertex_number(corner(e, c)))
                               - vertices.begin();
          description.coarse_cells.push_back(cell);
          description.coarse_cell_index_to_coarse_cell_id.push_back(e);

          TriangulationDescription::CellData<dim> info;
          info.id                 = CellId(e, {}).template to_binary<dim>();
          info.subdomain_id       = owner[e];
          info.level_subdomain_id = numbers::artificial_subdomain_id;
          info.manifold_id        = numbers::flat_manifold_id;
          info.manifold_line_ids.fill(numbers::flat_manifold_id);
          info.manifold_quad_ids.fill(numbers::flat_manifold_id);
          description.cell_infos[0].push_back(info);
        }
      return description;
    }
  } // namespace


  template <int dim>
  PatchMesh<dim>::PatchMesh(const MPI_Comm                            comm,
                            const SplineSpace<dim>                   &space,
                            std::shared_ptr<const NurbsGeometry<dim>> geometry)
    : tria(comm)
    , owner(partition_elements(space, Utilities::MPI::n_mpi_processes(comm)))
  {
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    for (unsigned int e = 0; e < owner.size(); ++e)
      if (owner[e] == rank)
        owned_elements.push_back(e);

    tria.create_triangulation(
      describe_local_mesh(space,
                          geometry.get(),
                          owner,
                          relevant_elements(space, owned_elements),
                          comm));
    for (const auto &cell : tria.active_cell_iterators())
      {
        cell->set_user_index(cell->id().get_coarse_cell_id());
        if (cell->is_locally_owned())
          max_diameter = std::max(max_diameter, cell->diameter());
      }
    max_diameter = Utilities::MPI::max(max_diameter, comm);
  }

  template class PatchMesh<1>;
  template class PatchMesh<2>;
  template class PatchMesh<3>;
} // namespace vesicle_iga
