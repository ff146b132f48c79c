#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/fields/natural_numbering.h>
#include <vesicle_iga/io/field_checkpoint.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    /// What defines the discrete space of a vector: a restart needs the
    /// same (spec section 7: a checkpoint restarts the same discretisation,
    /// on any number of ranks).
    struct RecordEntry
    {
      std::string key;
      double      value;
      std::string description;
    };

    template <int dim>
    std::vector<RecordEntry>
    discretization_record(const SplineDofHandler<dim> &dofs)
    {
      const FieldLayout<dim>  &layout = dofs.get_layout();
      std::vector<RecordEntry> r;
      r.push_back({"dimension", double(dim), "dimension"});
      r.push_back({"fields", double(layout.n_fields()), "number of fields"});
      for (unsigned int f = 0; f < layout.n_fields(); ++f)
        r.push_back({"field" + std::to_string(f) + ".components",
                     double(layout.field(f).n_components),
                     "components of field '" + layout.field(f).name + "'"});
      r.push_back({"spaces", double(layout.n_spaces()), "number of spaces"});
      for (unsigned int s = 0; s < layout.n_spaces(); ++s)
        for (unsigned int d = 0; d < dim; ++d)
          {
            const KnotVector &k = layout.space(s).knot_vector(d);
            const std::string key
              = "space" + std::to_string(s) + ".direction" + std::to_string(d);
            const std::string where = " in direction " + std::to_string(d)
                                      + " of spline space " + std::to_string(s);
            const auto &z = k.breakpoints();
            r.push_back(
              {key + ".degree", double(k.degree()), "degree" + where});
            r.push_back({key + ".elements",
                         double(k.n_elements()),
                         "number of elements" + where});
            r.push_back({key + ".basis",
                         double(k.n_basis()),
                         "number of basis functions (continuity, "
                         "periodicity)"
                           + where});
            r.push_back({key + ".lower", z.front(), "lower end" + where});
            r.push_back({key + ".upper", z.back(), "upper end" + where});
          }
      return r;
    }
  } // namespace


  template <int dim>
  void
  save_field(Checkpoint                                  &checkpoint,
             const std::string                           &name,
             const SplineDofHandler<dim>                 &dofs,
             const dealii::TrilinosWrappers::MPI::Vector &v)
  {
    // Each rank its own entries: no rank holds the whole field.
    FieldPart &part = checkpoint.fields[name];
    part.size       = dofs.n_dofs();
    part.natural_indices.clear();
    part.values.clear();
    for (const auto &[natural, dof] : owned_natural_entries(dofs))
      {
        part.natural_indices.push_back(natural);
        part.values.push_back(v[dof]);
      }
    for (const auto &entry : discretization_record(dofs))
      checkpoint.scalars[name + ".discretization." + entry.key] = entry.value;
  }


  template <int dim>
  void
  load_field(const Checkpoint                      &checkpoint,
             const std::string                     &name,
             const SplineDofHandler<dim>           &dofs,
             dealii::TrilinosWrappers::MPI::Vector &v)
  {
    // Files of format 2 and 3 hold the field as a vector on every rank.
    const bool        field = checkpoint.has_field(name);
    const std::size_t size  = field ? checkpoint.fields.at(name).size :
                                      checkpoint.vector(name).size();
    // Checkpoints of format 2 have no record; their size is checked below.
    for (const auto &entry : discretization_record(dofs))
      {
        const auto it
          = checkpoint.scalars.find(name + ".discretization." + entry.key);
        if (it == checkpoint.scalars.end())
          continue;
        const double tolerance = 1e-12 * std::max(1., std::abs(entry.value));
        check_input(std::abs(it->second - entry.value) <= tolerance,
                    "Restart from",
                    checkpoint.source,
                    "a checkpoint of the same discretisation: '" + name
                      + "' was written with " + entry.description + " = "
                      + value_text(it->second) + ", this run has "
                      + value_text(entry.value));
      }
    check_input(size == dofs.n_dofs(),
                "Restart from",
                checkpoint.source,
                "a checkpoint of the same mesh, degree and fields ('" + name
                  + "' has " + std::to_string(size) + " unknowns, this run "
                  + std::to_string(dofs.n_dofs()) + ")");
    if (field)
      {
        // Each rank reads its own entries.
        const auto                 entries = owned_natural_entries(dofs);
        std::vector<std::uint64_t> natural_indices;
        natural_indices.reserve(entries.size());
        for (const auto &entry : entries)
          natural_indices.push_back(entry.first);
        const std::vector<double> values
          = checkpoint.read_field(name,
                                  natural_indices,
                                  dofs.get_mesh().get_communicator());
        for (std::size_t k = 0; k < entries.size(); ++k)
          v[entries[k].second] = values[k];
        v.compress(VectorOperation::insert);
      }
    else
      scatter_natural(dofs, checkpoint.vector(name), v);
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
