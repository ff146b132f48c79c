// Study "plate-with-hole" (spec Part P, example PL1): plane-stress
// elasticity of the upper-left quarter of an 8x8 plate with a hole of
// radius 1 (P1), exact NURBS geometry (P2) with the corrected hole weight
// w* = (1 + 1/sqrt 2)/2 (spec section 7, item 48), symmetry conditions on
// the normal displacement component (item 50), exact Kirsch tractions (P3)
// on the outer edges (item 49), T_x = 10. Degree elevation of the coarse
// geometry keeps C^1 at xi = 1/2, then h-refinement inserts C^{p-1} knots.
// Expected: energy-norm and stress-L2 errors O(h^p).

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/fields/dirichlet_constraints.h>
#include <vesicle_iga/io/spline_output.h>
#include <vesicle_iga/models/stationary_problem.h>
#include <vesicle_iga/postprocess/field_integrals.h>
#include <vesicle_iga/studies/convergence_parameters.h>
#include <vesicle_iga/studies/convergence_study.h>
#include <vesicle_iga/studies/plate_with_hole_geometry.h>
#include <vesicle_iga/studies/study.h>
#include <vesicle_iga/terms/linear_elasticity.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  KirschSolution::KirschSolution(const double E,
                                 const double nu,
                                 const double Tx,
                                 const double R)
    : E(E)
    , nu(nu)
    , Tx(Tx)
    , R(R)
  {}


  SymmetricTensor<2, 2>
  KirschSolution::stress(const Point<2> &x) const
  {
    // (P3)
    const double          r = x.norm(), th = std::atan2(x[1], x[0]);
    const double          a2 = R * R / (r * r), a4 = a2 * a2;
    SymmetricTensor<2, 2> s;
    s[0][0] = Tx
              * (1 - a2 * (1.5 * std::cos(2 * th) + std::cos(4 * th))
                 + 1.5 * a4 * std::cos(4 * th));
    s[1][1] = Tx
              * (-a2 * (0.5 * std::cos(2 * th) - std::cos(4 * th))
                 - 1.5 * a4 * std::cos(4 * th));
    s[0][1] = Tx
              * (-a2 * (0.5 * std::sin(2 * th) + std::sin(4 * th))
                 + 1.5 * a4 * std::sin(4 * th));
    return s;
  }


  Tensor<1, 2>
  KirschSolution::displacement(const Point<2> &x) const
  {
    // (P4)
    const double r = x.norm(), th = std::atan2(x[1], x[0]);
    const double mu = E / (2 * (1 + nu)), kappa = (3 - nu) / (1 + nu);
    const double f = R * Tx / (8 * mu);
    Tensor<1, 2> u;
    u[0] = f
           * (r / R * (kappa + 1) * std::cos(th)
              + 2 * R / r * ((1 + kappa) * std::cos(th) + std::cos(3 * th))
              - 2 * std::pow(R / r, 3) * std::cos(3 * th));
    u[1] = f
           * (r / R * (kappa - 3) * std::sin(th)
              + 2 * R / r * ((1 - kappa) * std::sin(th) + std::sin(3 * th))
              - 2 * std::pow(R / r, 3) * std::sin(3 * th));
    return u;
  }


  std::shared_ptr<const NurbsGeometry<2>>
  make_plate_with_hole_geometry()
  {
    // (P2): xi along the hole (4 functions, C^1 at xi = 1/2), eta from the
    // hole to the outer edge (3 functions).
    const KnotVector      xi(2, {0., 0.5, 1.}, {1});
    const KnotVector      eta(2, {0., 1.});
    const SplineSpace<2>  space(std::array<KnotVector, 2>{{xi, eta}});
    const double          ws = 0.5 * (1 + 1 / std::sqrt(2.));
    const double          s2 = std::sqrt(2.);
    std::vector<Point<2>> P  = {{-1, 0},
                                {-1, s2 - 1},
                                {1 - s2, 1},
                                {0, 1},
                                {-2.5, 0},
                                {-2.5, 0.75},
                                {-0.75, 2.5},
                                {0, 2.5},
                                {-4, 0},
                                {-4, 4},
                                {-4, 4},
                                {0, 4}};
    std::vector<double>   w  = {1, ws, ws, 1, 1, 1, 1, 1, 1, 1, 1, 1};
    return std::make_shared<const NurbsGeometry<2>>(space, P, w);
  }


  namespace
  {
    const char *section = "Plate with hole";

    class PlateWithHole : public Study
    {
    public:
      PlateWithHole(ParameterHandler &prm, RunContext &context);
      void
      run() override;

    private:
      /// Displacement L2, energy and stress errors and the exact energy
      /// and stress norms, against (P3)-(P4).
      std::vector<double>
      errors(const StationaryProblem<2>             &problem,
             std::shared_ptr<const NurbsGeometry<2>> geometry,
             const unsigned int                      p,
             const KirschSolution                   &exact,
             const LinearElasticityTerm<2>          &elasticity) const;
      /// Displacement and stresses, computed and exact, as VTU.
      void
      write_fields(const StationaryProblem<2>             &problem,
                   std::shared_ptr<const NurbsGeometry<2>> geometry,
                   const unsigned int                      p,
                   const KirschSolution                   &exact,
                   const LinearElasticityTerm<2>          &elasticity) const;

      RunContext            &context;
      ConvergenceParameters  convergence;
      LinearSolverParameters solver;
      double                 E, nu, Tx;
    };


    /// The strain of the displacement (components 0, 1) at point q.
    SymmetricTensor<2, 2>
    strain(const SplineCellValues<2>              &v,
           const unsigned int                      q,
           const std::vector<std::vector<double>> &c)
    {
      Tensor<2, 2> G;
      for (unsigned int a = 0; a < 2; ++a)
        G[a] = v.gradient(c[a], q);
      return symmetrize(G);
    }


    PlateWithHole::PlateWithHole(ParameterHandler &prm, RunContext &context)
      : context(context)
    {
      check_input(context.dimension == 2,
                  "Dimension",
                  std::to_string(context.dimension),
                  "2 (the plate with a hole is a plane-stress problem)");
      prm.enter_subsection(section);
      convergence.parse(prm, 0);
      check_input(convergence.continuity < 0,
                  "Continuity",
                  std::to_string(convergence.continuity),
                  "-1 (spec section 5.5: elevation keeps C^1 at xi = 1/2, "
                  "inserted knots get C^{p-1})");
      solver.parse(prm);
      E  = prm.get_double("Young modulus");
      nu = prm.get_double("Poisson ratio");
      Tx = prm.get_double("Traction");
      prm.leave_subsection();
      check_input(nu > -1 && nu < 0.5,
                  "Poisson ratio",
                  value_text(nu),
                  "-1 < nu < 0.5");
    }


    void
    PlateWithHole::run()
    {
      const KirschSolution    exact(E, nu, Tx, 1.);
      const auto              coarse = make_plate_with_hole_geometry();
      LinearElasticityTerm<2> elasticity(0, E, nu, true);
      // xi = 0 is y = 0 (u_y = 0), xi = 1 is x = 0 (u_x = 0), eta = 1 the
      // outer edges with the exact traction, eta = 0 the free hole.
      const BoundarySelection<2>       symmetry_y("x-min", "symmetry");
      const BoundarySelection<2>       symmetry_x("x-max", "symmetry");
      const BoundarySelection<2>       outer("y-max", "traction");
      TractionTerm<2>                  traction(0,
                               outer,
                               [&](const Point<2> &x, const Tensor<1, 2> &n) {
                                 return exact.stress(x) * n;
                               });
      const Functions::ZeroFunction<2> zero(2);

      const auto   timer_owner = context.make_timer();
      TimerOutput &timer       = *timer_owner;
      run_convergence_study(
        context,
        2,
        convergence,
        {"L2", "energy", "stress_L2", "energy_relative", "stress_L2_relative"},
        [&](const unsigned int p, const unsigned int r) {
          check_input(p >= 2,
                      "Degrees",
                      std::to_string(p),
                      "p >= 2 (the exact geometry is quadratic NURBS)");
          const SplineSpace<2> space
            = coarse->space().degree_elevated(p - 2).h_refined(r);
          const auto geometry = std::make_shared<const NurbsGeometry<2>>(
            coarse->refined_to(space));
          StationaryProblem<2> problem(context.communicator,
                                       space,
                                       geometry,
                                       2);
          add_strong_dirichlet_constraints<2>(problem.dofs(),
                                              geometry,
                                              symmetry_y,
                                              zero,
                                              {false, true},
                                              problem.constraints());
          add_strong_dirichlet_constraints<2>(problem.dofs(),
                                              geometry,
                                              symmetry_x,
                                              zero,
                                              {true, false},
                                              problem.constraints());
          const auto result
            = problem.solve({&elasticity, &traction},
                            QGauss<1>(p + 1
                                      + convergence.extra_quadrature_points),
                            solver,
                            &timer);
          const auto e = this->errors(problem, geometry, p, exact, elasticity);
          if (convergence.write_vtu && r == convergence.refinements)
            {
              TimerOutput::Scope t(timer, "output");
              write_fields(problem, geometry, p, exact, elasticity);
            }
          return ConvergenceLevel{space.n_elements(),
                                  problem.dofs().n_dofs(),
                                  problem.mesh().max_cell_diameter(),
                                  {std::sqrt(e[4]),
                                   std::sqrt(e[0]),
                                   std::sqrt(e[1]),
                                   std::sqrt(e[0] / e[2]),
                                   std::sqrt(e[1] / e[3])},
                                  result};
        },
        "Errors: energy = (int (eps-eps_h):C(eps-eps_h))^(1/2) (no factor 1/2), "
        "stress_L2 = ||sigma-sigma_h||_L2, L2 = ||u-u_h||_L2 against (P4); "
        "*_relative: divided by the same norm of the exact field.");
    }


    std::vector<double>
    PlateWithHole::errors(const StationaryProblem<2>             &problem,
                          std::shared_ptr<const NurbsGeometry<2>> geometry,
                          const unsigned int                      p,
                          const KirschSolution                   &exact,
                          const LinearElasticityTerm<2> &elasticity) const
    {
      return integrate_field<2>(
        problem.dofs(),
        geometry,
        QGauss<1>(p + 3 + convergence.extra_quadrature_points),
        1,
        problem.solution(),
        5,
        [&](const SplineCellValues<2>              &v,
            const unsigned int                      q,
            const std::vector<std::vector<double>> &c,
            std::vector<double>                    &sums) {
          const auto s_exact = exact.stress(v.quadrature_point(q));
          const auto e_h     = strain(v, q, c);
          const auto s_h     = elasticity.stress(e_h);
          // Exact strain from the exact stress (plane stress compliance),
          // so that no displacement derivative is needed.
          const double                tr = trace(s_exact);
          const SymmetricTensor<2, 2> e_exact
            = ((1 + nu) * s_exact - nu * tr * unit_symmetric_tensor<2>()) / E;
          const auto de = e_exact - e_h;
          sums[0] += elasticity.energy_product(de) * v.JxW(q);
          sums[1] += (s_exact - s_h).norm() * (s_exact - s_h).norm() * v.JxW(q);
          sums[2] += elasticity.energy_product(e_exact) * v.JxW(q);
          sums[3] += s_exact.norm() * s_exact.norm() * v.JxW(q);
          // Displacement error against (P4).
          const Tensor<1, 2> u_exact
            = exact.displacement(v.quadrature_point(q));
          for (unsigned int a = 0; a < 2; ++a)
            sums[4] += std::pow(v.value(c[a], q) - u_exact[a], 2) * v.JxW(q);
        });
    }


    void
    PlateWithHole::write_fields(
      const StationaryProblem<2>             &problem,
      std::shared_ptr<const NurbsGeometry<2>> geometry,
      const unsigned int                      p,
      const KirschSolution                   &exact,
      const LinearElasticityTerm<2>          &elasticity) const
    {
      SplineFieldWriter<2> writer(problem.dofs(), geometry);
      writer.add_components({"u_x", "u_y"});
      for (const auto &[name, a, b] :
           std::vector<std::tuple<std::string, int, int>>{{"sigma_xx", 0, 0},
                                                          {"sigma_yy", 1, 1},
                                                          {"sigma_xy", 0, 1}})
        {
          writer.add_quantity(
            name,
            [&, a = a, b = b](const SplineCellValues<2>              &v,
                              const unsigned int                      q,
                              const std::vector<std::vector<double>> &c) {
              return elasticity.stress(strain(v, q, c))[a][b];
            },
            1);
          writer.add_quantity(
            name + "_exact",
            [&, a = a, b = b](const SplineCellValues<2> &v,
                              const unsigned int         q,
                              const std::vector<std::vector<double>> &) {
              return exact.stress(v.quadrature_point(q))[a][b];
            });
        }
      writer.write(problem.solution(),
                   context.output_directory,
                   "solution-p" + std::to_string(p));
    }
  } // namespace


  StudyDescription
  plate_with_hole_description()
  {
    return {"plate-with-hole",
            "Spec Part P: plane-stress plate with a circular hole on the exact "
            "NURBS geometry, energy-norm and stress errors against Kirsch's "
            "solution for p-elevated and h-refined spaces.",
            [](ParameterHandler &prm) {
              prm.enter_subsection(section);
              ConvergenceParameters::declare(prm, "2,3,4,5,6", "5", "1");
              LinearSolverParameters::declare(prm, "direct");
              prm.declare_entry("Young modulus",
                                "1e5",
                                Patterns::Double(0),
                                "E of spec section 5.3.");
              prm.declare_entry("Poisson ratio",
                                "0.3",
                                Patterns::Double(),
                                "nu of spec section 5.3, -1 < nu < 0.5.");
              prm.declare_entry("Traction",
                                "10",
                                Patterns::Double(),
                                "Remote uniaxial traction T_x (spec section 7, "
                                "item 49).");
              prm.leave_subsection();
            },
            [](ParameterHandler &prm,
               RunContext       &context) -> std::unique_ptr<Study> {
              return std::make_unique<PlateWithHole>(prm, context);
            }};
  }
} // namespace vesicle_iga
