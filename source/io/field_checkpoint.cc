#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/io/field_checkpoint.h>
#include <vesicle_iga/parallel/natural_numbering.h>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  void
  save_field(Checkpoint                                  &checkpoint,
             const std::string                           &name,
             const SplineDofHandler<dim>                 &dofs,
             const dealii::TrilinosWrappers::MPI::Vector &v)
  {
    checkpoint.vectors[name] = gather_natural(dofs, v);
  }


  template <int dim>
  void
  load_field(const Checkpoint                      &checkpoint,
             const std::string                     &name,
             const SplineDofHandler<dim>           &dofs,
             dealii::TrilinosWrappers::MPI::Vector &v)
  {
    const auto &natural = checkpoint.vector(name);
    check_input(natural.size() == dofs.n_dofs(),
                "Restart from",
                checkpoint.source,
                "a checkpoint of the same mesh, degree and fields ('" + name
                  + "' has " + std::to_string(natural.size())
                  + " unknowns, this run " + std::to_string(dofs.n_dofs())
                  + ")");
    scatter_natural(dofs, natural, v);
  }

#define INSTANTIATE(dim)                                                   \
  template void save_field(Checkpoint &,                                   \
                           const std::string &,                            \
                           const SplineDofHandler<dim> &,                  \
                           const dealii::TrilinosWrappers::MPI::Vector &); \
  template void load_field(const Checkpoint &,                             \
                           const std::string &,                            \
                           const SplineDofHandler<dim> &,                  \
                           dealii::TrilinosWrappers::MPI::Vector &);
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace vesicle_iga
