#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/solvers/linear_solver.h>

#include <memory>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    /// The Krylov entries every "Linear solver" subsection has.
    void
    declare_krylov_entries(ParameterHandler  &prm,
                           const std::string &default_tolerance,
                           const std::string &iteration_limit_meaning)
    {
      prm.declare_entry("Tolerance",
                        default_tolerance,
                        Patterns::Double(0, 1),
                        "Relative residual reduction of the Krylov method.");
      prm.declare_entry("Max iterations",
                        "5000",
                        Patterns::Integer(1),
                        "Iteration limit of the Krylov method; reaching it "
                          + iteration_limit_meaning + ".");
    }


    void
    parse_krylov_entries(ParameterHandler &prm, LinearSolverParameters &p)
    {
      p.method         = prm.get("Method");
      p.tolerance      = prm.get_double("Tolerance");
      p.max_iterations = prm.get_integer("Max iterations");
    }
  } // namespace


  void
  LinearSolverParameters::declare(ParameterHandler  &prm,
                                  const std::string &default_method,
                                  const std::string &default_tolerance,
                                  const std::string &default_smoother,
                                  const std::string &default_sweeps)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry(
      "Method",
      default_method,
      Patterns::Selection("cg-amg|gmres-amg|gmres-ilu|direct|gmres-mg|cg-mg"),
      "cg-amg: conjugate gradients with Trilinos ML algebraic "
      "multigrid (SPD systems); gmres-amg: restarted GMRES "
      "with the same AMG; gmres-ilu: restarted GMRES with "
      "ILU(1) on each rank (block Jacobi across ranks); "
      "direct: MUMPS sparse LU (Amesos); gmres-mg, cg-mg: GMRES "
      "or CG with one V-cycle of the geometric spline "
      "multigrid (subsection Multigrid).");
    declare_krylov_entries(prm, default_tolerance, "is an error");
    SplineMultigridParameters::declare(prm, default_smoother, default_sweeps);
    prm.leave_subsection();
  }


  void
  LinearSolverParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    parse_krylov_entries(prm, *this);
    multigrid.parse(prm);
    // CG needs a symmetric preconditioner; the restricted Schwarz smoother
    // makes the V-cycle non-symmetric.
    check_input(method != "cg-mg" || multigrid.smoother != "schwarz-ilu",
                "Linear solver/Multigrid/Smoother",
                multigrid.smoother,
                "a symmetric smoother (ssor, chebyshev, ilu) with Method = "
                "cg-mg, or Method = gmres-mg");
    prm.leave_subsection();
  }


  void
  FlowBlockPreconditionerParameters::declare(ParameterHandler         &prm,
                                             const FlowSolverDefaults &defaults)
  {
    prm.enter_subsection("Block preconditioner");
    prm.declare_entry(
      "Velocity preconditioner",
      "spline-multigrid",
      Patterns::Selection("spline-multigrid|amg"),
      "One V-cycle on the velocity block: spline-multigrid (the geometric "
      "multigrid of the nested spline spaces, every velocity component "
      "coarsened alike, smoother 'Velocity smoother', sparse LU on the "
      "coarsest level; "
      "mesh-independent counts) or amg (Trilinos ML; the count grows "
      "under refinement on spline spaces, doc/flow.md).");
    prm.declare_entry(
      "Velocity sweeps",
      defaults.velocity_sweeps,
      Patterns::Integer(1),
      "Smoother sweeps (ssor, ilu, schwarz-ilu) or Chebyshev degree of "
      "the V-cycle on the velocity block (Method = "
      "fgmres-block).");
    prm.declare_entry("Velocity smoother",
                      defaults.velocity_smoother,
                      Patterns::Selection(
                        SplineMultigridParameters::smoother_names()),
                      "Smoother of the velocity spline multigrid: "
                        + SplineMultigridParameters::smoother_documentation());
    prm.declare_entry("Velocity coarse size",
                      "0",
                      Patterns::Integer(0),
                      "The velocity spline multigrid coarsens until a level "
                      "has at most this many unknowns, solved by sparse LU "
                      "(0: 4000 in 2D, 1000 in 3D).");
    prm.declare_entry("Schur sweeps",
                      "2",
                      Patterns::Integer(1),
                      "Smoother sweeps of the AMG V-cycles on the pressure "
                      "Schur complement and (vesicles in the flow) on the "
                      "tension Schur complements.");
    prm.declare_entry("Velocity elliptic",
                      "true",
                      Patterns::Bool(),
                      "true: symmetric smoothed aggregation with Chebyshev "
                      "smoothing for the velocity block (mass and viscous "
                      "terms dominate); false: non-symmetric smoothed "
                      "aggregation (convection-dominated steps).");
    prm.declare_entry(
      "Schur approximation",
      defaults.schur_approximation,
      Patterns::Selection(
        "cahouet-chabard|stabilized-cahouet-chabard|simple|direct"),
      "cahouet-chabard: S^-1 = (lumped viscous pressure mass)^-1 + "
      "(C - D M_L^-1 B)^-1 with M_L the lumped velocity mass. "
      "stabilized-cahouet-chabard: the viscous part by (consistent "
      "viscous pressure mass + C)^-1, C the RBVMS pressure block: the "
      "equal-order pressure modes that only C controls are seen by it, "
      "and the count stays bounded under refinement in viscous flows "
      "(with the velocity V-cycle: 35-47 FGMRES iterations per step "
      "against 94-138 at 32 elements per unit length on HD3; "
      "doc/hydrodynamics.md, \"Linear solver\"). "
      "simple: S = C - D diag(A)^-1 B (grows with refinement in viscous "
      "flows; kept for comparison). direct: no approximation, the whole "
      "velocity-pressure block by sparse LU (Amesos KLU; the velocity "
      "settings are unused): a diagnostic that shows the Krylov iterations "
      "the two approximations cost, far too slow and large for runs.");
    prm.declare_entry(
      "Viscous Schur tolerance",
      "1e-2",
      Patterns::Double(0., 1.),
      "Schur approximation = stabilized-cahouet-chabard: relative "
      "tolerance of the CG solve (preconditioned by AMG) of the viscous "
      "part M_nu + C; 0 applies one AMG V-cycle instead.");
    prm.declare_entry(
      "Velocity tolerance",
      "0",
      Patterns::Double(0., 1.),
      "0: the velocity block is approximated by one V-cycle of the velocity "
      "preconditioner. > 0: by GMRES on the velocity block, preconditioned "
      "by that V-cycle, to this relative residual (at most 100 "
      "iterations): a V-cycle that is weak on the grad-div term of RBVMS "
      "then costs inner iterations instead of outer ones, and the outer "
      "count follows the Schur approximation alone (it takes 1e-5 to "
      "reach the count of the exact velocity solve; doc/hydrodynamics.md, "
      "\"Linear solver\").");
    prm.leave_subsection();
  }


  void
  FlowBlockPreconditionerParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Block preconditioner");
    velocity_preconditioner = prm.get("Velocity preconditioner");
    velocity_sweeps         = prm.get_integer("Velocity sweeps");
    velocity_coarse_size    = prm.get_integer("Velocity coarse size");
    velocity_smoother       = prm.get("Velocity smoother");
    schur_sweeps            = prm.get_integer("Schur sweeps");
    velocity_elliptic       = prm.get_bool("Velocity elliptic");
    schur_approximation     = prm.get("Schur approximation");
    viscous_schur_tolerance = prm.get_double("Viscous Schur tolerance");
    velocity_tolerance      = prm.get_double("Velocity tolerance");
    prm.leave_subsection();
  }


  void
  LinearSolverParameters::declare_flow(ParameterHandler         &prm,
                                       const FlowSolverDefaults &defaults)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Method",
                      defaults.method,
                      Patterns::Selection(
                        "gmres-ilu|gmres-amg|direct|fgmres-block"),
                      "gmres-ilu: restarted GMRES with ILU(1) on each rank "
                      "(block Jacobi across ranks); gmres-amg: GMRES with "
                      "Trilinos ML AMG on the whole system; direct: MUMPS "
                      "sparse LU (Amesos, parallel); fgmres-block: "
                      "flexible GMRES with the block upper-triangular "
                      "preconditioner of the Block preconditioner subsection "
                      "(a V-cycle on the velocity block, a Schur complement "
                      "approximation on the pressure; doc/flow.md).");
    declare_krylov_entries(prm,
                           defaults.tolerance,
                           "fails the time step (which is then retried with "
                           "a smaller step)");
    prm.declare_entry(
      "Preconditioner reuse",
      defaults.reuse,
      Patterns::Selection("every-matrix|across-steps"),
      "every-matrix: the block preconditioner is built for every Jacobian; "
      "across-steps: it is kept across Newton iterations and time steps "
      "and rebuilt once the solves since its build have needed 'Rebuild "
      "after extra iterations' more Krylov iterations than the first of "
      "them, when a solve fails and when the step size changes. The "
      "Jacobian itself is always current, so the solution is the same to "
      "the Krylov tolerance; the set-up (block extraction, Schur products, "
      "AMG and multigrid hierarchies) is then paid every few steps "
      "instead of every Newton iteration (method fgmres-block).");
    prm.declare_entry(
      "Rebuild after extra iterations",
      "40",
      Patterns::Integer(0),
      "Preconditioner reuse = across-steps: the sum over the solves since "
      "the last build of (iterations - iterations of the first solve) "
      "that triggers a rebuild. About the cost of a build in Krylov "
      "iterations (35-45 for the vesicle blocks of HD3 and the quick "
      "doublet); 0 rebuilds whenever a solve needs more iterations than "
      "the first.");
    FlowBlockPreconditionerParameters::declare(prm, defaults);
    prm.leave_subsection();
  }


  void
  LinearSolverParameters::parse_flow(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    parse_krylov_entries(prm, *this);
    preconditioner_reuse = prm.get("Preconditioner reuse");
    rebuild_extra_iterations
      = prm.get_integer("Rebuild after extra iterations");
    block.parse(prm);
    prm.leave_subsection();
  }


  LinearSolveResult
  solve_linear_system(const LinearSolverParameters         &parameters,
                      const TrilinosWrappers::SparseMatrix &A,
                      TrilinosWrappers::MPI::Vector        &x,
                      const TrilinosWrappers::MPI::Vector  &b,
                      const AffineConstraints<double>      &constraints,
                      MatrixPreconditioner *caller_preconditioner)
  {
    LinearSolveResult result{0, 0.};
    const double      b_norm = b.l2_norm();
    if (parameters.method == "direct")
      {
        // MUMPS (parallel, with a fill-reducing ordering): KLU's ordering
        // makes the coupled Part H systems (49 couplings per unknown and
        // field in 2D) about 100x slower to factor.
        SolverControl                  control(1, 0);
        TrilinosWrappers::SolverDirect solver(
          control,
          TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                         "Amesos_Mumps"));
        solver.solve(A, x, b);
      }
    else
      {
        SolverControl control(parameters.max_iterations,
                              parameters.tolerance * b_norm);
        std::unique_ptr<TrilinosWrappers::PreconditionBase> preconditioner;
        if (parameters.uses_caller_preconditioner())
          {
            check_input(caller_preconditioner != nullptr,
                        "Linear solver/Method",
                        parameters.method,
                        "a method this study offers (gmres-mg and cg-mg "
                        "serve the phase-field solvers, fgmres-block the "
                        "flow solver)");
          }
        else if (parameters.method == "gmres-ilu")
          {
            auto ilu = std::make_unique<TrilinosWrappers::PreconditionILU>();
            TrilinosWrappers::PreconditionILU::AdditionalData data(1);
            ilu->initialize(A, data);
            preconditioner = std::move(ilu);
          }
        else
          {
            auto amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
            TrilinosWrappers::PreconditionAMG::AdditionalData data;
            data.elliptic              = (parameters.method == "cg-amg");
            data.higher_order_elements = true;
            data.smoother_sweeps       = 2;
            data.aggregation_threshold = 0.02;
            amg->initialize(A, data);
            preconditioner = std::move(amg);
          }
        try
          {
            // The caller's preconditioner (multigrid V-cycle, flow blocks) as a
            // deal.II preconditioner.
            struct Wrapper
            {
              const MatrixPreconditioner *p;
              void
              vmult(TrilinosWrappers::MPI::Vector       &dst,
                    const TrilinosWrappers::MPI::Vector &src) const
              {
                p->vmult(dst, src);
              }
            } caller{caller_preconditioner};
            using Vector   = TrilinosWrappers::MPI::Vector;
            const auto run = [&](const auto &P) {
              if (parameters.method == "cg-amg" || parameters.method == "cg-mg")
                {
                  SolverCG<Vector> cg(control);
                  cg.solve(A, x, b, P);
                }
              else if (parameters.method == "fgmres-block")
                {
                  SolverFGMRES<Vector> fgmres(
                    control, SolverFGMRES<Vector>::AdditionalData(100));
                  fgmres.solve(A, x, b, P);
                }
              else
                {
                  // Right preconditioning: the tolerance then applies to
                  // the true residual, not to the preconditioned one.
                  SolverGMRES<Vector> gmres(
                    control, SolverGMRES<Vector>::AdditionalData(100, true));
                  gmres.solve(A, x, b, P);
                }
            };
            if (parameters.uses_caller_preconditioner())
              run(caller);
            else
              run(*preconditioner);
          }
        catch (const SolverControl::NoConvergence &e)
          {
            throw std::runtime_error(
              "Linear solver: " + parameters.method + " did not converge in "
              + std::to_string(e.last_step) + " iterations (residual "
              + std::to_string(e.last_residual)
              + "); raise 'Max iterations' or use 'set Method = direct'.");
          }
        result.iterations = control.last_step();
      }
    TrilinosWrappers::MPI::Vector r(b);
    A.vmult(r, x);
    r.sadd(-1., 1., b);
    result.residual = b_norm > 0 ? r.l2_norm() / b_norm : r.l2_norm();
    constraints.distribute(x);
    return result;
  }
} // namespace vesicle_iga
