#include <deal.II/base/mpi.h>

#include <vesicle_iga/postprocess/crossing_tolerance.h>

#include <algorithm>
#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    double
    tolerance_for_range(const double range)
    {
      return 1e-12 * std::max(range, 1e-300);
    }
  } // namespace


  double
  crossing_tolerance(const std::vector<double> &natural,
                     const unsigned int         n_components,
                     const unsigned int         component)
  {
    double range = 0;
    for (unsigned int i = component; i < natural.size(); i += n_components)
      range = std::max(range, std::abs(natural[i]));
    return tolerance_for_range(range);
  }


  template <int dim>
  double
  crossing_tolerance(const SplineDofHandler<dim>         &dofs,
                     const TrilinosWrappers::MPI::Vector &ghosted,
                     const unsigned int                   component)
  {
    std::vector<std::vector<double>> c;
    double                           range = 0;
    for (const unsigned int e : dofs.get_mesh().locally_owned_elements())
      {
        get_element_coefficients(dofs, ghosted, e, c);
        for (const double v : c[component])
          range = std::max(range, std::abs(v));
      }
    return tolerance_for_range(
      Utilities::MPI::max(range, dofs.get_mesh().get_communicator()));
  }


  template double
  crossing_tolerance(const SplineDofHandler<2> &,
                     const TrilinosWrappers::MPI::Vector &,
                     unsigned int);
  template double
  crossing_tolerance(const SplineDofHandler<3> &,
                     const TrilinosWrappers::MPI::Vector &,
                     unsigned int);
} // namespace vesicle_iga
