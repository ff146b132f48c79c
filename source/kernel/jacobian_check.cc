#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vesicle_iga/kernel/jacobian_check.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    /// The ghosted vector v + h f d with f the per-component factor.
    template <int dim>
    void
    perturb(const SplineDofHandler<dim>         &dofs,
            const TrilinosWrappers::MPI::Vector &v,
            const std::vector<double>           &factor,
            const double                         default_factor,
            const TrilinosWrappers::MPI::Vector &d,
            const double                         h,
            TrilinosWrappers::MPI::Vector       &result)
    {
      TrilinosWrappers::MPI::Vector owned(dofs.locally_owned_dofs(),
                                          dofs.get_mesh().get_communicator());
      for (const auto i : dofs.locally_owned_dofs())
        owned[i] = v[i];
      for (unsigned int k = 0; k < dofs.n_components(); ++k)
        {
          const double f = factor.empty() ? default_factor : factor[k];
          for (unsigned int i = 0; i < dofs.component_space(k).n_basis(); ++i)
            {
              const auto g = dofs.dof_index(i, k);
              if (dofs.locally_owned_dofs().is_element(g))
                owned[g] += h * f * d[g];
            }
        }
      owned.compress(VectorOperation::insert);
      result.reinit(dofs.locally_owned_dofs(),
                    dofs.locally_relevant_dofs(),
                    dofs.get_mesh().get_communicator());
      result = owned;
    }
  } // namespace


  template <int dim>
  JacobianCheck
  check_jacobian(const SystemAssembler<dim>          &assembler,
                 const AssemblyState                 &state,
                 const AffineConstraints<double>     &constraints,
                 const TrilinosWrappers::MPI::Vector &d,
                 const std::vector<double>           &steps)
  {
    const auto                       &dofs = assembler.get_dofs();
    TrilinosWrappers::SparsityPattern sparsity;
    dofs.make_sparsity_pattern(sparsity);
    TrilinosWrappers::SparseMatrix K(sparsity);
    TrilinosWrappers::MPI::Vector  Kd(d), rp(d), rm(d);
    JacobianCheck                  result;

    AssemblyState value_only = state;
    value_only.rate_factor.assign(dofs.n_components(), 0.);
    assembler.assemble(value_only, constraints, nullptr, &K);
    K.vmult(Kd, d);
    result.norm_value_part = Kd.l2_norm();
    assembler.assemble(state, constraints, nullptr, &K);
    K.vmult(Kd, d);
    result.norm_Kd = Kd.l2_norm();

    TrilinosWrappers::MPI::Vector value, rate;
    for (const double h : steps)
      {
        for (const double sign : {1., -1.})
          {
            AssemblyState perturbed = state;
            perturb(
              dofs, *state.value, state.value_factor, 1., d, sign * h, value);
            perturbed.value = &value;
            if (state.rate)
              {
                perturb(
                  dofs, *state.rate, state.rate_factor, 0., d, sign * h, rate);
                perturbed.rate = &rate;
              }
            assembler.assemble(perturbed,
                               constraints,
                               sign > 0 ? &rp : &rm,
                               nullptr);
          }
        rp -= rm;
        rp *= 1. / (2 * h);
        rp -= Kd;
        result.relative_difference.push_back(rp.l2_norm() / result.norm_Kd);
      }
    return result;
  }


  template <int dim>
  TrilinosWrappers::MPI::Vector
  test_direction(const SplineDofHandler<dim>     &dofs,
                 const AffineConstraints<double> &constraints)
  {
    TrilinosWrappers::MPI::Vector d(dofs.locally_owned_dofs(),
                                    dofs.get_mesh().get_communicator());
    unsigned int                  natural = 0;
    for (unsigned int k = 0; k < dofs.n_components(); ++k)
      for (unsigned int i = 0; i < dofs.component_space(k).n_basis();
           ++i, ++natural)
        if (d.in_local_range(dofs.dof_index(i, k)))
          d[dofs.dof_index(i, k)]
            = std::sin(0.37 * natural) * std::cos(0.11 * natural);
    d.compress(VectorOperation::insert);
    constraints.set_zero(d);
    return d;
  }

#define INSTANTIATE(dim)                                                       \
  template JacobianCheck check_jacobian(const SystemAssembler<dim> &,          \
                                        const AssemblyState &,                 \
                                        const AffineConstraints<double> &,     \
                                        const TrilinosWrappers::MPI::Vector &, \
                                        const std::vector<double> &);          \
  template TrilinosWrappers::MPI::Vector test_direction(                       \
    const SplineDofHandler<dim> &, const AffineConstraints<double> &);
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace vesicle_iga
