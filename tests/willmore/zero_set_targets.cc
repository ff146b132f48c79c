// `Constraint targets = zero level set` (ZeroSetTargetControl; issue 16,
// item 1; doc/validation.md 1d) against the spec's diffuse constraints, on
// a 2D ellipse whose semi-minor axis is only four interface widths thick
// (semi-axes 1.0 x 0.4, eps = 2h = 0.1, cubic C^2, 40 adaptive steps).
//
// Checked against theory: the initial zero level set is the ellipse, whose
// length (the complete elliptic integral, by Simpson's rule here) and
// enclosed area pi a b are the references. The first step relaxes the
// initial tanh profile and moves the zero contour's area by 1.8e-3 with
// either option (the control corrects the targets after a step, so it
// lags by one). Over the last 10 of the 40 steps, holding the zero level
// set's own measures keeps both within 4e-4 of the ellipse's (measured:
// 3.8e-5 and 2.0e-4, the ALM tolerance 1e-4 on the diffuse constraints
// plus the change of the diffuse-sharp difference over a step); holding
// the diffuse (E9) as the spec does leaves the enclosed area more than
// 2e-3 off (measured: 3.3e-3; the length 8.7e-4). Both runs are gradient flows
// within the ALM tolerance (relaxation_checks.h). Checked to fail with the
// correction's sign reversed (target = reference - (diffuse - sharp)).
// Same outcome on 1 and 2 ranks (the sharp measures are gathered on rank 0
// and the targets broadcast with them).

#include <algorithm>
#include <cmath>

#include "../root_output.h"
#include "relaxation_checks.h"

namespace
{
  /// Length of the ellipse with semi-axes a >= b: 4 a E(e), E the complete
  /// elliptic integral of the second kind, by composite Simpson's rule (the
  /// integrand is smooth and periodic: 2000 intervals give 1e-15).
  double
  ellipse_length(const double a, const double b)
  {
    const double       e2 = 1 - b * b / (a * a);
    const unsigned int n  = 2000;
    const double       h  = M_PI / 2 / n;
    double             s  = 0;
    for (unsigned int i = 0; i <= n; ++i)
      {
        const double t = i * h;
        const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        s += w * std::sqrt(1 - e2 * std::sin(t) * std::sin(t));
      }
    return 4 * a * s * h / 3;
  }

  /// Largest relative deviation of the zero contour's length and enclosed
  /// area from the ellipse's over the last 10 accepted steps.
  std::pair<double, double>
  sharp_drift(const NamedTimeSeries &series, const double L, const double A)
  {
    double             dl = 0, da = 0;
    const unsigned int n = series.rows.size();
    for (unsigned int i = n < 10 ? 0 : n - 10; i < n; ++i)
      {
        dl = std::max(dl, std::abs(series.value("contour_length", i) / L - 1));
        da = std::max(da, std::abs(series.value("contour_area", i) / A - 1));
      }
    return {dl, da};
  }
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                            out = root_output();
  const double                             a = 1.0, b = 0.4;
  const double L = ellipse_length(a, b), A = M_PI * a * b;
  for (const std::string targets : {"zero level set", "diffuse"})
    {
      const std::string dir = targets == "diffuse" ? "diffuse" : "zero";
      const StudyRun    run = run_study(
        "set Study = willmore-flow\nset Dimension = 2\n"
           "set Output directory = "
        + dir
        + "\nset Print details = false\n"
             "subsection Willmore flow\nset Initial shape = ellipsoid\n"
             "set Center = 0\nset Semi-axes = 1.0, 0.4\n"
             "set Constraint targets = "
        + targets
        + "\nsubsection Mesh\nset Lower corner = -1.4, -0.8\n"
             "set Upper corner = 1.4, 0.8\nset Elements = 56, 32\nend\n"
             "subsection Time stepping\nset Max steps = 40\n"
             "set Initial dt = 1e-4\nend\nend\n");
      const auto series = read_named_time_series(dir + "/time-series.csv");
      out << "Constraint targets = " << targets << ":\n";
      check_gradient_flow(out, run, series, 40);
      const auto [dl, da] = sharp_drift(series, L, A);
      if (targets == "diffuse")
        out << "over the last 10 steps the zero contour's enclosed area is "
               "more than 2e-3 off pi a b: "
            << (da > 2e-3 ? "yes" : "NO") << '\n';
      else
        out << "over the last 10 steps the zero contour's length and "
               "enclosed area are within 4e-4 of the ellipse's: "
            << (dl < 4e-4 && da < 4e-4 ? "yes" : "NO") << '\n';
    }
}
