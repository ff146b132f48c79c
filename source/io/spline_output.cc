#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe_field.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/numerics/data_out.h>

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


  template <int dim>
  std::string
  SplineFieldWriter<dim>::write(const TrilinosWrappers::MPI::Vector &ghosted,
                                const std::string                   &directory,
                                const std::string &basename) const
  {
    const auto        &tria = spline_dofs.get_mesh().triangulation();
    const unsigned int p    = max_degree(spline_dofs.get_space());

    DoFHandler<dim> fe_dofs(tria);
    fe_dofs.distribute_dofs(FESystem<dim>(FE_Q<dim>(p), quantities.size()));
    LinearAlgebra::distributed::Vector<double> fields;
    interpolate_to_fe_field(
      spline_dofs, geometry, ghosted, quantities, order, fe_dofs, fields);

    // Geometry of the output cells: the NURBS map interpolated in the same
    // FE_Q space (for boxes the cells are straight and MappingQ(1) is exact).
    DoFHandler<dim> geometry_dofs(tria);
    geometry_dofs.distribute_dofs(FESystem<dim>(FE_Q<dim>(p), dim));
    LinearAlgebra::distributed::Vector<double> euler;
    std::vector<PointEvaluator<dim>>           coordinate;
    for (unsigned int d = 0; d < dim; ++d)
      coordinate.push_back([d](const SplineCellValues<dim> &v,
                               const unsigned int           q,
                               const std::vector<std::vector<double>> &) {
        return v.quadrature_point(q)[d];
      });
    interpolate_to_fe_field(
      spline_dofs, geometry, ghosted, coordinate, 0, geometry_dofs, euler);
    const MappingQ<dim> q1(1);
    const MappingFEField<dim, dim, LinearAlgebra::distributed::Vector<double>>
                        curved(geometry_dofs, euler);
    const Mapping<dim> &mapping
      = geometry ? static_cast<const Mapping<dim> &>(curved) : q1;

    DataOut<dim> data_out;
    data_out.attach_dof_handler(fe_dofs);
    data_out.add_data_vector(fields, names);
    Vector<float> subdomain(tria.n_active_cells());
    for (const auto &cell : tria.active_cell_iterators())
      subdomain(cell->active_cell_index()) = cell->subdomain_id();
    data_out.add_data_vector(subdomain, "subdomain");
    DataOutBase::VtkFlags flags;
    flags.write_higher_order_cells = true;
    data_out.set_flags(flags);
    data_out.build_patches(mapping, p, DataOut<dim>::curved_inner_cells);
    // Every rank writes its piece; all agree on the outcome, so that a
    // rank that cannot write ends the run with a message instead of
    // leaving the others in the next collective.
    std::string record, error;
    try
      {
        record = data_out.write_vtu_with_pvtu_record(
          directory + "/", basename, 0, tria.get_communicator(), 0, 0);
      }
    catch (...)
      {
        error = "rank "
                + std::to_string(
                  Utilities::MPI::this_mpi_process(tria.get_communicator()));
      }
    if (fault_requested("vtu-write"))
      kill_while_writing(directory + "/" + record);
    const auto  failed = Utilities::MPI::gather(tria.get_communicator(), error);
    std::string ranks;
    for (const auto &f : failed)
      if (!f.empty())
        ranks += (ranks.empty() ? "" : ", ") + f;
    ranks = Utilities::MPI::broadcast(tria.get_communicator(), ranks, 0);
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
