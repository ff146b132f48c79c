// Study "poisson-mms": -Delta u = f on a box with the manufactured solution
// u = prod sin(k_d x_d + phi_d); strong (Greville) or weak (Nitsche)
// Dirichlet conditions, exact Neumann data elsewhere. Expected rates on
// C^{p-1} splines of degree p: L2 p+1, H1 p.

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/fields/dirichlet_constraints.h>
#include <vesicle_iga/io/spline_output.h>
#include <vesicle_iga/models/stationary_problem.h>
#include <vesicle_iga/postprocess/field_integrals.h>
#include <vesicle_iga/postprocess/manufactured_solution.h>
#include <vesicle_iga/spline/box_space_parameters.h>
#include <vesicle_iga/studies/convergence_parameters.h>
#include <vesicle_iga/studies/convergence_study.h>
#include <vesicle_iga/studies/study.h>
#include <vesicle_iga/terms/laplace.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    const char *section = "Poisson MMS";

    template <int dim>
    class PoissonMMS : public Study
    {
    public:
      PoissonMMS(ParameterHandler &prm, RunContext &context);
      void
      run() override;

    private:
      RunContext            &context;
      BoxSpaceParameters     box;
      ConvergenceParameters  convergence;
      LinearSolverParameters solver;
      std::string            strong_text, nitsche_text;
      double                 nitsche_constant;
    };


    template <int dim>
    PoissonMMS<dim>::PoissonMMS(ParameterHandler &prm, RunContext &context)
      : context(context)
    {
      prm.enter_subsection(section);
      box.parse(prm, dim, section);
      convergence.parse(prm, 0);
      solver.parse(prm);
      strong_text      = prm.get("Strong Dirichlet boundaries");
      nitsche_text     = prm.get("Nitsche boundaries");
      nitsche_constant = prm.get_double("Nitsche penalty");
      prm.leave_subsection();
      // Build every coarse space once, so that an invalid mesh is reported
      // before any work is done.
      for (const unsigned int p : convergence.degrees)
        box.make_space<dim>(p, convergence.continuity);
      // Parse once here, so that a malformed selection is reported before
      // any work is done.
      BoundarySelection<dim>(strong_text, "Strong Dirichlet boundaries");
      BoundarySelection<dim>(nitsche_text, "Nitsche boundaries");
    }


    template <int dim>
    void
    PoissonMMS<dim>::run()
    {
      std::array<double, dim> k, phase;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double L = box.upper[d] - box.lower[d];
          // One full period in a periodic direction, otherwise a generic
          // non-symmetric profile that is non-zero on the faces.
          k[d]     = box.periodic[d] ? 2 * M_PI / L : 1.3 * M_PI / L;
          phase[d] = box.periodic[d] ? -2 * M_PI * box.lower[d] / L + 0.4 :
                                       0.4 + 0.3 * d - k[d] * box.lower[d];
        }
      const ProductSineSolution<dim>              exact(k, phase);
      const ScalarFunctionFromFunctionObject<dim> f(
        [&](const Point<dim> &x) { return -exact.laplacian(x); });
      const BoundarySelection<dim> strong(strong_text,
                                          "Strong Dirichlet boundaries");
      const BoundarySelection<dim> nitsche(nitsche_text, "Nitsche boundaries");

      const auto   timer_owner = context.make_timer();
      TimerOutput &timer       = *timer_owner;
      run_convergence_study(
        context,
        dim,
        convergence,
        {"L2", "H1"},
        [&](const unsigned int p, const unsigned int r) {
          const SplineSpace<dim> space
            = box.make_space<dim>(p, convergence.continuity).h_refined(r);
          StationaryProblem<dim> problem(context.communicator,
                                         space,
                                         nullptr,
                                         1);
          add_strong_dirichlet_constraints<dim>(problem.dofs(),
                                                nullptr,
                                                strong,
                                                exact,
                                                {true},
                                                problem.constraints());
          const double penalty
            = nitsche_constant > 0 ? nitsche_constant : 5. * (p + 1);
          LaplaceTerm<dim>          laplace(0, f);
          NitscheDirichletTerm<dim> weak(0, nitsche, exact, penalty);
          NeumannTerm<dim>          neumann(
            0,
            [&](const unsigned int face, const Point<dim> &x) {
              return !strong.contains(face, x) && !nitsche.contains(face, x);
            },
            [&](const Point<dim> &x) { return exact.gradient(x); });
          const auto result
            = problem.solve({&laplace, &weak, &neumann},
                            QGauss<1>(p + 1
                                      + convergence.extra_quadrature_points),
                            solver,
                            &timer);
          if (convergence.write_vtu && r == convergence.refinements)
            {
              TimerOutput::Scope     t(timer, "output");
              SplineFieldWriter<dim> writer(problem.dofs(), nullptr);
              writer.add_components({"u"});
              writer.add_quantity(
                "error",
                [&](const SplineCellValues<dim>            &v,
                    const unsigned int                      q,
                    const std::vector<std::vector<double>> &c) {
                  return v.value(c[0], q) - exact.value(v.quadrature_point(q));
                });
              writer.write(problem.solution(),
                           context.output_directory,
                           "solution-p" + std::to_string(p));
            }
          return ConvergenceLevel{
            space.n_elements(),
            problem.dofs().n_dofs(),
            problem.mesh().max_cell_diameter(),
            scalar_error_norms<dim>(
              problem.dofs(),
              exact,
              QGauss<1>(p + 3 + convergence.extra_quadrature_points),
              1,
              problem.solution()),
            result};
        });
    }
  } // namespace


  StudyDescription
  poisson_mms_description()
  {
    return {
      "poisson-mms",
      "Poisson equation with a manufactured solution: L2 and H1 error rates "
      "of B-spline spaces, strong or Nitsche Dirichlet conditions.",
      [](ParameterHandler &prm) {
        prm.enter_subsection(section);
        BoxSpaceParameters::declare(prm, "0", "1", "4");
        ConvergenceParameters::declare(prm, "2,3,4,5", "4");
        LinearSolverParameters::declare(prm, "cg-amg");
        prm.declare_entry("Strong Dirichlet boundaries",
                          "all",
                          Patterns::Anything(),
                          "Boundary pieces where u = u_exact is imposed "
                          "strongly (Greville interpolation of the trace): "
                          "'all', 'none' or e.g. 'x-min; y-max{x:0:0.5}'.");
        prm.declare_entry("Nitsche boundaries",
                          "none",
                          Patterns::Anything(),
                          "Boundary pieces where u = u_exact is imposed "
                          "weakly by Nitsche's method (same syntax). The "
                          "rest of the boundary gets the exact flux.");
        prm.declare_entry("Nitsche penalty",
                          "-1",
                          Patterns::Double(),
                          "Constant C of the Nitsche penalty C/h_n; <= 0 "
                          "means C = 5(p+1).");
        prm.leave_subsection();
      },
      [](ParameterHandler &prm, RunContext &context) -> std::unique_ptr<Study> {
        if (context.dimension == 2)
          return std::make_unique<PoissonMMS<2>>(prm, context);
        return std::make_unique<PoissonMMS<3>>(prm, context);
      }};
  }
} // namespace vesicle_iga
