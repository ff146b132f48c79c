#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/spline/nurbs_geometry.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  NurbsGeometry<dim>::NurbsGeometry(const SplineSpace<dim>        &space,
                                    const std::vector<Point<dim>> &cp,
                                    const std::vector<double>     &w)
    : spline_space(space)
    , points(cp)
    , weights_(w)
  {
    check_input(cp.size() == space.n_basis() && w.size() == space.n_basis(),
                "NURBS control net",
                std::to_string(cp.size()) + " points, "
                  + std::to_string(w.size()) + " weights",
                "one control point and one weight per basis function ("
                  + std::to_string(space.n_basis()) + ")");
    for (const double wi : w)
      check_input(wi > 0, "NURBS weight", value_text(wi), "w > 0");
    homogeneous.resize(spline_space.n_basis() * (dim + 1));
    for (unsigned int i = 0; i < spline_space.n_basis(); ++i)
      {
        for (unsigned int d = 0; d < dim; ++d)
          homogeneous[i * (dim + 1) + d] = weights_[i] * points[i][d];
        homogeneous[i * (dim + 1) + dim] = weights_[i];
      }
  }


  template <int dim>
  Point<dim>
  NurbsGeometry<dim>::point(const Point<dim> &xi) const
  {
    std::vector<double> v;
    spline_space.evaluate(homogeneous, dim + 1, xi, v);
    Point<dim> x;
    for (unsigned int d = 0; d < dim; ++d)
      x[d] = v[d] / v[dim];
    return x;
  }


  template <int dim>
  NurbsGeometry<dim>
  NurbsGeometry<dim>::refined_to(const SplineSpace<dim> &finer) const
  {
    std::vector<double> values(finer.n_basis() * (dim + 1)), v;
    for (unsigned int i = 0; i < finer.n_basis(); ++i)
      {
        spline_space.evaluate(homogeneous, dim + 1, finer.greville_point(i), v);
        for (unsigned int c = 0; c <= dim; ++c)
          values[i * (dim + 1) + c] = v[c];
      }
    const auto c = interpolate_at_greville_points(finer, values, dim + 1);
    std::vector<Point<dim>> cp(finer.n_basis());
    std::vector<double>     w(finer.n_basis());
    for (unsigned int i = 0; i < finer.n_basis(); ++i)
      {
        w[i] = c[i * (dim + 1) + dim];
        for (unsigned int d = 0; d < dim; ++d)
          cp[i][d] = c[i * (dim + 1) + d] / w[i];
      }
    NurbsGeometry<dim> result(finer, cp, w);
    // A space that does not contain the old one would silently change the
    // geometry: compare both maps between the interpolation points.
    for (unsigned int e = 0; e < finer.n_elements(); ++e)
      {
        const Point<dim> xi
          = finer.element_lower_corner(e) + 0.37 * finer.element_lengths(e);
        const double err = (result.point(xi) - point(xi)).norm();
        AssertThrow(err < 1e-10 * (1 + point(xi).norm()),
                    ExcMessage("NurbsGeometry::refined_to: the target space "
                               "does not contain the geometry's space."));
      }
    return result;
  }

  template class NurbsGeometry<1>;
  template class NurbsGeometry<2>;
  template class NurbsGeometry<3>;
} // namespace vesicle_iga
