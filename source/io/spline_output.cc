#include <deal.II/base/data_out_base.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>

#include <vesicle_iga/base/fault_injection.h>
#include <vesicle_iga/fields/spline_dof_handler.h>
#include <vesicle_iga/io/spline_output.h>

#include <algorithm>
#include <filesystem>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    /// Test fault "vtu-write": a kill in the middle of the file (its
    /// second half lost).
    [[noreturn]] void
    kill_while_writing(const std::string &filename)
    {
      std::error_code error;
      const auto      size = std::filesystem::file_size(filename, error);
      if (!error)
        std::filesystem::resize_file(filename, size / 2, error);
      kill_process();
    }

    template <int dim>
    unsigned int
    max_degree(const SplineSpace<dim> &space)
    {
      unsigned int p = 1;
      for (unsigned int d = 0; d < dim; ++d)
        p = std::max(p, space.knot_vector(d).degree());
      return p;
    }
  } // namespace


  template <int dim>
  void
  interpolate_to_fe_field(const SplineDofHandler<dim>              &spline_dofs,
                          std::shared_ptr<const NurbsGeometry<dim>> geometry,
                          const TrilinosWrappers::MPI::Vector      &ghosted,
                          const std::vector<PointEvaluator<dim>>   &quantities,
                          const unsigned int                        order,
                          const DoFHandler<dim>                    &fe_dofs,
                          LinearAlgebra::distributed::Vector<double> &result)
  {
    const auto &fe   = fe_dofs.get_fe();
    const auto &base = fe.base_element(0);
    AssertThrow(fe.n_components() == quantities.size(),
                ExcMessage("One FE component per quantity."));
    // The support points of FE_Q form a tensor grid: collect the 1D
    // coordinates, and for every FE dof its position in the grid.
    std::array<std::vector<double>, dim> grid;
    for (const auto &p : base.get_unit_support_points())
      for (unsigned int d = 0; d < dim; ++d)
        grid[d].push_back(p[d]);
    for (unsigned int d = 0; d < dim; ++d)
      {
        std::sort(grid[d].begin(), grid[d].end());
        grid[d].erase(std::unique(grid[d].begin(),
                                  grid[d].end(),
                                  [](double a, double b) {
                                    return std::abs(a - b) < 1e-12;
                                  }),
                      grid[d].end());
      }
    std::vector<unsigned int> point_of_dof(fe.n_dofs_per_cell());
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const Point<dim> p
          = base.unit_support_point(fe.system_to_base_index(i).second);
        unsigned int q = 0, stride = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int k
              = std::lower_bound(grid[d].begin(), grid[d].end(), p[d] - 1e-12)
                - grid[d].begin();
            q += k * stride;
            stride *= grid[d].size();
          }
        point_of_dof[i] = q;
      }

    result.reinit(fe_dofs.locally_owned_dofs(),
                  DoFTools::extract_locally_relevant_dofs(fe_dofs),
                  fe_dofs.get_communicator());
    SplineCellValues<dim>                values(spline_dofs.get_space(),
                                 geometry,
                                 QGauss<1>(1),
                                 order);
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    std::vector<std::vector<double>>     c;
    for (const auto &cell : fe_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int e = cell->user_index();
          values.reinit_points(e, grid);
          get_element_coefficients(spline_dofs, ghosted, e, c);
          cell->get_dof_indices(dof_indices);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            if (result.locally_owned_elements().is_element(dof_indices[i]))
              result[dof_indices[i]]
                = quantities[fe.system_to_component_index(i).first](
                  values, point_of_dof[i], c);
        }
    result.update_ghost_values();
  }


  template <int dim>
  SplineFieldWriter<dim>::SplineFieldWriter(
    const SplineDofHandler<dim>              &dofs,
    std::shared_ptr<const NurbsGeometry<dim>> geometry)
    : spline_dofs(dofs)
    , geometry(geometry)
  {}


  template <int dim>
  void
  SplineFieldWriter<dim>::add_quantity(const std::string         &name,
                                       const PointEvaluator<dim> &evaluator,
                                       const unsigned int         derivative)
  {
    names.push_back(name);
    quantities.push_back(evaluator);
    order = std::max(order, derivative);
  }


  template <int dim>
  void
  SplineFieldWriter<dim>::add_components(const std::vector<std::string> &n)
  {
    for (unsigned int c = 0; c < n.size(); ++c)
      add_quantity(n[c],
                   [c](const SplineCellValues<dim>            &v,
                       const unsigned int                      q,
                       const std::vector<std::vector<double>> &coefficients) {
                     return v.value(coefficients[c], q);
                   });
  }


  namespace
  {
    /// Patches built by hand, for DataOutInterface's VTU writers.
    template <int dim>
    class PatchCollection : public DataOutInterface<dim, dim>
    {
    public:
      std::vector<DataOutBase::Patch<dim, dim>> patches;
      std::vector<std::string>                  names;

    private:
      const std::vector<DataOutBase::Patch<dim, dim>> &
      get_patches() const override
      {
        return patches;
      }
      std::vector<std::string>
      get_dataset_names() const override
      {
        return names;
      }
    };
  } // namespace


  template <int dim>
  std::string
  SplineFieldWriter<dim>::write(const TrilinosWrappers::MPI::Vector &ghosted,
                                const std::string                   &directory,
                                const std::string &basename) const
  {
    // One patch per owned element, of degree p: the quantities evaluated at
    // the (p+1)^dim equidistant points of the element, which VTK's Lagrange
    // cells interpolate. On boxes the patch corners define the points (an
    // exact multilinear map); on NURBS patches the physical points are
    // stored with the data. No FE space, DoFHandler or mapping is built,
    // so the output costs (p+1)^dim values per quantity and owned element.
    const MPI_Comm     comm = spline_dofs.get_mesh().get_communicator();
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int p    = max_degree(spline_dofs.get_space());
    std::array<std::vector<double>, dim> grid;
    for (unsigned int d = 0; d < dim; ++d)
      for (unsigned int k = 0; k <= p; ++k)
        grid[d].push_back(double(k) / p);
    const unsigned int n_points = Utilities::pow(p + 1, dim);
    const unsigned int n_data   = quantities.size() + 1;
    const bool         curved   = geometry != nullptr;

    PatchCollection<dim> collection;
    collection.names = names;
    collection.names.emplace_back("subdomain");
    SplineCellValues<dim>            values(spline_dofs.get_space(),
                                 geometry,
                                 QGauss<1>(1),
                                 order);
    std::vector<std::vector<double>> c;
    for (const unsigned int e : spline_dofs.get_mesh().locally_owned_elements())
      {
        values.reinit_points(e, grid);
        get_element_coefficients(spline_dofs, ghosted, e, c);
        DataOutBase::Patch<dim, dim> patch;
        patch.patch_index          = collection.patches.size();
        patch.n_subdivisions       = p;
        patch.reference_cell       = ReferenceCells::get_hypercube<dim>();
        patch.points_are_available = curved;
        patch.data.reinit(n_data + (curved ? dim : 0), n_points);
        for (unsigned int q = 0; q < n_points; ++q)
          {
            for (unsigned int k = 0; k < quantities.size(); ++k)
              patch.data(k, q) = quantities[k](values, q, c);
            patch.data(n_data - 1, q) = rank;
            if (curved)
              for (unsigned int d = 0; d < dim; ++d)
                patch.data(n_data + d, q) = values.quadrature_point(q)[d];
          }
        // Corner v (lexicographic, as deal.II numbers cell vertices) is
        // the point p * (v_0 + (p+1) v_1 + ...).
        for (const unsigned int v : GeometryInfo<dim>::vertex_indices())
          {
            unsigned int q = 0;
            for (unsigned int d = 0, stride = p; d < dim; ++d, stride *= p + 1)
              q += ((v >> d) & 1) * stride;
            patch.vertices[v] = values.quadrature_point(q);
          }
        collection.patches.push_back(std::move(patch));
      }
    DataOutBase::VtkFlags flags;
    flags.write_higher_order_cells = true;
    // deal.II's default, best_compression, spent 10 s of zlib on a 30^3
    // cubic field (23 MB) against a Newton iteration of 7 s; best_speed
    // writes it in a fraction of that for a somewhat larger file.
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    collection.set_flags(flags);

    // Every rank writes its piece; all agree on the outcome, so that a
    // rank that cannot write ends the run with a message instead of
    // leaving the others in the next collective.
    std::string record, error;
    try
      {
        record = collection.write_vtu_with_pvtu_record(
          directory + "/", basename, 0, comm, 0, 0);
      }
    catch (...)
      {
        error = "rank " + std::to_string(rank);
      }
    if (fault_requested("vtu-write"))
      kill_while_writing(directory + "/" + record);
    const auto  failed = Utilities::MPI::gather(comm, error);
    std::string ranks;
    for (const auto &f : failed)
      if (!f.empty())
        ranks += (ranks.empty() ? "" : ", ") + f;
    ranks = Utilities::MPI::broadcast(comm, ranks, 0);
    AssertThrow(ranks.empty(),
                ExcMessage("cannot write the VTU output " + directory + "/"
                           + basename + "* (" + ranks
                           + " failed: no permission, disk full, quota or "
                             "file size limit?)"));
    return record;
  }

  template class SplineFieldWriter<2>;
  template class SplineFieldWriter<3>;
  template void
  interpolate_to_fe_field(const SplineDofHandler<2> &,
                          std::shared_ptr<const NurbsGeometry<2>>,
                          const TrilinosWrappers::MPI::Vector &,
                          const std::vector<PointEvaluator<2>> &,
                          const unsigned int,
                          const DoFHandler<2> &,
                          LinearAlgebra::distributed::Vector<double> &);
  template void
  interpolate_to_fe_field(const SplineDofHandler<3> &,
                          std::shared_ptr<const NurbsGeometry<3>>,
                          const TrilinosWrappers::MPI::Vector &,
                          const std::vector<PointEvaluator<3>> &,
                          const unsigned int,
                          const DoFHandler<3> &,
                          LinearAlgebra::distributed::Vector<double> &);
} // namespace vesicle_iga
