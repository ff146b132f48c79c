#include <vesicle_iga/postprocess/level_set_extent.h>

namespace vesicle_iga
{
  using namespace dealii;

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
    const auto         &z = space.knot_vector(d).breakpoints();
    const double        a = z.front(), b = z.back();
    const unsigned int  n = 20 * space.knot_vector(d).n_elements();
    std::vector<double> crossings;
    double              s0 = a, f0 = phi_at(a);
    for (unsigned int i = 1; i <= n; ++i)
      {
        const double s1 = a + (b - a) * i / n, f1 = phi_at(s1);
        if ((f0 < 0) != (f1 < 0))
          {
            double lo = s0, hi = s1, flo = f0;
            for (unsigned int k = 0; k < 50; ++k)
              {
                const double m = 0.5 * (lo + hi), fm = phi_at(m);
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
} // namespace vesicle_iga
