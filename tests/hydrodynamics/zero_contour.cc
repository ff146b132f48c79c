// The membrane samples of spec 4.12 (tension-<step>.csv) come from
// zero_contours(): marching squares on the spline with the crossings placed
// on the spline's own zero set. Checked against exact geometry, on a cubic
// C^2 space of 32^2 elements on [0, 2]^2 (h = 1/16) with three components:
//  - a circle of radius R = 0.5 as the tanh profile of (H0) with eps = 2 h,
//    interpolated at the Greville points: one closed piece, every point
//    within 1e-3 of the circle (the interpolation error of the profile
//    moves the zero set by less than that), length 2 pi R within 1e-3
//    (the chords of 4 samples per element are h / 4 long: relative error
//    (h/4)^2 / (24 R^2) = 4e-5), counter-clockwise (signed area pi R^2
//    within 1e-3; reduced area 4 pi A / L^2 = 1 within 2e-3, twice the
//    length's error bound), starting at the rightmost point (R, 0) from the
//    centre, the length closer to 2 pi R with 8 samples per element than with
//    4, and every point on the spline's zero set (|phi| < 1e-10 there: the
//    crossings are not those of a linear interpolant);
//  - a linear function g = 2x - y + 0.5, reproduced exactly by the
//    interpolant: the values reported at the contour points equal g there
//    to 1e-10 (the values come from the spline at the points found);
//  - two circles (max of two profiles, centres (0.55, 0.55) and (1.45, 1.45),
//    symmetric under (x, y) -> (2 - x, 2 - y)) give two closed pieces of equal
//    length, and the straight level set y = 1.3 one open piece from x = 0 to
//    x = 2 of length 2 (to 1e-12: the field is linear).

#include <vesicle_iga/postprocess/zero_contour.h>

#include <cmath>
#include <fstream>
#include <iostream>

#include "vesicle_flow_setup.h"

using namespace vesicle_iga;
using namespace dealii;

namespace
{
  double
  profile(const Point<2> &x, const Point<2> &centre)
  {
    const double eps = 0.125;
    return std::tanh((0.5 - x.distance(centre)) / (std::sqrt(2.) * eps));
  }
} // namespace

int
main()
{
  std::ofstream        out("output");
  const SplineSpace<2> space(cubic_box_knots(32, 0., 2.));
  const Point<2>       centre(1., 1.);
  const double         R = 0.5;

  // Components: circle, g, two circles, straight line.
  const unsigned int  nc = 4;
  std::vector<double> at_greville;
  for (unsigned int i = 0; i < space.n_basis(); ++i)
    {
      const Point<2> x = space.greville_point(i);
      at_greville.insert(at_greville.end(),
                         {profile(x, centre),
                          2 * x[0] - x[1] + 0.5,
                          std::max(profile(x, {0.55, 0.55}),
                                   profile(x, {1.45, 1.45})),
                          x[1] - 1.3});
    }
  const std::vector<double> natural
    = interpolate_at_greville_points(space, at_greville, nc);


  const auto circle       = zero_contours(space, natural, nc, 0, 4);
  double     worst_radius = 0, worst_g = 0, worst_phi = 0;
  for (unsigned int k = 0; k < circle[0].points.size(); ++k)
    {
      const Point<2> &p = circle[0].points[k];
      worst_radius = std::max(worst_radius, std::abs(p.distance(centre) - R));
      worst_phi    = std::max(worst_phi, std::abs(circle[0].values[k][0]));
      worst_g
        = std::max(worst_g,
                   std::abs(circle[0].values[k][1] - (2 * p[0] - p[1] + 0.5)));
    }
  const double area = circle[0].enclosed_area();
  const double length_error_4
    = std::abs(circle[0].length() / (2 * M_PI * R) - 1);
  const auto   fine           = zero_contours(space, natural, nc, 0, 8);
  const double length_error_8 = std::abs(fine[0].length() / (2 * M_PI * R) - 1);
  const Point<2> start        = circle[0].points.front();

  out << "circle: one closed piece: "
      << verdict(circle.size() == 1 && circle[0].closed
                 && circle[0].points.front() == circle[0].points.back())
      << "\ncircle: points within 1e-3 of the circle: "
      << verdict(worst_radius < 1e-3) << "\ncircle: length 2 pi R within 1e-3: "
      << verdict(length_error_4 < 1e-3)
      << "\ncircle: counter-clockwise, area pi R^2 within 1e-3: "
      << verdict(std::abs(area / (M_PI * R * R) - 1) < 1e-3)
      << "\ncircle: reduced area 4 pi A / L^2 within 2e-3 of 1: "
      << verdict(std::abs(circle[0].reduced_area() - 1) < 2e-3)
      << "\ncircle: starts at the rightmost point: "
      << verdict(start.distance({1.5, 1.}) < 1e-3)
      << "\ncircle: length closer to 2 pi R with 8 samples than with 4: "
      << verdict(length_error_8 < length_error_4)
      << "\ncircle: points on the spline's zero set (|phi| < 1e-10): "
      << verdict(worst_phi < 1e-10)
      << "\nvalues at the points are the spline's (linear g to 1e-10): "
      << verdict(worst_g < 1e-10);

  const auto two = zero_contours(space, natural, nc, 2, 4);
  out << "\ntwo circles: two closed pieces of equal length: "
      << verdict(two.size() == 2 && two[0].closed && two[1].closed
                 && std::abs(two[0].length() - two[1].length()) < 1e-6);

  const auto line = zero_contours(space, natural, nc, 3, 4);
  out << "\nstraight line y = 1.3: one open piece of length 2: "
      << verdict(line.size() == 1 && !line[0].closed
                 && std::abs(line[0].length() - 2) < 1e-12)
      << "\nstraight line: no enclosed area, reduced area 0: "
      << verdict(line[0].enclosed_area() == 0 && line[0].reduced_area() == 0)
      << '\n';

  std::cout << "radius error " << worst_radius << ", |phi| " << worst_phi
            << ", length error (4 / 8 "
            << "samples) " << length_error_4 << " / " << length_error_8
            << ", area " << area / (M_PI * R * R) - 1 << ", g error " << worst_g
            << ", start " << start << ", two circles " << two.size() << " "
            << (two.size() == 2 ? two[0].length() - two[1].length() : 0.)
            << ", line " << line.size() << " " << line[0].length() - 2
            << std::endl;
}
