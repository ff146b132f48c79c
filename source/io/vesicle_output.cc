#include <deal.II/base/mpi.h>

#include <vesicle_iga/io/checked_output.h>
#include <vesicle_iga/io/spline_output.h>
#include <vesicle_iga/io/vesicle_output.h>

#include <fstream>
#include <iomanip>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  void
  write_vesicle_vtu(const SplineDofHandler<dim>         &dofs,
                    const TrilinosWrappers::MPI::Vector &phi,
                    const TrilinosWrappers::MPI::Vector *psi,
                    const ElectromechanicsMaterial      &material,
                    const std::string                   &directory,
                    const std::string                   &basename)
  {
    const MPI_Comm comm = dofs.get_mesh().get_communicator();
    if (!psi)
      {
        SplineFieldWriter<dim> writer(dofs, nullptr);
        writer.add_components({"phi"});
        writer.write(phi, directory, basename);
        return;
      }
    // One two-component field (phi, psi) on the same basis.
    const SplineDofHandler<dim>   pair(dofs.get_mesh(), dofs.get_space(), 2);
    TrilinosWrappers::MPI::Vector owned(pair.locally_owned_dofs(), comm);
    for (unsigned int i = 0; i < dofs.get_space().n_basis(); ++i)
      if (owned.in_local_range(pair.dof_index(i, 0)))
        {
          owned[pair.dof_index(i, 0)] = phi[dofs.dof_index(i)];
          owned[pair.dof_index(i, 1)] = (*psi)[dofs.dof_index(i)];
        }
    owned.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector ghosted(pair.locally_owned_dofs(),
                                          pair.locally_relevant_dofs(),
                                          comm);
    ghosted = owned;
    SplineFieldWriter<dim> writer(pair, nullptr);
    writer.add_components({"phi", "psi"});
    writer.add_quantity(
      "grad_psi_norm",
      [](const SplineCellValues<dim>            &v,
         const unsigned int                      q,
         const std::vector<std::vector<double>> &c) {
        return v.gradient(c[1], q).norm();
      },
      1);
    writer.add_quantity("sigma",
                        [&material](const SplineCellValues<dim>            &v,
                                    const unsigned int                      q,
                                    const std::vector<std::vector<double>> &c) {
                          return material.conductivity(v.value(c[0], q));
                        });
    writer.write(ghosted, directory, basename);
  }


  template <int dim>
  void
  write_axis_profiles(const SplineSpace<dim>         &space,
                      const std::vector<double>      &phi,
                      const std::vector<double>      *psi,
                      const ElectromechanicsMaterial &material,
                      const Point<dim>               &center,
                      const std::string              &filename)
  {
    std::ofstream out(filename);
    out << "axis,s,phi,sigma" << (psi ? ",psi,grad_psi_norm" : "") << '\n'
        << std::setprecision(10);
    std::vector<double> value, grad_plus, grad_minus;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const auto        &z = space.knot_vector(d).breakpoints();
        const unsigned int n = 50 * space.knot_vector(d).n_elements();
        for (unsigned int i = 0; i <= n; ++i)
          {
            Point<dim> x = center;
            x[d]         = z.front() + (z.back() - z.front()) * i / n;
            space.evaluate(phi, 1, x, value);
            out << "xyz"[d] << ',' << x[d] << ',' << value[0] << ','
                << material.conductivity(value[0]);
            if (psi)
              {
                space.evaluate(*psi, 1, x, value);
                // |grad psi| by central differences of the spline (1e-6
                // of the element size; the spline is C^2).
                Tensor<1, dim> g;
                for (unsigned int k = 0; k < dim; ++k)
                  {
                    const double h
                      = 1e-6
                        * (space.knot_vector(k).breakpoints().back()
                           - space.knot_vector(k).breakpoints().front())
                        / space.knot_vector(k).n_elements();
                    Point<dim> xp = x, xm = x;
                    xp[k] = std::min(x[k] + h,
                                     space.knot_vector(k).breakpoints().back());
                    xm[k]
                      = std::max(x[k] - h,
                                 space.knot_vector(k).breakpoints().front());
                    space.evaluate(*psi, 1, xp, grad_plus);
                    space.evaluate(*psi, 1, xm, grad_minus);
                    g[k] = (grad_plus[0] - grad_minus[0]) / (xp[k] - xm[k]);
                  }
                out << ',' << value[0] << ',' << g.norm();
              }
            out << '\n';
          }
      }
    check_written(out, filename);
  }


  template <int dim>
  void
  write_plane_section(const SplineSpace<dim>    &space,
                      const std::vector<double> &phi,
                      const Point<dim>          &center,
                      const unsigned int         first_axis,
                      const unsigned int         second_axis,
                      const std::string         &filename)
  {
    std::ofstream out(filename);
    out << "xyz"[first_axis] << ',' << "xyz"[second_axis] << ",phi\n"
        << std::setprecision(8);
    const auto         &za = space.knot_vector(first_axis).breakpoints();
    const auto         &zb = space.knot_vector(second_axis).breakpoints();
    const unsigned int  na = 4 * space.knot_vector(first_axis).n_elements();
    const unsigned int  nb = 4 * space.knot_vector(second_axis).n_elements();
    std::vector<double> value;
    for (unsigned int j = 0; j <= nb; ++j)
      for (unsigned int i = 0; i <= na; ++i)
        {
          Point<dim> x   = center;
          x[first_axis]  = za.front() + (za.back() - za.front()) * i / na;
          x[second_axis] = zb.front() + (zb.back() - zb.front()) * j / nb;
          space.evaluate(phi, 1, x, value);
          out << x[first_axis] << ',' << x[second_axis] << ',' << value[0]
              << '\n';
        }
    check_written(out, filename);
  }

  template void
  write_vesicle_vtu(const SplineDofHandler<2> &,
                    const TrilinosWrappers::MPI::Vector &,
                    const TrilinosWrappers::MPI::Vector *,
                    const ElectromechanicsMaterial &,
                    const std::string &,
                    const std::string &);
  template void
  write_vesicle_vtu(const SplineDofHandler<3> &,
                    const TrilinosWrappers::MPI::Vector &,
                    const TrilinosWrappers::MPI::Vector *,
                    const ElectromechanicsMaterial &,
                    const std::string &,
                    const std::string &);
  template void
  write_axis_profiles(const SplineSpace<2> &,
                      const std::vector<double> &,
                      const std::vector<double> *,
                      const ElectromechanicsMaterial &,
                      const Point<2> &,
                      const std::string &);
  template void
  write_axis_profiles(const SplineSpace<3> &,
                      const std::vector<double> &,
                      const std::vector<double> *,
                      const ElectromechanicsMaterial &,
                      const Point<3> &,
                      const std::string &);
  template void
  write_plane_section(const SplineSpace<2> &,
                      const std::vector<double> &,
                      const Point<2> &,
                      unsigned int,
                      unsigned int,
                      const std::string &);
  template void
  write_plane_section(const SplineSpace<3> &,
                      const std::vector<double> &,
                      const Point<3> &,
                      unsigned int,
                      unsigned int,
                      const std::string &);
} // namespace vesicle_iga
