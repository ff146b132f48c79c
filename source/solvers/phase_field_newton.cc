#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vesicle_iga/assembly/assembler.h>
#include <vesicle_iga/solvers/phase_field_newton.h>

#include <cmath>
#include <iomanip>

namespace vesicle_iga
{
  void
  NewtonParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry("Max Newton iterations",
                      "12",
                      Patterns::Integer(1),
                      "Newton iterations before the step counts as failed "
                      "(it is then repeated with dt / 4).");
    prm.declare_entry("Newton relative tolerance",
                      "1e-8",
                      Patterns::Double(0),
                      "Reduction of the residual norm of (E18) relative to "
                      "its value at the predictor.");
    prm.declare_entry("Newton absolute tolerance",
                      "1e-10",
                      Patterns::Double(0),
                      "Residual norm of (E18) that counts as converged.");
  }


  void
  NewtonParameters::parse(ParameterHandler &prm)
  {
    max_iterations     = prm.get_integer("Max Newton iterations");
    relative_tolerance = prm.get_double("Newton relative tolerance");
    absolute_tolerance = prm.get_double("Newton absolute tolerance");
  }


  template <int dim>
  PhaseFieldNewton<dim>::PhaseFieldNewton(
    const SplineDofHandler<dim>     &dofs,
    PhaseFieldOperator<dim>         &op,
    const AffineConstraints<double> &increment_constraints,
    const Quadrature<1>             &quadrature_1d,
    const LinearSolverParameters    &solver,
    const NewtonParameters          &newton,
    TimerOutput                     &timer)
    : dofs(dofs)
    , op(op)
    , constraints(increment_constraints)
    , quadrature(quadrature_1d)
    , solver(solver)
    , newton(newton)
    , timer(timer)
  {
    TrilinosWrappers::SparsityPattern sparsity;
    dofs.make_sparsity_pattern(sparsity);
    matrix.reinit(sparsity);
    if (solver.uses_multigrid())
      multigrid = std::make_unique<SplineMultigrid<dim>>(dofs,
                                                         constraints,
                                                         solver.multigrid);
    const MPI_Comm comm = dofs.get_mesh().get_communicator();
    ghost_phi.reinit(dofs.locally_owned_dofs(),
                     dofs.locally_relevant_dofs(),
                     comm);
    ghost_rate.reinit(ghost_phi);
  }


  template <int dim>
  std::string
  PhaseFieldNewton<dim>::solver_description() const
  {
    return solver.method
           + (multigrid ? " with " + multigrid->description() : std::string());
  }


  template <int dim>
  void
  PhaseFieldNewton<dim>::assemble(const double                   m,
                                  const double                   s,
                                  TrilinosWrappers::MPI::Vector &rhs,
                                  const bool                     matrix_too)
  {
    TimerOutput::Scope t(timer, "assembly");
    op.set_state(ghost_phi, ghost_rate, m, s, matrix_too);
    if (matrix_too)
      assemble_linear_system<dim>(
        dofs, nullptr, quadrature, {&op}, constraints, matrix, rhs);
    else
      assemble_vector<dim>(dofs, nullptr, quadrature, {&op}, constraints, rhs);
  }


  template <int dim>
  typename PhaseFieldNewton<dim>::Result
  PhaseFieldNewton<dim>::solve(const GeneralizedAlpha              &ga,
                               const double                         dt,
                               const TrilinosWrappers::MPI::Vector &phi_n,
                               const TrilinosWrappers::MPI::Vector &phidot_n,
                               TrilinosWrappers::MPI::Vector       &phi,
                               TrilinosWrappers::MPI::Vector       &phidot)
  {
    Result       result;
    const double s = ga.alpha_f * ga.gamma * dt;
    // Predictor (spec section 2.4, step 1).
    phidot = phidot_n;
    phidot *= (ga.gamma - 1) / ga.gamma;
    phi = phi_n;
    TrilinosWrappers::MPI::Vector rhs(phi_n), tmp(phi_n), increment(phi_n);
    double                        r0               = -1;
    unsigned int                  first_iterations = 0, last_iterations = 0;
    for (unsigned int it = 0; it <= newton.max_iterations; ++it)
      {
        // phidot_{n+alpha_m}, phi_{n+alpha_f} (N2).
        tmp = phidot;
        tmp.sadd(ga.alpha_m, 1 - ga.alpha_m, phidot_n);
        ghost_rate = tmp;
        tmp        = phi;
        tmp.sadd(ga.alpha_f, 1 - ga.alpha_f, phi_n);
        ghost_phi = tmp;
        assemble(ga.alpha_m, s, rhs, false);
        const double r = rhs.l2_norm();
        if (!std::isfinite(r))
          return result;
        if (r0 < 0)
          r0 = r;
        result.newton_iterations = it;
        if (r <= std::max(newton.absolute_tolerance,
                          newton.relative_tolerance * r0))
          {
            result.converged = true;
            return result;
          }
        if (it == newton.max_iterations)
          return result;
        // The matrix only when a correction is needed (the last iteration
        // of a step only checks the residual).
        assemble(ga.alpha_m, s, rhs, true);
        // The multigrid hierarchy (Galerkin products, smoothers, coarse
        // LU) is built from the first Newton matrix of the step and kept
        // while it stays effective: the matrix changes little between
        // Newton iterations, the set-up costs about two Krylov solves.
        if (multigrid
            && (it == 0 || last_iterations > 2 * first_iterations + 5))
          {
            TimerOutput::Scope t(timer, "preconditioner");
            multigrid->initialize(matrix);
            first_iterations = 0;
          }
        try
          {
            TimerOutput::Scope t(timer, "solve");
            increment = 0;
            last_iterations
              = solve_linear_system(
                  solver, matrix, increment, rhs, constraints, multigrid.get())
                  .iterations;
            result.krylov_iterations += last_iterations;
            if (first_iterations == 0)
              first_iterations = last_iterations;
          }
        catch (const std::exception &)
          {
            return result;
          }
        phidot += increment;
        phi.add(ga.gamma * dt, increment);
      }
    return result;
  }


  template <int dim>
  void
  PhaseFieldNewton<dim>::linear_response(
    const std::vector<TrilinosWrappers::MPI::Vector> &b,
    std::vector<TrilinosWrappers::MPI::Vector>       &x)
  {
    TimerOutput::Scope t(timer, "solve");
    x.resize(b.size());
    for (unsigned int k = 0; k < b.size(); ++k)
      {
        x[k].reinit(b[k]);
        solve_linear_system(
          solver, matrix, x[k], b[k], constraints, multigrid.get());
      }
  }


  template <int dim>
  TrilinosWrappers::MPI::Vector
  PhaseFieldNewton<dim>::test_vector() const
  {
    TrilinosWrappers::MPI::Vector d(dofs.locally_owned_dofs(),
                                    dofs.get_mesh().get_communicator());
    for (unsigned int i = 0; i < dofs.get_space().n_basis(); ++i)
      if (d.in_local_range(dofs.dof_index(i)))
        d[dofs.dof_index(i)] = std::sin(0.37 * i) * std::cos(0.11 * i);
    d.compress(VectorOperation::insert);
    constraints.set_zero(d);
    return d;
  }


  template <int dim>
  void
  PhaseFieldNewton<dim>::check_jacobian(
    const GeneralizedAlpha              &ga,
    const TrilinosWrappers::MPI::Vector &phi_n,
    const TrilinosWrappers::MPI::Vector &phidot_n,
    const ConditionalOStream            &out)
  {
    // K d against (R(phidot + h d) - R(phidot - h d)) / 2h at the state
    // (phi_n, phidot_n) (the predictor's phi), with dt = 1, so that the
    // energy part alpha_f gamma dt DR of K (N4) dominates the mass part.
    const double                  dt = 1., s = ga.alpha_f * ga.gamma * dt;
    const auto                    d = test_vector();
    TrilinosWrappers::MPI::Vector rhs(d), Kd(d), rp(d), rm(d), tmp(d);
    const auto                    residual = [&](const double                   h,
                              TrilinosWrappers::MPI::Vector &r,
                              const bool                     with_matrix) {
      tmp = phidot_n;
      tmp.add(ga.alpha_m * h, d);
      ghost_rate = tmp;
      tmp        = phi_n;
      tmp.add(s * h, d);
      ghost_phi = tmp;
      assemble(ga.alpha_m, s, r, with_matrix);
    };
    residual(0, rhs, true);
    matrix.vmult(Kd, d);
    // Share of the energy tangent in K d (the rest is the mass term).
    assemble(0., s, tmp, true);
    matrix.vmult(tmp, d);
    out << "Jacobian check: |alpha_f gamma dt DR d| / |K d| = "
        << std::setprecision(3) << tmp.l2_norm() / Kd.l2_norm()
        << std::setprecision(6) << std::endl
        << "Jacobian check (tangent (E20) against central differences of the "
           "residual (E18)):"
        << std::endl;
    for (const double h : {1e-2, 1e-3, 1e-4})
      {
        residual(h, rp, false);
        residual(-h, rm, false);
        // rhs = -R, so -(rp - rm)/2h approximates K d.
        rp -= rm;
        rp *= -1. / (2 * h);
        rp -= Kd;
        out << "  h = " << h << ": |FD - K d| / |K d| = " << std::scientific
            << std::setprecision(1) << rp.l2_norm() / Kd.l2_norm()
            << std::defaultfloat << std::setprecision(6) << std::endl;
      }
  }


  template <int dim>
  void
  PhaseFieldNewton<dim>::benchmark_linear_solver(
    const GeneralizedAlpha              &ga,
    const double                         dt,
    const TrilinosWrappers::MPI::Vector &phi_n,
    const TrilinosWrappers::MPI::Vector &phidot_n,
    const ConditionalOStream            &out)
  {
    // The Newton matrix K (N4) of the first step (phi = phi_n, the given
    // rate) for this dt, and b = K x* with a known x*.
    const MPI_Comm                comm    = dofs.get_mesh().get_communicator();
    const auto                    x_exact = test_vector();
    TrilinosWrappers::MPI::Vector b(x_exact), x(x_exact);
    ghost_phi  = phi_n;
    ghost_rate = phidot_n;
    Timer clock(comm, true);
    assemble(ga.alpha_m, ga.alpha_f * ga.gamma * dt, b, true);
    clock.stop();
    const double assembly_time = clock.wall_time();
    matrix.vmult(b, x_exact);
    x = 0;
    clock.restart();
    if (multigrid)
      multigrid->initialize(matrix);
    const auto r
      = solve_linear_system(solver, matrix, x, b, constraints, multigrid.get());
    clock.stop();
    x -= x_exact;
    out << "linear solver benchmark: unknowns " << dofs.n_dofs() << " dt " << dt
        << " method " << solver.method << " iterations " << r.iterations
        << " relative residual " << r.residual << " relative error "
        << x.l2_norm() / x_exact.l2_norm() << " assembly " << assembly_time
        << " s solve (with set-up) " << clock.wall_time() << " s" << std::endl;
  }

  template class PhaseFieldNewton<2>;
  template class PhaseFieldNewton<3>;
} // namespace vesicle_iga
