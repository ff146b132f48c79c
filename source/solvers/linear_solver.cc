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
                                  const std::string &default_method)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Method",
                      default_method,
                      Patterns::Selection("cg-amg|gmres-amg|gmres-ilu|direct"),
                      "cg-amg: conjugate gradients with Trilinos ML algebraic "
                      "multigrid (SPD systems); gmres-amg: restarted GMRES "
                      "with the same AMG; gmres-ilu: restarted GMRES with "
                      "ILU(1) on each rank (block Jacobi across ranks); "
                      "direct: Amesos KLU sparse LU.");
    prm.declare_entry("Tolerance",
                      "1e-12",
                      Patterns::Double(0, 1),
                      "Relative residual reduction of the Krylov method.");
    prm.declare_entry("Max iterations",
                      "5000",
                      Patterns::Integer(1),
                      "Iteration limit of the Krylov method; reaching it is "
                      "an error.");
    prm.leave_subsection();
  }


  void
  LinearSolverParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    method         = prm.get("Method");
    tolerance      = prm.get_double("Tolerance");
    max_iterations = prm.get_integer("Max iterations");
    prm.leave_subsection();
  }


  LinearSolveResult
  solve_linear_system(const LinearSolverParameters         &parameters,
                      const TrilinosWrappers::SparseMatrix &A,
                      TrilinosWrappers::MPI::Vector        &x,
                      const TrilinosWrappers::MPI::Vector  &b,
                      const AffineConstraints<double>      &constraints)
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
        if (parameters.method == "gmres-ilu")
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
            if (parameters.method == "cg-amg")
              {
                SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
                cg.solve(A, x, b, *preconditioner);
              }
            else
              {
                SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
                  control,
                  SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
                    100));
                gmres.solve(A, x, b, *preconditioner);
              }
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
