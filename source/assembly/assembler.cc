#include <deal.II/base/mpi.h>
#include <deal.II/base/work_stream.h>

#include <vesicle_iga/assembly/assembler.h>

namespace vesicle_iga
{
  namespace
  {
    template <int dim>
    struct ScratchData
    {
      ScratchData(const SplineSpace<dim>                   &space,
                  std::shared_ptr<const NurbsGeometry<dim>> geometry,
                  const Quadrature<1>                      &q,
                  const unsigned int                        order,
                  const bool                                shape_tables)
        : cell(space, geometry, q, order, shape_tables)
        , face(space, geometry, q, order)
      {}
      SplineCellValues<dim> cell;
      SplineCellValues<dim> face;
    };

    struct CopyData
    {
      FullMatrix<double>                   matrix;
      Vector<double>                       rhs;
      std::vector<types::global_dof_index> indices;
    };
  } // namespace


  namespace
  {
    template <int dim>
    void
    assemble(const SplineDofHandler<dim>                  &dof_handler,
             std::shared_ptr<const NurbsGeometry<dim>>     geometry,
             const Quadrature<1>                          &quadrature_1d,
             const std::vector<const AssemblyTerm<dim> *> &terms,
             const AffineConstraints<double>              &constraints,
             TrilinosWrappers::SparseMatrix               *matrix,
             TrilinosWrappers::MPI::Vector                &rhs)
    {
      const SplineSpace<dim> &space        = dof_handler.get_space();
      unsigned int            order        = 0;
      bool                    shape_tables = false;
      for (const auto *t : terms)
        {
          order        = std::max(order, t->derivative_order());
          shape_tables = shape_tables || t->needs_shape_tables();
        }
      const unsigned int n_local
        = space.n_basis_per_element() * dof_handler.n_components();

      if (matrix)
        *matrix = 0;
      rhs = 0;
      const auto worker
        = [&](const std::vector<unsigned int>::const_iterator &e,
              ScratchData<dim>                                &scratch,
              CopyData                                        &copy) {
            copy.matrix.reinit(matrix ? n_local : 0, matrix ? n_local : 0);
            copy.rhs.reinit(n_local);
            dof_handler.element_dof_indices(*e, copy.indices);
            scratch.cell.reinit(*e);
            for (const auto *t : terms)
              t->assemble_cell(scratch.cell, copy.matrix, copy.rhs);
            for (unsigned int f = 0; f < 2 * dim; ++f)
              if (space.element_at_face(*e, f))
                {
                  bool active = false;
                  for (const auto *t : terms)
                    active = active || t->acts_on_face(f);
                  if (!active)
                    continue;
                  scratch.face.reinit_face(*e, f);
                  for (const auto *t : terms)
                    if (t->acts_on_face(f))
                      t->assemble_face(f, scratch.face, copy.matrix, copy.rhs);
                }
          };
      const auto copier = [&](const CopyData &copy) {
        if (matrix)
          constraints.distribute_local_to_global(
            copy.matrix, copy.rhs, copy.indices, *matrix, rhs);
        else
          constraints.distribute_local_to_global(copy.rhs, copy.indices, rhs);
      };
      const auto &elements = dof_handler.get_mesh().locally_owned_elements();
      WorkStream::run(
        elements.begin(),
        elements.end(),
        worker,
        copier,
        ScratchData<dim>(space, geometry, quadrature_1d, order, shape_tables),
        CopyData());
      if (matrix)
        matrix->compress(VectorOperation::add);
      rhs.compress(VectorOperation::add);
    }
  } // namespace


  template <int dim>
  void
  assemble_linear_system(const SplineDofHandler<dim>              &dof_handler,
                         std::shared_ptr<const NurbsGeometry<dim>> geometry,
                         const Quadrature<1> &quadrature_1d,
                         const std::vector<const AssemblyTerm<dim> *> &terms,
                         const AffineConstraints<double> &constraints,
                         TrilinosWrappers::SparseMatrix  &matrix,
                         TrilinosWrappers::MPI::Vector   &rhs)
  {
    assemble<dim>(
      dof_handler, geometry, quadrature_1d, terms, constraints, &matrix, rhs);
  }


  template <int dim>
  void
  assemble_vector(const SplineDofHandler<dim>                  &dof_handler,
                  std::shared_ptr<const NurbsGeometry<dim>>     geometry,
                  const Quadrature<1>                          &quadrature_1d,
                  const std::vector<const AssemblyTerm<dim> *> &terms,
                  const AffineConstraints<double>              &constraints,
                  TrilinosWrappers::MPI::Vector                &rhs)
  {
    assemble<dim>(
      dof_handler, geometry, quadrature_1d, terms, constraints, nullptr, rhs);
  }


  template <int dim>
  void
  get_element_coefficients(const SplineDofHandler<dim>         &dof_handler,
                           const TrilinosWrappers::MPI::Vector &ghosted,
                           const unsigned int                   element,
                           std::vector<std::vector<double>>    &c)
  {
    std::vector<types::global_dof_index> indices;
    dof_handler.element_dof_indices(element, indices);
    const unsigned int nc = dof_handler.n_components();
    const unsigned int m  = indices.size() / nc;
    c.resize(nc);
    for (unsigned int k = 0; k < nc; ++k)
      {
        c[k].resize(m);
        for (unsigned int j = 0; j < m; ++j)
          c[k][j] = ghosted[indices[k * m + j]];
      }
  }


  template <int dim>
  std::vector<double>
  integrate_field(
    const SplineDofHandler<dim>                      &dof_handler,
    std::shared_ptr<const NurbsGeometry<dim>>         geometry,
    const Quadrature<1>                              &quadrature_1d,
    const unsigned int                                order,
    const TrilinosWrappers::MPI::Vector              &ghosted,
    const unsigned int                                n_sums,
    const std::function<void(const SplineCellValues<dim> &,
                             const unsigned int,
                             const std::vector<std::vector<double>> &,
                             std::vector<double> &)> &integrand)
  {
    SplineCellValues<dim>            values(dof_handler.get_space(),
                                 geometry,
                                 quadrature_1d,
                                 order);
    std::vector<double>              sums(n_sums, 0.);
    std::vector<std::vector<double>> c;
    for (const unsigned int e : dof_handler.get_mesh().locally_owned_elements())
      {
        values.reinit(e);
        get_element_coefficients(dof_handler, ghosted, e, c);
        for (unsigned int q = 0; q < values.n_quadrature_points(); ++q)
          integrand(values, q, c, sums);
      }
    Utilities::MPI::sum(sums, dof_handler.get_mesh().get_communicator(), sums);
    return sums;
  }

#define INSTANTIATE(dim)                                               \
  template void assemble_linear_system(                                \
    const SplineDofHandler<dim> &,                                     \
    std::shared_ptr<const NurbsGeometry<dim>>,                         \
    const Quadrature<1> &,                                             \
    const std::vector<const AssemblyTerm<dim> *> &,                    \
    const AffineConstraints<double> &,                                 \
    TrilinosWrappers::SparseMatrix &,                                  \
    TrilinosWrappers::MPI::Vector &);                                  \
  template void assemble_vector(                                       \
    const SplineDofHandler<dim> &,                                     \
    const std::shared_ptr<const NurbsGeometry<dim>>,                   \
    const Quadrature<1> &,                                             \
    const std::vector<const AssemblyTerm<dim> *> &,                    \
    const AffineConstraints<double> &,                                 \
    TrilinosWrappers::MPI::Vector &);                                  \
  template std::vector<double> integrate_field(                        \
    const SplineDofHandler<dim> &,                                     \
    std::shared_ptr<const NurbsGeometry<dim>>,                         \
    const Quadrature<1> &,                                             \
    const unsigned int,                                                \
    const TrilinosWrappers::MPI::Vector &,                             \
    const unsigned int,                                                \
    const std::function<void(const SplineCellValues<dim> &,            \
                             const unsigned int,                       \
                             const std::vector<std::vector<double>> &, \
                             std::vector<double> &)> &);               \
  template void get_element_coefficients(                              \
    const SplineDofHandler<dim> &,                                     \
    const TrilinosWrappers::MPI::Vector &,                             \
    const unsigned int,                                                \
    std::vector<std::vector<double>> &);
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace vesicle_iga
