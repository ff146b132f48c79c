#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <vesicle_iga/solvers/restricted_schwarz_ilu.h>
#include <vesicle_iga/solvers/spline_multigrid.h>

#include <algorithm>
#include <sstream>

namespace vesicle_iga
{
  using namespace dealii;

  const char *
  SplineMultigridParameters::smoother_names()
  {
    return "ssor|chebyshev|ilu|schwarz-ilu";
  }


  std::string
  SplineMultigridParameters::smoother_documentation()
  {
    return "ssor (symmetric Gauss-Seidel on each rank), chebyshev (a "
           "polynomial of degree 'Sweeps' in the Jacobi-scaled matrix), "
           "ilu (ILU(0) on each rank: the strongest on one rank, but the "
           "Krylov count grows with the ranks) or schwarz-ilu (ILU(0) on "
           "each rank's unknowns extended by layers of matrix neighbours "
           "('Overlap' where declared, else one), restricted additive "
           "Schwarz: ILU(0) on one rank, "
           "counts nearly independent of the ranks; not symmetric, so not "
           "with CG).";
  }


  void
  SplineMultigridParameters::declare(ParameterHandler  &prm,
                                     const std::string &default_smoother,
                                     const std::string &default_sweeps)
  {
    prm.enter_subsection("Multigrid");
    prm.declare_entry("Smoother",
                      default_smoother,
                      Patterns::Selection(smoother_names()),
                      "Smoother on every level but the coarsest: "
                        + smoother_documentation());
    prm.declare_entry("Sweeps",
                      default_sweeps,
                      Patterns::Integer(1, 20),
                      "Pre- and post-smoothing sweeps (ssor, ilu, "
                      "schwarz-ilu), or the Chebyshev degree.");
    prm.declare_entry("Coarse size",
                      "0",
                      Patterns::Integer(0),
                      "Coarsen until a level has at most this many unknowns "
                      "(or no direction can be coarsened); that level is "
                      "solved by sparse LU. 0: 4000 in 2D, 1000 in 3D (the "
                      "LU of a 3D spline matrix fills in much more).");
    prm.declare_entry("SSOR relaxation",
                      "1.0",
                      Patterns::Double(0.1, 1.9),
                      "Relaxation factor omega of the SSOR smoother.");
    prm.declare_entry("Overlap",
                      "1",
                      Patterns::Integer(0, 4),
                      "Smoother schwarz-ilu: layers of matrix neighbours "
                      "added to each rank's unknowns (0: the same as ilu).");
    prm.leave_subsection();
  }


  void
  SplineMultigridParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Multigrid");
    smoother        = prm.get("Smoother");
    sweeps          = prm.get_integer("Sweeps");
    coarse_size     = prm.get_integer("Coarse size");
    ssor_relaxation = prm.get_double("SSOR relaxation");
    overlap         = prm.get_integer("Overlap");
    prm.leave_subsection();
  }


  template <int dim>
  struct SplineMultigrid<dim>::Level
  {
    std::array<KnotVector, dim>   knot_vectors;
    std::array<unsigned int, dim> n_basis;
    /// Unknowns per basis function; natural index = basis * nc + component.
    unsigned int nc = 1;
    /// Level unknown of each natural basis index (invalid: not kept).
    std::vector<types::global_dof_index> index;
    types::global_dof_index              n_unknowns = 0;
    /// The natural index of each level unknown (inverse of index): the
    /// order in which the schwarz-ilu smoother factors.
    std::vector<types::global_dof_index> natural;
    IndexSet                             owned;
    /// From the next coarser level to this one (empty on level 0).
    TrilinosWrappers::SparseMatrix                      prolongation;
    TrilinosWrappers::SparseMatrix                      galerkin_matrix;
    const TrilinosWrappers::SparseMatrix               *matrix = nullptr;
    std::unique_ptr<TrilinosWrappers::PreconditionBase> smoother;
    std::unique_ptr<SolverControl>                      direct_control;
    std::unique_ptr<TrilinosWrappers::SolverDirect>     direct;
    mutable TrilinosWrappers::MPI::Vector               x, b, r, t;

    /// The tensor-product index of the basis function of natural index i.
    std::array<unsigned int, dim>
    multi_index(unsigned int i) const
    {
      i /= nc;
      std::array<unsigned int, dim> m;
      for (unsigned int d = 0; d < dim; ++d)
        {
          m[d] = i % n_basis[d];
          i /= n_basis[d];
        }
      return m;
    }
    unsigned int
    n_natural() const
    {
      unsigned int n = nc;
      for (unsigned int d = 0; d < dim; ++d)
        n *= n_basis[d];
      return n;
    }
  };


  template <int dim>
  SplineMultigrid<dim>::SplineMultigrid(
    const SplineDofHandler<dim>     &dofs,
    const AffineConstraints<double> &constraints,
    const SplineMultigridParameters &parameters)
    : prm(parameters)
    , communicator(dofs.get_mesh().get_communicator())
  {
    AssertThrow(dofs.n_components() == 1,
                ExcMessage("SplineMultigrid: scalar fields only."));
    setup(
      dofs.get_space(),
      1,
      [&](const unsigned int i, const unsigned int) {
        return dofs.dof_index(i);
      },
      dofs.locally_owned_dofs(),
      [&](const types::global_dof_index g) {
        if (!constraints.is_constrained(g))
          return false;
        AssertThrow(!constraints.is_inhomogeneously_constrained(g)
                      && constraints.get_constraint_entries(g)->empty(),
                    ExcMessage("SplineMultigrid: only homogeneous "
                               "Dirichlet constraints (x_i = 0)."));
        return true;
      });
  }


  template <int dim>
  SplineMultigrid<dim>::SplineMultigrid(
    const SplineDofHandler<dim> &dofs,
    const unsigned int           n_components,
    const std::function<types::global_dof_index(unsigned int, unsigned int)>
                                                       &unknown,
    const IndexSet                                     &owned,
    const std::function<bool(types::global_dof_index)> &constrained,
    const SplineMultigridParameters                    &parameters)
    : prm(parameters)
    , communicator(dofs.get_mesh().get_communicator())
  {
    setup(dofs.get_space(), n_components, unknown, owned, constrained);
  }


  namespace
  {
    /// Whether a level's knot vector is halved for the next coarser one: at
    /// least 4 elements, and a periodic direction keeps at least p + 1
    /// basis functions (as many as elements), which its knot vector needs
    /// (24 x 12 x 12 periodic in x, z: the third coarsening would leave 3
    /// cubic elements in z).
    bool
    can_be_halved(const KnotVector &kv)
    {
      return kv.n_elements() >= 4
             && (!kv.is_periodic() || kv.n_elements() >= 2 * (kv.degree() + 1));
    }


    /// The prolongation between two levels, the Kronecker product of the
    /// univariate knot-insertion matrices, applied row by row without
    /// forming it: for_row calls action(J, value) for every coarse natural
    /// index J in the row of a fine basis function (the same component).
    template <int dim>
    class TensorProlongation
    {
    public:
      TensorProlongation(
        const std::array<std::vector<std::vector<double>>, dim> &univariate,
        const std::array<unsigned int, dim>                     &coarse_n_basis,
        const unsigned int                                       nc)
        : coarse_n_basis(coarse_n_basis)
        , nc(nc)
      {
        for (unsigned int d = 0; d < dim; ++d)
          {
            nonzeros[d].resize(univariate[d].size());
            for (unsigned int i = 0; i < univariate[d].size(); ++i)
              for (unsigned int j = 0; j < univariate[d][i].size(); ++j)
                if (univariate[d][i][j] != 0.)
                  nonzeros[d][i].emplace_back(j, univariate[d][i][j]);
          }
      }

      template <typename Action>
      void
      for_row(const std::array<unsigned int, dim> &fine_basis,
              const unsigned int                   component,
              const Action                        &action) const
      {
        std::array<unsigned int, dim> k{};
        while (true)
          {
            unsigned int J = component, stride = nc;
            double       v = 1;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const auto &entry = nonzeros[d][fine_basis[d]][k[d]];
                J += entry.first * stride;
                v *= entry.second;
                stride *= coarse_n_basis[d];
              }
            action(J, v);
            unsigned int d = 0;
            for (; d < dim; ++d)
              if (++k[d] < nonzeros[d][fine_basis[d]].size())
                break;
              else
                k[d] = 0;
            if (d == dim)
              return;
          }
      }

    private:
      /// Per direction and fine basis function: (coarse index, value).
      std::array<std::vector<std::vector<std::pair<unsigned int, double>>>, dim>
                                    nonzeros;
      std::array<unsigned int, dim> coarse_n_basis;
      unsigned int                  nc;
    };
  } // namespace

  template <int dim>
  void
  SplineMultigrid<dim>::setup(
    const SplineSpace<dim> &space,
    const unsigned int      nc,
    const std::function<types::global_dof_index(unsigned int, unsigned int)>
                                                       &unknown,
    const IndexSet                                     &owned,
    const std::function<bool(types::global_dof_index)> &is_constrained)
  {
    // The fine level: the caller's numbering; constrained unknowns
    // (gathered from all ranks, natural numbering) are not level unknowns.
    auto fine          = std::make_unique<Level>();
    fine->knot_vectors = space.knot_vectors();
    fine->nc           = nc;
    for (unsigned int d = 0; d < dim; ++d)
      fine->n_basis[d] = space.knot_vector(d).n_basis();
    fine->index.resize(fine->n_natural());
    fine->owned      = owned;
    fine->n_unknowns = owned.size();
    std::vector<unsigned int> constrained_here;
    for (unsigned int I = 0; I < fine->n_natural(); ++I)
      {
        const auto g   = unknown(I / nc, I % nc);
        fine->index[I] = g;
        if (fine->owned.is_element(g) && is_constrained(g))
          constrained_here.push_back(I);
      }
    std::vector<bool> constrained(fine->n_natural(), false);
    for (const auto &v :
         Utilities::MPI::all_gather(communicator, constrained_here))
      for (const unsigned int i : v)
        constrained[i] = true;

    std::vector<std::unique_ptr<Level>> top_down;
    top_down.push_back(std::move(fine));
    const unsigned int coarse_size
      = prm.coarse_size > 0 ? prm.coarse_size : (dim == 2 ? 4000u : 1000u);
    while (static_cast<unsigned int>(
             std::count(constrained.begin(), constrained.end(), false))
           > coarse_size)
      {
        auto coarse = coarser_level(*top_down.back(), constrained);
        if (!coarse)
          break;
        top_down.push_back(std::move(coarse));
      }
    // Store coarsest first; each level's prolongation maps the level below
    // (index l - 1) into it.
    for (auto it = top_down.rbegin(); it != top_down.rend(); ++it)
      levels.push_back(std::move(*it));
    for (auto &l : levels)
      {
        l->natural.assign(l->n_unknowns, numbers::invalid_dof_index);
        for (unsigned int I = 0; I < l->index.size(); ++I)
          if (l->index[I] != numbers::invalid_dof_index)
            l->natural[l->index[I]] = I;
        l->x.reinit(l->owned, communicator);
        l->b.reinit(l->owned, communicator);
        l->r.reinit(l->owned, communicator);
        l->t.reinit(l->owned, communicator);
      }
  }


  template <int dim>
  std::unique_ptr<typename SplineMultigrid<dim>::Level>
  SplineMultigrid<dim>::coarser_level(Level             &f,
                                      std::vector<bool> &constrained) const
  {
    auto c = std::make_unique<Level>();
    c->nc  = f.nc;
    bool                                              coarsened = false;
    std::array<std::vector<std::vector<double>>, dim> P1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const KnotVector &kv    = f.knot_vectors[d];
        const bool        halve = can_be_halved(kv);
        c->knot_vectors[d]      = halve ? kv.coarsened() : kv;
        coarsened               = coarsened || halve;
        c->n_basis[d]           = c->knot_vectors[d].n_basis();
        P1[d]                   = prolongation_matrix(c->knot_vectors[d], kv);
      }
    if (!coarsened)
      return nullptr;
    const TensorProlongation<dim> P(P1, c->n_basis, c->nc);

    std::vector<bool> coarse_constrained(c->n_natural(), false);
    for (unsigned int I = 0; I < f.n_natural(); ++I)
      if (constrained[I])
        P.for_row(f.multi_index(I),
                  I % f.nc,
                  [&](const unsigned int J, const double) {
                    coarse_constrained[J] = true;
                  });
    // Level unknowns: the kept functions in natural order, owned in
    // contiguous blocks.
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator);
    c->index.assign(c->n_natural(), numbers::invalid_dof_index);
    for (unsigned int J = 0; J < c->n_natural(); ++J)
      if (!coarse_constrained[J])
        c->index[J] = c->n_unknowns++;
    c->owned.set_size(c->n_unknowns);
    c->owned.add_range(c->n_unknowns * rank / n_ranks,
                       c->n_unknowns * (rank + 1) / n_ranks);
    c->owned.compress();

    // Prolongation from c to f (rows: f's owned unknowns): the pattern,
    // then the values, over the same rows.
    const auto for_owned_rows = [&](const auto &action) {
      for (unsigned int I = 0; I < f.n_natural(); ++I)
        if (!constrained[I] && f.owned.is_element(f.index[I]))
          P.for_row(f.multi_index(I),
                    I % f.nc,
                    [&](const unsigned int J, const double v) {
                      if (!coarse_constrained[J])
                        action(f.index[I], c->index[J], v);
                    });
    };
    DynamicSparsityPattern sp(f.n_unknowns, c->n_unknowns, f.owned);
    for_owned_rows([&](const types::global_dof_index i,
                       const types::global_dof_index j,
                       const double) { sp.add(i, j); });
    f.prolongation.reinit(f.owned, c->owned, sp, communicator);
    for_owned_rows([&](const types::global_dof_index i,
                       const types::global_dof_index j,
                       const double v) { f.prolongation.set(i, j, v); });
    f.prolongation.compress(VectorOperation::insert);

    constrained = std::move(coarse_constrained);
    return c;
  }


  template <int dim>
  SplineMultigrid<dim>::~SplineMultigrid() = default;


  template <int dim>
  void
  SplineMultigrid<dim>::initialize(const TrilinosWrappers::SparseMatrix &A)
  {
    levels.back()->matrix = &A;
    for (unsigned int l = levels.size() - 1; l > 0; --l)
      {
        Level                         &f = *levels[l];
        TrilinosWrappers::SparseMatrix AP;
        f.matrix->mmult(AP, f.prolongation);
        f.prolongation.Tmmult(levels[l - 1]->galerkin_matrix, AP);
        levels[l - 1]->matrix = &levels[l - 1]->galerkin_matrix;
      }
    for (unsigned int l = 1; l < levels.size(); ++l)
      {
        Level &L = *levels[l];
        // The old smoother goes first: built beside it, the new ILU
        // factors would double the smoother's memory at every set-up.
        L.smoother.reset();
        if (prm.smoother == "ssor")
          {
            auto s = std::make_unique<TrilinosWrappers::PreconditionSSOR>();
            s->initialize(*L.matrix,
                          TrilinosWrappers::PreconditionSSOR::AdditionalData(
                            prm.ssor_relaxation));
            L.smoother = std::move(s);
          }
        else if (prm.smoother == "schwarz-ilu")
          {
            auto s = std::make_unique<RestrictedSchwarzILU>();
            s->initialize(*L.matrix,
                          prm.overlap,
                          [&L](const types::global_dof_index g) {
                            return L.natural[g];
                          });
            L.smoother = std::move(s);
          }
        else if (prm.smoother == "ilu")
          {
            auto s = std::make_unique<TrilinosWrappers::PreconditionILU>();
            s->initialize(*L.matrix,
                          TrilinosWrappers::PreconditionILU::AdditionalData(0));
            L.smoother = std::move(s);
          }
        else
          {
            auto s
              = std::make_unique<TrilinosWrappers::PreconditionChebyshev>();
            TrilinosWrappers::PreconditionChebyshev::AdditionalData data;
            data.degree           = prm.sweeps;
            data.eigenvalue_ratio = 30;
            s->initialize(*L.matrix, data);
            L.smoother = std::move(s);
          }
      }
    Level &C         = *levels[0];
    C.direct_control = std::make_unique<SolverControl>(1, 0);
    C.direct
      = std::make_unique<TrilinosWrappers::SolverDirect>(*C.direct_control);
    C.direct->initialize(*C.matrix);
  }


  template <int dim>
  void
  SplineMultigrid<dim>::v_cycle(const unsigned int                   l,
                                TrilinosWrappers::MPI::Vector       &x,
                                const TrilinosWrappers::MPI::Vector &b) const
  {
    const Level &L = *levels[l];
    if (l == 0)
      {
        L.direct->solve(x, b);
        return;
      }
    const unsigned int sweeps = prm.smoother != "chebyshev" ? prm.sweeps : 1;
    const auto         smooth = [&]() {
      for (unsigned int s = 0; s < sweeps; ++s)
        {
          L.matrix->vmult(L.r, x);
          L.r.sadd(-1., 1., b);
          L.smoother->vmult(L.t, L.r);
          x += L.t;
        }
    };
    x = 0;
    smooth();
    // Coarse-grid correction.
    const Level &C = *levels[l - 1];
    L.matrix->vmult(L.r, x);
    L.r.sadd(-1., 1., b);
    L.prolongation.Tvmult(C.b, L.r);
    v_cycle(l - 1, C.x, C.b);
    L.prolongation.vmult(L.t, C.x);
    x += L.t;
    smooth();
  }


  template <int dim>
  void
  SplineMultigrid<dim>::vmult(TrilinosWrappers::MPI::Vector       &dst,
                              const TrilinosWrappers::MPI::Vector &src) const
  {
    v_cycle(levels.size() - 1, dst, src);
  }


  template <int dim>
  std::string
  SplineMultigrid<dim>::description() const
  {
    std::ostringstream s;
    s << "spline multigrid, " << levels.size() << " levels (unknowns";
    for (auto it = levels.rbegin(); it != levels.rend(); ++it)
      s << ' ' << (*it)->n_unknowns;
    s << "), " << prm.smoother << '(' << prm.sweeps << "), KLU on the "
      << "coarsest";
    return s.str();
  }

  template class SplineMultigrid<2>;
  template class SplineMultigrid<3>;
} // namespace vesicle_iga
