#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/physics/ellipsoid_distance.h>
#include <vesicle_iga/physics/vesicle_shape.h>

#include <algorithm>
#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  void
  VesicleShape<dim>::declare(ParameterHandler &prm)
  {
    prm.declare_entry("Initial shape",
                      "sphere",
                      Patterns::Selection("sphere|ellipsoid"),
                      "sphere (circle in 2D) or ellipsoid (spheroid, "
                      "ellipse) with the tanh profile (E1)/(E3) of the "
                      "exact signed distance.");
    prm.declare_entry("Center",
                      "0",
                      Patterns::Anything(),
                      "Centre of the initial shape: one coordinate per "
                      "direction, or one value for all.");
    prm.declare_entry("Semi-axes",
                      "1",
                      Patterns::Anything(),
                      "Radius, or one semi-axis per direction (length "
                      "unit, um in the normalised units of spec 3.10).");
  }


  template <int dim>
  void
  VesicleShape<dim>::parse(ParameterHandler &prm)
  {
    shape                    = prm.get("Initial shape");
    const std::string c_text = prm.get("Center");
    const auto        c      = parse_double_list(c_text, "Center");
    check_input(c.size() == 1 || c.size() == dim,
                "Center",
                c_text,
                "one value or " + std::to_string(dim) + " coordinates");
    for (unsigned int d = 0; d < dim; ++d)
      center[d] = c.size() == 1 ? c[0] : c[d];
    const std::string a_text = prm.get("Semi-axes");
    const auto        a      = parse_double_list(a_text, "Semi-axes");
    check_input(a.size() == 1 || a.size() == dim,
                "Semi-axes",
                a_text,
                "one value (sphere/circle) or one per direction");
    for (unsigned int d = 0; d < dim; ++d)
      {
        semi_axes[d] = a.size() == 1 ? a[0] : a[d];
        check_input(semi_axes[d] > 0, "Semi-axes", a_text, "positive values");
      }
    check_input(shape == "ellipsoid"
                  || *std::max_element(semi_axes.begin(), semi_axes.end())
                       == *std::min_element(semi_axes.begin(), semi_axes.end()),
                "Semi-axes",
                a_text,
                "equal semi-axes for 'Initial shape = sphere' (use "
                "ellipsoid for a spheroid or an ellipse)");
  }


  template <int dim>
  double
  VesicleShape<dim>::signed_distance(const Point<dim> &x) const
  {
    Point<dim> y;
    for (unsigned int d = 0; d < dim; ++d)
      y[d] = x[d] - center[d];
    return signed_distance_to_ellipsoid<dim>(y, semi_axes);
  }


  template <int dim>
  void
  VesicleShape<dim>::check_fits(const Point<dim>         &lower,
                                const Point<dim>         &upper,
                                const double              epsilon,
                                const ConditionalOStream &out) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double gap = std::min(center[d] - semi_axes[d] - lower[d],
                                    upper[d] - center[d] - semi_axes[d]);
        const double phi_boundary = std::tanh(gap / (std::sqrt(2.) * epsilon));
        check_input(phi_boundary >= 0.9,
                    "Semi-axes",
                    value_text(semi_axes[d]) + " (direction "
                      + std::string(1, "xyz"[d]) + ")",
                    "a shape that fits in the domain with a gap of at "
                    "least 2.08 epsilon = "
                      + value_text(2.08 * epsilon)
                      + " to every face, so that phi_0 >= 0.9 on the "
                        "boundary where (E15) sets phi = 1 (here phi_0 = "
                      + value_text(phi_boundary) + ")");
        if (phi_boundary < 0.999)
          out << "warning: the initial phase field is only " << phi_boundary
              << " on the faces normal to "
              << "xyz"[d] << " (gap " << gap << " = " << gap / epsilon
              << " epsilon); (E15) sets 1 there" << std::endl;
      }
  }


  template <int dim>
  std::vector<double>
  VesicleShape<dim>::phase_field(const SplineSpace<dim> &space,
                                 const double            epsilon) const
  {
    std::vector<double> values(space.n_basis());
    for (unsigned int i = 0; i < space.n_basis(); ++i)
      values[i] = std::tanh(signed_distance(space.greville_point(i))
                            / (std::sqrt(2.) * epsilon));
    return interpolate_at_greville_points(space, values, 1);
  }

  template struct VesicleShape<2>;
  template struct VesicleShape<3>;
} // namespace vesicle_iga
