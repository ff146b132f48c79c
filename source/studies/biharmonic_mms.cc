// Study "biharmonic-mms": Delta^2 u = f in primal H^2 form on C^1 and
// smoother splines, clamped (u, du/dn given) or simply supported (u and
// Delta u given) edges, manufactured solution u = prod sin(k_d x_d + phi_d).
// Theory for degree p >= 2 (C^{p-1}): |e|_H2 = O(h^{p-1}),
// |e|_H1 = O(h^p), ||e||_L2 = O(h^{min(p+1, 2p-2)}) (Aubin-Nitsche in H^2:
// the L2 rate gains p-1 over H2, so p = 2 gives 2, not 3).

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <vesicle_iga/fields/dirichlet_constraints.h>
#include <vesicle_iga/io/spline_output.h>
#include <vesicle_iga/models/stationary_problem.h>
#include <vesicle_iga/postprocess/field_integrals.h>
#include <vesicle_iga/postprocess/manufactured_solution.h>
#include <vesicle_iga/spline/box_space_parameters.h>
#include <vesicle_iga/studies/convergence_parameters.h>
#include <vesicle_iga/studies/convergence_study.h>
#include <vesicle_iga/studies/study.h>
#include <vesicle_iga/terms/biharmonic.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    const char *section = "Biharmonic MMS";

    template <int dim>
    class BiharmonicMMS : public Study
    {
    public:
      BiharmonicMMS(ParameterHandler &prm, RunContext &context);
      void
      run() override;

    private:
      RunContext            &context;
      BoxSpaceParameters     box;
      ConvergenceParameters  convergence;
      LinearSolverParameters solver;
      std::string            boundary_condition;
    };


    template <int dim>
    BiharmonicMMS<dim>::BiharmonicMMS(ParameterHandler &prm,
                                      RunContext       &context)
      : context(context)
    {
      prm.enter_subsection(section);
      box.parse(prm, dim, section);
      convergence.parse(prm, 1);
      solver.parse(prm);
      boundary_condition = prm.get("Boundary condition");
      prm.leave_subsection();
      // Build every coarse space once, so that an invalid mesh is reported
      // before any work is done.
      for (const unsigned int p : convergence.degrees)
        box.make_space<dim>(p, convergence.continuity);
    }


    template <int dim>
    void
    BiharmonicMMS<dim>::run()
    {
      std::array<double, dim> k, phase;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double L = box.upper[d] - box.lower[d];
          k[d]           = 1.3 * M_PI / L;
          phase[d]       = 0.4 + 0.3 * d - k[d] * box.lower[d];
        }
      const ProductSineSolution<dim>              exact(k, phase);
      const ScalarFunctionFromFunctionObject<dim> f(
        [&](const Point<dim> &x) { return exact.bilaplacian(x); });
      const ScalarFunctionFromFunctionObject<dim> laplacian(
        [&](const Point<dim> &x) { return exact.laplacian(x); });
      const BoundarySelection<dim> all("all", "Boundary condition");
      const bool                   clamped = (boundary_condition == "clamped");

      const auto   timer_owner = context.make_timer();
      TimerOutput &timer       = *timer_owner;
      run_convergence_study(
        context,
        dim,
        convergence,
        {"L2", "H1", "H2"},
        [&](const unsigned int p, const unsigned int r) {
          const SplineSpace<dim> space
            = box.make_space<dim>(p, convergence.continuity).h_refined(r);
          StationaryProblem<dim> problem(context.communicator,
                                         space,
                                         nullptr,
                                         1);
          if (clamped)
            {
              const auto dudn
                = [&](const Point<dim> &x, const Tensor<1, dim> &n) {
                    return exact.gradient(x) * n;
                  };
              add_clamped_constraints<dim>(
                problem.dofs(), all, exact, dudn, problem.constraints());
            }
          else
            add_strong_dirichlet_constraints<dim>(problem.dofs(),
                                                  nullptr,
                                                  all,
                                                  exact,
                                                  {true},
                                                  problem.constraints());
          BiharmonicTerm<dim>        bilaplace(0, f);
          BoundaryLaplacianTerm<dim> moment(
            0, clamped ? BoundarySelection<dim>() : all, laplacian);
          const auto result
            = problem.solve({&bilaplace, &moment},
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
                "laplacian_u",
                [](const SplineCellValues<dim>            &v,
                   const unsigned int                      q,
                   const std::vector<std::vector<double>> &c) {
                  return trace(v.hessian(c[0], q));
                },
                2);
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
              2,
              problem.solution()),
            result};
        });
    }
  } // namespace


  StudyDescription
  biharmonic_mms_description()
  {
    return {
      "biharmonic-mms",
      "Biharmonic equation in primal H^2 form on C^1+ splines with a "
      "manufactured solution: L2, H1 and H2 error rates, clamped or simply "
      "supported edges.",
      [](ParameterHandler &prm) {
        prm.enter_subsection(section);
        BoxSpaceParameters::declare(prm, "0", "1", "4");
        ConvergenceParameters::declare(prm, "2,3,4,5", "4");
        LinearSolverParameters::declare(prm, "direct");
        prm.declare_entry("Boundary condition",
                          "clamped",
                          Patterns::Selection("clamped|simply-supported"),
                          "clamped: u and du/dn prescribed (two layers of "
                          "coefficients); simply-supported: u prescribed "
                          "strongly, Delta u naturally.");
        prm.leave_subsection();
      },
      [](ParameterHandler &prm, RunContext &context) -> std::unique_ptr<Study> {
        if (context.dimension == 2)
          return std::make_unique<BiharmonicMMS<2>>(prm, context);
        return std::make_unique<BiharmonicMMS<3>>(prm, context);
      }};
  }
} // namespace vesicle_iga
