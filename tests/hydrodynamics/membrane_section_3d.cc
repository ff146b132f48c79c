// The 3D membrane samples (tension-<step>.csv of a 3D run) come from
// section_at_z(): the plane section z = z_0 of a trivariate spline is the
// bivariate spline with coefficients sum_k c_ijk N_k(z_0), on which
// zero_contours() runs. Checked against exact geometry on a cubic C^2 space
// of 16^3 elements on [0, 2]^3 (h = 1/8), periodic in z (the seam far from
// the sphere, as in the periodic shear studies), with two components:
//  - a sphere of radius R = 0.6 about (1, 1, 1) as the tanh profile of (H0)
//    with eps = 2 h, interpolated at the Greville points; the section at
//    z_0 = 1.2 is one closed circle of radius r = sqrt(R^2 - 0.2^2) =
//    0.5657: every point within 2e-3 of it (the interpolation error of the
//    profile; measured 6.9e-5), its length 2 pi r within 2e-3 (measured
//    1.7e-4), counter-clockwise (enclosed area pi r^2 within 2e-3,
//    measured 5.6e-4);
//  - exactness of the section itself: at every contour point the 3D
//    spline, evaluated directly at (x, y, z_0) by Cox-de Boor, vanishes to
//    1e-10 (the points lie on the 3D zero set; measured 7e-13), and the second
//    component (the interpolant of g = x + 2y + sin(pi z), standing for
//    lambda_i or p) reported with the point equals the 3D spline there to
//    1e-12;
//  - a section through the seam (z_0 = 0) misses the sphere: no piece;
//  - the periodic direction has no ends: z_0 + 2 (one period) gives the
//    coefficients of the section at z_0 to 1e-13 (z_0 + 2 - 2 is not z_0
//    to the last bit in binary).

#include <vesicle_iga/postprocess/spline_section.h>
#include <vesicle_iga/postprocess/zero_contour.h>

#include <cmath>
#include <fstream>
#include <iostream>

#include "../root_output.h"

using namespace vesicle_iga;
using namespace dealii;

namespace
{
  double
  max_difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    double worst = a.size() == b.size() ? 0. : 1e300;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
      worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
  }
} // namespace

int
main()
{
  std::ofstream        out("output");
  const SplineSpace<3> space(
    std::array<KnotVector, 3>{{KnotVector::uniform(3, 16, 0., 2.),
                               KnotVector::uniform(3, 16, 0., 2.),
                               KnotVector::uniform(3, 16, 0., 2., -1, true)}});
  const Point<3> centre(1., 1., 1.);
  const double   R = 0.6, eps = 0.25, z0 = 1.2;
  const double   r = std::sqrt(R * R - (z0 - 1.) * (z0 - 1.));

  const unsigned int  nc = 2;
  std::vector<double> at_greville;
  for (unsigned int i = 0; i < space.n_basis(); ++i)
    {
      const Point<3> x = space.greville_point(i);
      at_greville.insert(at_greville.end(),
                         {std::tanh((R - x.distance(centre))
                                    / (std::sqrt(2.) * eps)),
                          x[0] + 2 * x[1] + std::sin(M_PI * x[2])});
    }
  const std::vector<double> natural
    = interpolate_at_greville_points(space, at_greville, nc);

  const auto section  = section_at_z(space, natural, nc, z0);
  const auto contours = zero_contours(section.space, section.natural, nc, 0);
  double     worst_radius = 0, worst_phi = 0, worst_g = 0;
  std::vector<double> values;
  for (unsigned int k = 0; k < contours.at(0).points.size(); ++k)
    {
      const Point<2> &p = contours[0].points[k];
      const Point<2>  axis(1., 1.);
      worst_radius = std::max(worst_radius, std::abs(p.distance(axis) - r));
      space.evaluate(natural, nc, Point<3>(p[0], p[1], z0), values);
      worst_phi = std::max(worst_phi, std::abs(values[0]));
      worst_g
        = std::max(worst_g, std::abs(values[1] - contours[0].values[k][1]));
    }
  const double length_error
    = std::abs(contours[0].length() / (2 * M_PI * r) - 1);
  const double area_error
    = std::abs(contours[0].enclosed_area() / (M_PI * r * r) - 1);
  const auto at_seam    = section_at_z(space, natural, nc, 0.);
  const auto one_period = section_at_z(space, natural, nc, z0 + 2.);

  out << "section z = 1.2: one closed piece: "
      << verdict(contours.size() == 1 && contours[0].closed)
      << "\nsection z = 1.2: points within 2e-3 of the circle of radius "
         "sqrt(R^2 - 0.04): "
      << verdict(worst_radius < 2e-3)
      << "\nsection z = 1.2: length 2 pi r within 2e-3: "
      << verdict(length_error < 2e-3)
      << "\nsection z = 1.2: counter-clockwise, area pi r^2 within 2e-3: "
      << verdict(area_error < 2e-3)
      << "\nthe points lie on the 3D zero set (|phi(x, y, z_0)| < 1e-10): "
      << verdict(worst_phi < 1e-10)
      << "\nthe values at the points are the 3D spline's (to 1e-12): "
      << verdict(worst_g < 1e-12) << "\nsection z = 0 (the seam): no piece: "
      << verdict(zero_contours(at_seam.space, at_seam.natural, nc, 0).empty())
      << "\nsection z = 3.2, one period on: the same coefficients: "
      << verdict(max_difference(one_period.natural, section.natural) < 1e-13)
      << '\n';
  std::cout << "radius error " << worst_radius << ", |phi| " << worst_phi
            << ", g error " << worst_g << ", length error " << length_error
            << ", area error " << area_error << ", one period "
            << max_difference(one_period.natural, section.natural) << std::endl;
}
