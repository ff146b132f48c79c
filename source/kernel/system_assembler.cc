// The assembly kernel (doc/engine.md, "The kernel"). Per element:
// 1. the univariate factors of every space (SplineCellValues without full
//    tables on boxes, with them on NURBS geometries);
// 2. every declared input (field, component, derivative) at all points by
//    sum factorisation (TensorProductKernel::evaluate);
// 3. every term once, adding coefficient arrays;
// 4. the residual coefficients against the test functions, the Jacobian
//    coefficients (with the time integrator's factors) against test and
//    trial functions, block by block of components;
// 5. scatter through the constraints (ElementScatter).

#include <deal.II/base/mpi.h>
#include <deal.II/base/work_stream.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vesicle_iga/kernel/element_scatter.h>
#include <vesicle_iga/kernel/system_assembler.h>
#include <vesicle_iga/kernel/tensor_product_kernel.h>
#include <vesicle_iga/spline/spline_cell_values.h>

#include <algorithm>

namespace vesicle_iga
{
  using namespace dealii;

  /// What the assembler does for one list of terms (the cell terms, the
  /// boundary terms, or an integrand): the slots of the inputs and outputs
  /// and how they are evaluated and integrated.
  template <int dim>
  struct SystemAssembler<dim>::Plan
  {
    TermDeclaration<dim>     declaration;
    std::vector<Term<dim> *> terms;
    /// Per term: its own input, residual and Jacobian handles -> slots.
    struct HandleMap
    {
      std::vector<unsigned int> inputs, residuals, jacobians;
    };
    std::vector<HandleMap> maps;
    std::vector<HandleMap> integrand_maps;

    /// Plain derivatives of one (source, component) evaluated together.
    struct InputGroup
    {
      FieldSource               source;
      unsigned int              auxiliary, component, space;
      std::vector<unsigned int> derivatives, slots;
    };
    std::vector<InputGroup> groups;
    /// A Laplacian-type input: the sum of plain input slots.
    struct Combined
    {
      unsigned int              slot;
      std::vector<unsigned int> parts;
    };
    std::vector<Combined> combined;

    /// Residual atoms (plain derivative, residual slot) of one component.
    struct ResidualComponent
    {
      unsigned int                                       component;
      std::vector<std::pair<unsigned int, unsigned int>> atoms;
    };
    std::vector<ResidualComponent> residual_components;

    struct Contribution
    {
      unsigned int slot;
      FieldSource  source;
    };
    struct PairPlan
    {
      unsigned int              test, trial;
      std::vector<Contribution> contributions;
    };
    /// The derivative pairs of one (test component, trial component) block.
    struct Block
    {
      unsigned int          test_component, trial_component;
      std::vector<PairPlan> pairs;
    };
    std::vector<Block> blocks;
    unsigned int       n_pairs = 0;

    /// The distinct spaces, the key of every system and auxiliary
    /// component, the highest derivative order.
    std::vector<const SplineSpace<dim> *>  spaces;
    std::vector<unsigned int>              system_space;
    std::vector<std::vector<unsigned int>> auxiliary_space;
    unsigned int                           max_order = 0;

    unsigned int
    space_of(const FieldSource  source,
             const unsigned int auxiliary,
             const unsigned int component) const
    {
      return source == FieldSource::auxiliary ?
               auxiliary_space[auxiliary][component] :
               system_space[component];
    }
  };


  namespace
  {
    template <int dim>
    using PlanOf = typename SystemAssembler<dim>::Plan;

    /// The distinct spaces of the system and auxiliary components.
    template <int dim>
    void
    collect_spaces(const SplineDofHandler<dim>                      &dofs,
                   const std::vector<const SplineDofHandler<dim> *> &aux,
                   PlanOf<dim>                                      &plan)
    {
      const auto key = [&](const SplineSpace<dim> &s) {
        for (unsigned int i = 0; i < plan.spaces.size(); ++i)
          if (*plan.spaces[i] == s)
            return i;
        plan.spaces.push_back(&s);
        return static_cast<unsigned int>(plan.spaces.size() - 1);
      };
      for (unsigned int k = 0; k < dofs.n_components(); ++k)
        plan.system_space.push_back(key(dofs.component_space(k)));
      for (const auto *a : aux)
        {
          plan.auxiliary_space.emplace_back();
          for (unsigned int k = 0; k < a->n_components(); ++k)
            plan.auxiliary_space.back().push_back(key(a->component_space(k)));
        }
    }


    /// Inputs: combined derivatives expanded into (possibly new, hidden)
    /// plain inputs; plain inputs grouped by field component.
    template <int dim>
    void
    plan_inputs(PlanOf<dim> &plan)
    {
      using D                 = Derivative<dim>;
      auto              &decl = plan.declaration;
      const unsigned int n    = decl.inputs.size();
      for (unsigned int s = 0; s < n; ++s)
        {
          const FieldInput in = decl.inputs[s];
          if (in.derivative < D::n_plain)
            continue;
          std::array<unsigned int, dim>  parts;
          const unsigned int             m = D::expand(in.derivative, parts);
          typename PlanOf<dim>::Combined c{s, {}};
          for (unsigned int k = 0; k < m; ++k)
            {
              FieldInput plain = in;
              plain.derivative = parts[k];
              c.parts.push_back(decl.input(plain).index);
            }
          plan.combined.push_back(c);
        }
      for (unsigned int s = 0; s < decl.inputs.size(); ++s)
        {
          const FieldInput &in = decl.inputs[s];
          if (in.derivative >= D::n_plain)
            continue;
          plan.max_order
            = std::max(plan.max_order, D::total_order(in.derivative));
          typename PlanOf<dim>::InputGroup *group = nullptr;
          for (auto &g : plan.groups)
            if (g.source == in.source && g.auxiliary == in.auxiliary
                && g.component == in.component)
              group = &g;
          if (!group)
            {
              plan.groups.push_back(
                {in.source,
                 in.auxiliary,
                 in.component,
                 plan.space_of(in.source, in.auxiliary, in.component),
                 {},
                 {}});
              group = &plan.groups.back();
            }
          group->derivatives.push_back(in.derivative);
          group->slots.push_back(s);
        }
    }


    /// Residual atoms per test component and Jacobian pairs per block.
    template <int dim>
    void
    plan_outputs(PlanOf<dim> &plan)
    {
      using D            = Derivative<dim>;
      const auto &decl   = plan.declaration;
      const auto  expand = [](const unsigned int d) {
        std::array<unsigned int, dim> parts;
        const unsigned int            m = D::expand(d, parts);
        return std::vector<unsigned int>(parts.begin(), parts.begin() + m);
      };
      for (unsigned int s = 0; s < decl.residuals.size(); ++s)
        {
          const auto &r  = decl.residuals[s];
          auto        it = std::find_if(plan.residual_components.begin(),
                                 plan.residual_components.end(),
                                 [&](const auto &c) {
                                   return c.component == r.component;
                                 });
          if (it == plan.residual_components.end())
            {
              plan.residual_components.push_back({r.component, {}});
              it = plan.residual_components.end() - 1;
            }
          for (const unsigned int a : expand(r.derivative))
            {
              it->atoms.emplace_back(a, s);
              plan.max_order = std::max(plan.max_order, D::total_order(a));
            }
        }
      for (unsigned int s = 0; s < decl.jacobians.size(); ++s)
        {
          const auto &j = decl.jacobians[s];
          auto        it
            = std::find_if(plan.blocks.begin(),
                           plan.blocks.end(),
                           [&](const auto &b) {
                             return b.test_component == j.test_component
                                    && b.trial_component == j.trial_component;
                           });
          if (it == plan.blocks.end())
            {
              plan.blocks.push_back({j.test_component, j.trial_component, {}});
              it = plan.blocks.end() - 1;
            }
          for (const unsigned int a : expand(j.test_derivative))
            for (const unsigned int b : expand(j.trial_derivative))
              {
                auto p = std::find_if(it->pairs.begin(),
                                      it->pairs.end(),
                                      [&](const auto &pp) {
                                        return pp.test == a && pp.trial == b;
                                      });
                if (p == it->pairs.end())
                  {
                    it->pairs.push_back({a, b, {}});
                    p = it->pairs.end() - 1;
                    ++plan.n_pairs;
                  }
                p->contributions.push_back({s, j.trial_source});
                plan.max_order = std::max(
                  {plan.max_order, D::total_order(a), D::total_order(b)});
              }
        }
    }


    template <int dim>
    std::unique_ptr<PlanOf<dim>>
    make_plan(const SplineDofHandler<dim>                      &dofs,
              const std::vector<const SplineDofHandler<dim> *> &aux,
              const std::vector<Term<dim> *>                   &terms,
              const std::vector<Integrand<dim> *>              &integrands)
    {
      auto plan = std::make_unique<PlanOf<dim>>();
      collect_spaces<dim>(dofs, aux, *plan);
      plan->terms      = terms;
      auto      &decl  = plan->declaration;
      const auto merge = [&](const TermDeclaration<dim>      &local,
                             typename PlanOf<dim>::HandleMap &map) {
        for (const auto &in : local.inputs)
          map.inputs.push_back(decl.input(in).index);
        for (const auto &r : local.residuals)
          map.residuals.push_back(
            decl.residual(r.component, r.derivative).index);
        for (const auto &j : local.jacobians)
          map.jacobians.push_back(decl
                                    .jacobian(j.test_component,
                                              j.test_derivative,
                                              j.trial_component,
                                              j.trial_derivative,
                                              j.trial_source)
                                    .index);
        decl.points = decl.points || local.points;
      };
      for (auto *t : terms)
        {
          TermDeclaration<dim> local;
          t->declare(local);
          plan->maps.emplace_back();
          merge(local, plan->maps.back());
        }
      for (auto *integrand : integrands)
        {
          TermDeclaration<dim> local;
          integrand->declare(local);
          plan->integrand_maps.emplace_back();
          merge(local, plan->integrand_maps.back());
        }
      plan_inputs<dim>(*plan);
      plan_outputs<dim>(*plan);
      return plan;
    }


    /// Derivative alpha of the full basis tables (NURBS geometries).
    template <int dim>
    double
    tabulated(const SplineCellValues<dim> &v,
              const unsigned int           alpha,
              const unsigned int           j,
              const unsigned int           q)
    {
      using D                       = Derivative<dim>;
      const auto                  o = D::orders(alpha);
      std::array<unsigned int, 3> k{};
      unsigned int                n = 0;
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int r = 0; r < o[d]; ++r)
          k[n++] = d;
      switch (n)
        {
          case 0:
            return v.shape_value(j, q);
          case 1:
            return v.shape_grad(j, q)[k[0]];
          case 2:
            return v.shape_hessian(j, q)[k[0]][k[1]];
          default:
            return v.shape_3rd_derivative(j, q)[k[0]][k[1]][k[2]];
        }
    }

    struct CopyData
    {
      FullMatrix<double>                   matrix;
      Vector<double>                       rhs;
      std::vector<types::global_dof_index> indices;
    };
  } // namespace


  /// Per-thread buffers: factors of every space, kernel workspace, the
  /// input and output arrays. Sized once; nothing is allocated per element
  /// once the largest element has been seen.
  template <int dim>
  struct SystemAssembler<dim>::Scratch
  {
    Scratch(const std::vector<const SplineSpace<dim> *> &spaces,
            std::shared_ptr<const NurbsGeometry<dim>>    geometry,
            const Quadrature<1>                         &quadrature,
            const unsigned int                           order)
    {
      for (const auto *s : spaces)
        {
          cell.emplace_back(*s, geometry, quadrature, order, bool(geometry));
          face.emplace_back(*s, geometry, quadrature, order, bool(geometry));
        }
      stride = 1;
      for (unsigned int d = 0; d < dim; ++d)
        stride *= quadrature.size();
    }
    std::size_t                                  stride = 0;
    std::vector<SplineCellValues<dim>>           cell, face;
    typename TensorProductKernel<dim>::Workspace workspace;
    std::vector<double>         inputs, residuals, jacobians, coefficients, JxW;
    std::vector<double>         local;
    std::vector<Point<dim>>     points;
    std::vector<Tensor<1, dim>> normals;
    std::vector<Tensor<2, dim>> metrics;
    std::vector<std::vector<types::global_dof_index>>    aux_indices;
    std::vector<double *>                                out;
    std::vector<typename TensorProductKernel<dim>::Atom> atoms;
    std::vector<typename TensorProductKernel<dim>::Pair> pairs;
    QuadratureInputs<dim>                                in;
    TermCoefficients                                     coefficients_out;
    unsigned int                                         n_q = 0;
  };


  namespace
  {
    template <int dim>
    using ScratchOf = typename SystemAssembler<dim>::Scratch;

    /// Factors, weights, points, metric and normals of element e (face
    /// @p face, or the cell for face < 0).
    template <int dim>
    void
    reinit_geometry(const PlanOf<dim> &plan,
                    ScratchOf<dim>    &s,
                    const unsigned int e,
                    const int          face,
                    const bool         tables)
    {
      auto &values = face < 0 ? s.cell : s.face;
      for (auto &v : values)
        face < 0 ? v.reinit(e) : v.reinit_face(e, face);
      const SplineCellValues<dim> &v0 = values[0];
      const unsigned int           nq = v0.n_quadrature_points();
      s.n_q                           = nq;
      s.JxW.resize(nq);
      s.points.resize(plan.declaration.points ? nq : 0);
      s.metrics.resize(nq);
      s.normals.resize(face < 0 ? 0 : nq);
      if (tables)
        {
          for (unsigned int q = 0; q < nq; ++q)
            {
              s.JxW[q]     = v0.JxW(q);
              s.metrics[q] = v0.metric_tensor(q);
              if (plan.declaration.points)
                s.points[q] = v0.quadrature_point(q);
              if (face >= 0)
                s.normals[q] = v0.normal_vector(q);
            }
          return;
        }
      const auto &f = v0.tensor_product_factors();
      TensorProductKernel<dim>::weights(f, s.JxW);
      // Boxes: G = diag(4 / h_d^2) (N1), normals along the axes.
      const Tensor<1, dim> h = plan.spaces[0]->element_lengths(e);
      Tensor<2, dim>       G;
      for (unsigned int d = 0; d < dim; ++d)
        G[d][d] = 4. / (h[d] * h[d]);
      std::fill(s.metrics.begin(), s.metrics.end(), G);
      if (face >= 0)
        {
          Tensor<1, dim> n;
          n[face / 2] = face % 2 ? 1. : -1.;
          std::fill(s.normals.begin(), s.normals.end(), n);
        }
      for (unsigned int q = 0; q < s.points.size(); ++q)
        {
          unsigned int r = q;
          for (unsigned int d = 0; d < dim; ++d)
            {
              s.points[q][d] = f.points[d][r % f.n_points[d]];
              r /= f.n_points[d];
            }
        }
    }


    /// Every input of the plan at all points of the current element.
    template <int dim>
    void
    evaluate_inputs(const PlanOf<dim>                                &plan,
                    ScratchOf<dim>                                   &s,
                    const AssemblyState                              &state,
                    const SplineDofHandler<dim>                      &dofs,
                    const std::vector<const SplineDofHandler<dim> *> &aux,
                    const std::vector<types::global_dof_index>       &indices,
                    const int                                         face,
                    const bool                                        tables)
    {
      const auto        &values = face < 0 ? s.cell : s.face;
      const unsigned int nq     = s.n_q;
      const std::size_t  stride = s.stride;
      s.inputs.resize(plan.declaration.inputs.size() * stride);
      for (const auto &g : plan.groups)
        {
          const TrilinosWrappers::MPI::Vector *v
            = g.source == FieldSource::value ?
                state.value :
                (g.source == FieldSource::rate ? state.rate :
                                                 state.auxiliary[g.auxiliary]);
          AssertThrow(v != nullptr,
                      ExcMessage("A term reads a field the state lacks."));
          const auto        &idx = g.source == FieldSource::auxiliary ?
                                     s.aux_indices[g.auxiliary] :
                                     indices;
          const unsigned int offset
            = g.source == FieldSource::auxiliary ?
                aux[g.auxiliary]->local_offset(g.component) :
                dofs.local_offset(g.component);
          const SplineCellValues<dim> &cv = values[g.space];
          const unsigned int           n  = cv.n_basis_per_element();
          s.local.resize(n);
          for (unsigned int j = 0; j < n; ++j)
            s.local[j] = (*v)(idx[offset + j]);
          s.out.resize(g.slots.size());
          for (unsigned int k = 0; k < g.slots.size(); ++k)
            s.out[k] = &s.inputs[g.slots[k] * stride];
          if (!tables)
            TensorProductKernel<dim>::evaluate(cv.tensor_product_factors(),
                                               s.local.data(),
                                               g.derivatives,
                                               s.out.data(),
                                               s.workspace);
          else
            for (unsigned int k = 0; k < g.slots.size(); ++k)
              for (unsigned int q = 0; q < nq; ++q)
                {
                  double sum = 0;
                  for (unsigned int j = 0; j < n; ++j)
                    sum += s.local[j] * tabulated(cv, g.derivatives[k], j, q);
                  s.out[k][q] = sum;
                }
        }
      for (const auto &c : plan.combined)
        {
          double *out = &s.inputs[c.slot * stride];
          std::fill(out, out + nq, 0.);
          for (const unsigned int p : c.parts)
            for (unsigned int q = 0; q < nq; ++q)
              out[q] += s.inputs[p * stride + q];
        }
      s.in.data        = s.inputs.data();
      s.in.stride      = stride;
      s.in.n_points    = nq;
      s.in.points      = &s.points;
      s.in.normals     = &s.normals;
      s.in.metrics     = &s.metrics;
      s.in.face_number = face;
      s.in.time        = state.time;
      s.in.time_step   = state.time_step;
    }


    /// Every term of the plan (on a face: those acting on it).
    template <int dim>
    void
    run_terms(const PlanOf<dim> &plan,
              ScratchOf<dim>    &s,
              const bool         want_residual,
              const bool         want_matrix)
    {
      const std::size_t stride = s.in.stride;
      s.residuals.assign(plan.declaration.residuals.size() * stride, 0.);
      s.jacobians.assign(
        want_matrix ? plan.declaration.jacobians.size() * stride : 0, 0.);
      auto &out         = s.coefficients_out;
      out.residual_data = s.residuals.data();
      out.jacobian_data = s.jacobians.data();
      out.stride        = stride;
      out.with_matrix   = want_matrix;
      out.with_residual = want_residual;
      for (unsigned int k = 0; k < plan.terms.size(); ++k)
        {
          const auto *t = plan.terms[k];
          if (s.in.face_number >= 0 && !t->acts_on_face(s.in.face_number))
            continue;
          s.in.input_map   = plan.maps[k].inputs.data();
          out.residual_map = plan.maps[k].residuals.data();
          out.jacobian_map = plan.maps[k].jacobians.data();
          t->evaluate(s.in, out);
        }
    }


    /// Local residual += the residual coefficients against the test
    /// functions.
    template <int dim>
    void
    integrate_residual(const PlanOf<dim>           &plan,
                       ScratchOf<dim>              &s,
                       const SplineDofHandler<dim> &dofs,
                       const int                    face,
                       const bool                   tables,
                       Vector<double>              &rhs)
    {
      const auto        &values = face < 0 ? s.cell : s.face;
      const unsigned int nq     = s.n_q;
      const std::size_t  stride = s.in.stride;
      for (unsigned int r = 0; r < plan.declaration.residuals.size(); ++r)
        for (unsigned int q = 0; q < nq; ++q)
          s.residuals[r * stride + q] *= s.JxW[q];
      for (const auto &rc : plan.residual_components)
        {
          const SplineCellValues<dim> &cv
            = values[plan.system_space[rc.component]];
          double *b = &rhs(dofs.local_offset(rc.component));
          if (tables)
            {
              for (const auto &[alpha, slot] : rc.atoms)
                for (unsigned int i = 0; i < cv.n_basis_per_element(); ++i)
                  for (unsigned int q = 0; q < nq; ++q)
                    b[i] += tabulated(cv, alpha, i, q)
                            * s.residuals[slot * stride + q];
              continue;
            }
          s.atoms.clear();
          for (const auto &[alpha, slot] : rc.atoms)
            s.atoms.push_back({alpha, &s.residuals[slot * stride]});
          TensorProductKernel<dim>::integrate(cv.tensor_product_factors(),
                                              s.atoms,
                                              b,
                                              s.workspace);
        }
    }


    /// Whether the pairs of a diagonal block form a symmetric matrix: every
    /// (a, b, C) has its partner (b, a, C).
    template <int dim>
    bool
    symmetric_pairs(
      const std::vector<typename TensorProductKernel<dim>::Pair> &pairs,
      const unsigned int                                          n_q)
    {
      for (const auto &p : pairs)
        {
          if (p.test == p.trial)
            continue;
          const auto partner
            = std::find_if(pairs.begin(), pairs.end(), [&](const auto &o) {
                return o.test == p.trial && o.trial == p.test;
              });
          if (partner == pairs.end()
              || !std::equal(p.coefficient,
                             p.coefficient + n_q,
                             partner->coefficient))
            return false;
        }
      return true;
    }


    /// Local matrix += the Jacobian coefficients (with the factors of the
    /// state) against test and trial functions, block by block.
    template <int dim>
    void
    integrate_jacobian(const PlanOf<dim>           &plan,
                       ScratchOf<dim>              &s,
                       const SplineDofHandler<dim> &dofs,
                       const AssemblyState         &state,
                       const int                    face,
                       const bool                   tables,
                       FullMatrix<double>          &A)
    {
      const auto        &values = face < 0 ? s.cell : s.face;
      const unsigned int nq     = s.n_q;
      const std::size_t  stride = s.in.stride;
      s.coefficients.resize(plan.n_pairs * stride);
      const auto factor = [&](const FieldSource src, const unsigned int k) {
        const auto &f
          = src == FieldSource::rate ? state.rate_factor : state.value_factor;
        return f.empty() ? (src == FieldSource::rate ? 0. : 1.) : f[k];
      };
      unsigned int next = 0;
      for (const auto &block : plan.blocks)
        {
          s.pairs.clear();
          for (const auto &pair : block.pairs)
            {
              double *c = &s.coefficients[next++ * stride];
              std::fill(c, c + nq, 0.);
              bool any = false;
              for (const auto &contribution : pair.contributions)
                {
                  const double w
                    = factor(contribution.source, block.trial_component);
                  if (w == 0.)
                    continue;
                  any             = true;
                  const double *j = &s.jacobians[contribution.slot * stride];
                  for (unsigned int q = 0; q < nq; ++q)
                    c[q] += w * j[q];
                }
              if (!any)
                continue;
              for (unsigned int q = 0; q < nq; ++q)
                c[q] *= s.JxW[q];
              s.pairs.push_back({pair.test, pair.trial, c});
            }
          if (s.pairs.empty())
            continue;
          const unsigned int row = dofs.local_offset(block.test_component);
          const unsigned int col = dofs.local_offset(block.trial_component);
          const SplineCellValues<dim> &vt
            = values[plan.system_space[block.test_component]];
          const SplineCellValues<dim> &vs
            = values[plan.system_space[block.trial_component]];
          if (tables)
            {
              for (const auto &p : s.pairs)
                for (unsigned int i = 0; i < vt.n_basis_per_element(); ++i)
                  for (unsigned int j = 0; j < vs.n_basis_per_element(); ++j)
                    {
                      double sum = 0;
                      for (unsigned int q = 0; q < nq; ++q)
                        sum += tabulated(vt, p.test, i, q) * p.coefficient[q]
                               * tabulated(vs, p.trial, j, q);
                      A(row + i, col + j) += sum;
                    }
              continue;
            }
          const bool symmetric = block.test_component == block.trial_component
                                 && symmetric_pairs<dim>(s.pairs, nq);
          TensorProductKernel<dim>::integrate_matrix(
            vt.tensor_product_factors(),
            vs.tensor_product_factors(),
            s.pairs,
            symmetric,
            &A(row, col),
            A.n(),
            s.workspace);
        }
    }
  } // namespace


  template <int dim>
  SystemAssembler<dim>::SystemAssembler(
    const SplineDofHandler<dim>              &dofs,
    const Quadrature<1>                      &quadrature_1d,
    std::shared_ptr<const NurbsGeometry<dim>> geometry)
    : dofs(dofs)
    , quadrature(quadrature_1d)
    , geometry(geometry)
  {
    rebuild_plans();
  }


  template <int dim>
  SystemAssembler<dim>::~SystemAssembler() = default;


  template <int dim>
  unsigned int
  SystemAssembler<dim>::add_auxiliary_field(
    const SplineDofHandler<dim> &auxiliary)
  {
    auxiliary_dofs.push_back(&auxiliary);
    rebuild_plans();
    return auxiliary_dofs.size() - 1;
  }


  template <int dim>
  void
  SystemAssembler<dim>::add_term(Term<dim> &term)
  {
    terms.push_back(&term);
    rebuild_plans();
  }


  template <int dim>
  void
  SystemAssembler<dim>::clear_terms()
  {
    terms.clear();
    rebuild_plans();
  }


  template <int dim>
  void
  SystemAssembler<dim>::rebuild_plans()
  {
    std::vector<Term<dim> *> cell_terms, face_terms;
    for (auto *t : terms)
      (t->domain() == Term<dim>::Domain::cell ? cell_terms : face_terms)
        .push_back(t);
    cell_plan = make_plan<dim>(dofs, auxiliary_dofs, cell_terms, {});
    face_plan = make_plan<dim>(dofs, auxiliary_dofs, face_terms, {});
  }


  template <int dim>
  void
  SystemAssembler<dim>::assemble(const AssemblyState             &state,
                                 const AffineConstraints<double> &constraints,
                                 TrilinosWrappers::MPI::Vector   *residual,
                                 TrilinosWrappers::SparseMatrix  *matrix) const
  {
    const bool         tables  = bool(geometry);
    const unsigned int n_local = dofs.n_element_dofs();
    const unsigned int order
      = std::max({1u, cell_plan->max_order, face_plan->max_order});
    if (matrix)
      *matrix = 0;
    if (residual)
      *residual = 0;
    const auto &space = dofs.get_space();

    const auto worker = [&](const std::vector<unsigned int>::const_iterator &e,
                            Scratch                                         &s,
                            CopyData &copy) {
      copy.matrix.reinit(matrix ? n_local : 0, matrix ? n_local : 0);
      copy.rhs.reinit(residual ? n_local : 0);
      dofs.element_dof_indices(*e, copy.indices);
      s.aux_indices.resize(auxiliary_dofs.size());
      for (unsigned int a = 0; a < auxiliary_dofs.size(); ++a)
        auxiliary_dofs[a]->element_dof_indices(*e, s.aux_indices[a]);
      const auto process = [&](const Plan &plan, const int face) {
        reinit_geometry<dim>(plan, s, *e, face, tables);
        evaluate_inputs<dim>(
          plan, s, state, dofs, auxiliary_dofs, copy.indices, face, tables);
        s.in.element_index = *e;
        run_terms<dim>(plan, s, residual, matrix);
        if (residual)
          integrate_residual<dim>(plan, s, dofs, face, tables, copy.rhs);
        if (matrix)
          integrate_jacobian<dim>(
            plan, s, dofs, state, face, tables, copy.matrix);
      };
      if (!cell_plan->terms.empty())
        process(*cell_plan, -1);
      for (unsigned int f = 0; f < 2 * dim && !face_plan->terms.empty(); ++f)
        if (space.element_at_face(*e, f)
            && std::any_of(face_plan->terms.begin(),
                           face_plan->terms.end(),
                           [f](const Term<dim> *t) {
                             return t->acts_on_face(f);
                           }))
          process(*face_plan, f);
    };
    ElementScatter scatter(constraints, matrix, residual);
    const auto     copier = [&](const CopyData &copy) {
      scatter.add(copy.matrix, copy.rhs, copy.indices);
    };
    const auto &elements = dofs.get_mesh().locally_owned_elements();
    WorkStream::run(elements.begin(),
                    elements.end(),
                    worker,
                    copier,
                    Scratch(cell_plan->spaces, geometry, quadrature, order),
                    CopyData());
    if (matrix)
      matrix->compress(VectorOperation::add);
    if (residual)
      residual->compress(VectorOperation::add);
  }


  template <int dim>
  std::vector<double>
  SystemAssembler<dim>::integrate(
    const std::vector<Integrand<dim> *> &integrands,
    const AssemblyState                 &state) const
  {
    const auto plan   = make_plan<dim>(dofs, auxiliary_dofs, {}, integrands);
    const bool tables = bool(geometry);
    Scratch    s(plan->spaces,
              geometry,
              quadrature,
              std::max(1u, plan->max_order));
    std::vector<unsigned int> first(1, 0);
    for (const auto *i : integrands)
      first.push_back(first.back() + i->n_values());
    std::vector<double>                  sums(first.back(), 0.);
    std::vector<types::global_dof_index> indices;
    s.aux_indices.resize(auxiliary_dofs.size());
    for (const unsigned int e : dofs.get_mesh().locally_owned_elements())
      {
        dofs.element_dof_indices(e, indices);
        for (unsigned int a = 0; a < auxiliary_dofs.size(); ++a)
          auxiliary_dofs[a]->element_dof_indices(e, s.aux_indices[a]);
        reinit_geometry<dim>(*plan, s, e, -1, tables);
        evaluate_inputs<dim>(
          *plan, s, state, dofs, auxiliary_dofs, indices, -1, tables);
        s.in.element_index = e;
        for (unsigned int k = 0; k < integrands.size(); ++k)
          {
            s.in.input_map = plan->integrand_maps[k].inputs.data();
            integrands[k]->integrate(s.in, s.JxW.data(), &sums[first[k]]);
          }
      }
    Utilities::MPI::sum(sums, dofs.get_mesh().get_communicator(), sums);
    return sums;
  }

  template class SystemAssembler<2>;
  template class SystemAssembler<3>;
} // namespace vesicle_iga
