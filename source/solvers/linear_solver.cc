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
  void
  LinearSolverParameters::declare(ParameterHandler  &prm,
                                  const std::string &default_method,
                                  const std::string &default_tolerance,
                                  const std::string &default_smoother,
                                  const std::string &default_sweeps)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Method",
                      default_method,
                      Patterns::Selection(
                        "cg-amg|gmres-amg|gmres-ilu|direct|gmres-mg|cg-mg"),
                      "cg-amg: conjugate gradients with Trilinos ML algebraic "
                      "multigrid (SPD systems); gmres-amg: restarted GMRES "
                      "with the same AMG; gmres-ilu: restarted GMRES with "
                      "ILU(1) on each rank (block Jacobi across ranks); "
                      "direct: Amesos KLU sparse LU; gmres-mg, cg-mg: GMRES "
                      "or CG with one V-cycle of the geometric spline "
                      "multigrid (subsection Multigrid; phase-field studies "
                      "only).");
    prm.declare_entry("Tolerance",
                      default_tolerance,
                      Patterns::Double(0, 1),
                      "Relative residual reduction of the Krylov method.");
    prm.declare_entry("Max iterations",
                      "5000",
                      Patterns::Integer(1),
                      "Iteration limit of the Krylov method; reaching it is "
                      "an error.");
    SplineMultigridParameters::declare(prm, default_smoother, default_sweeps);
    prm.leave_subsection();
  }


  void
  LinearSolverParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    method         = prm.get("Method");
    tolerance      = prm.get_double("Tolerance");
    max_iterations = prm.get_integer("Max iterations");
    multigrid.parse(prm);
    prm.leave_subsection();
  }


  LinearSolveResult
  solve_linear_system(const LinearSolverParameters         &parameters,
                      const TrilinosWrappers::SparseMatrix &A,
                      TrilinosWrappers::MPI::Vector        &x,
                      const TrilinosWrappers::MPI::Vector  &b,
                      const AffineConstraints<double>      &constraints,
                      MatrixPreconditioner                 *multigrid)
  {
    LinearSolveResult result{0, 0.};
    const double      b_norm = b.l2_norm();
    if (parameters.method == "direct")
      {
        SolverControl                  control(1, 0);
        TrilinosWrappers::SolverDirect solver(control);
        solver.solve(A, x, b);
      }
    else
      {
        SolverControl control(parameters.max_iterations,
                              parameters.tolerance * b_norm);
        std::unique_ptr<TrilinosWrappers::PreconditionBase> preconditioner;
        if (parameters.uses_multigrid())
          {
            check_input(multigrid != nullptr,
                        "Linear solver/Method",
                        parameters.method,
                        "a method without multigrid for this study (the "
                        "spline multigrid serves the phase-field solvers)");
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
            // The multigrid V-cycle as a deal.II preconditioner.
            struct Wrapper
            {
              const MatrixPreconditioner *p;
              void
              vmult(TrilinosWrappers::MPI::Vector       &dst,
                    const TrilinosWrappers::MPI::Vector &src) const
              {
                p->vmult(dst, src);
              }
            } mg{multigrid};
            using Vector   = TrilinosWrappers::MPI::Vector;
            const auto run = [&](const auto &P) {
              if (parameters.method == "cg-amg" || parameters.method == "cg-mg")
                {
                  SolverCG<Vector> cg(control);
                  cg.solve(A, x, b, P);
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
            if (parameters.uses_multigrid())
              run(mg);
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
