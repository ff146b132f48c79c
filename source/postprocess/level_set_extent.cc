#include <deal.II/base/mpi.h>

#include <vesicle_iga/postprocess/level_set_extent.h>

#include <algorithm>
#include <limits>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    /**
     * Where the restriction @p f of the level-set function to a line
     * changes sign in [@p a, @p b]: each of @p n equal intervals whose end
     * values differ in sign is bisected 50 times. Shared by the global
     * search along an axis and the search within one element.
     */
    template <typename Function>
    std::vector<double>
    sign_changes(const Function    &f,
                 const double       a,
                 const double       b,
                 const unsigned int n)
    {
      std::vector<double> crossings;
      double              s0 = a, f0 = f(a);
      for (unsigned int i = 1; i <= n; ++i)
        {
          const double s1 = i == n ? b : a + (b - a) * i / n, f1 = f(s1);
          if ((f0 < 0) != (f1 < 0))
            {
              double lo = s0, hi = s1, flo = f0;
              for (unsigned int k = 0; k < 50; ++k)
                {
                  const double m = 0.5 * (lo + hi), fm = f(m);
                  if ((fm < 0) == (flo < 0))
                    {
                      lo  = m;
                      flo = fm;
                    }
                  else
                    hi = m;
                }
              crossings.push_back(0.5 * (lo + hi));
            }
          s0 = s1;
          f0 = f1;
        }
      return crossings;
    }
  } // namespace

  template <int dim>
  std::vector<double>
  zero_crossings_along_axis(const SplineSpace<dim>    &space,
                            const std::vector<double> &c,
                            const dealii::Point<dim>  &through,
                            const unsigned int         d)
  {
    std::vector<double> value;
    const auto          phi_at = [&](const double s) {
      dealii::Point<dim> x = through;
      x[d]                 = s;
      space.evaluate(c, 1, x, value);
      return value[0];
    };
    const auto &z = space.knot_vector(d).breakpoints();
    return sign_changes(phi_at,
                        z.front(),
                        z.back(),
                        20 * space.knot_vector(d).n_elements());
  }


  template <int dim>
  double
  zero_level_set_extent(const SplineSpace<dim>    &space,
                        const std::vector<double> &c,
                        const dealii::Point<dim>  &through,
                        const unsigned int         d)
  {
    const auto x = zero_crossings_along_axis(space, c, through, d);
    return x.size() >= 2 ? x.back() - x.front() : 0.;
  }

  template <int dim>
  std::vector<double>
  zero_crossing_bounds(const SplineDofHandler<dim>         &dofs,
                       const TrilinosWrappers::MPI::Vector &ghosted,
                       const unsigned int                   component,
                       const dealii::Point<dim>            &through,
                       const unsigned int                   d)
  {
    const SplineSpace<dim>          &space = dofs.get_space();
    double                           first = std::numeric_limits<double>::max();
    double                           last  = -first;
    std::vector<std::vector<double>> c;
    for (const unsigned int e : dofs.get_mesh().locally_owned_elements())
      {
        // The elements whose closure the line crosses: on a breakpoint both
        // neighbours search, which can only repeat a crossing.
        const auto lower   = space.element_lower_corner(e);
        const auto length  = space.element_lengths(e);
        bool       on_line = true;
        for (unsigned int o = 0; o < dim; ++o)
          if (o != d)
            on_line = on_line && through[o] >= lower[o]
                      && through[o] <= lower[o] + length[o];
        if (!on_line)
          continue;
        get_element_coefficients(dofs, ghosted, e, c);
        const auto phi_at = [&](const double s) {
          dealii::Point<dim> x = through;
          x[d]                 = s;
          return space.evaluate_on_element(e, c[component], x);
        };
        // The 20 samples per element of the global
        // zero_crossings_along_axis(), within this element.
        for (const double x :
             sign_changes(phi_at, lower[d], lower[d] + length[d], 20))
          {
            first = std::min(first, x);
            last  = std::max(last, x);
          }
      }
    const MPI_Comm comm = dofs.get_mesh().get_communicator();
    first               = Utilities::MPI::min(first, comm);
    last                = Utilities::MPI::max(last, comm);
    // One crossing found twice (from both sides of a breakpoint) is one.
    const auto  &z    = space.knot_vector(d).breakpoints();
    const double span = z.back() - z.front();
    if (!(last - first > 1e-12 * span))
      return {};
    return {first, last};
  }


  template std::vector<double>
  zero_crossings_along_axis(const SplineSpace<2> &,
                            const std::vector<double> &,
                            const dealii::Point<2> &,
                            const unsigned int);
  template std::vector<double>
  zero_crossings_along_axis(const SplineSpace<3> &,
                            const std::vector<double> &,
                            const dealii::Point<3> &,
                            const unsigned int);
  template double
  zero_level_set_extent(const SplineSpace<2> &,
                        const std::vector<double> &,
                        const dealii::Point<2> &,
                        const unsigned int);
  template double
  zero_level_set_extent(const SplineSpace<3> &,
                        const std::vector<double> &,
                        const dealii::Point<3> &,
                        const unsigned int);
  template std::vector<double>
  zero_crossing_bounds(const SplineDofHandler<2> &,
                       const TrilinosWrappers::MPI::Vector &,
                       unsigned int,
                       const dealii::Point<2> &,
                       unsigned int);
  template std::vector<double>
  zero_crossing_bounds(const SplineDofHandler<3> &,
                       const TrilinosWrappers::MPI::Vector &,
                       unsigned int,
                       const dealii::Point<3> &,
                       unsigned int);
} // namespace vesicle_iga
