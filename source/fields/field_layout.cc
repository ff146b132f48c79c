#include <deal.II/base/exceptions.h>

#include <vesicle_iga/fields/field_layout.h>

#include <stdexcept>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  FieldLayout<dim>::FieldLayout(const SplineSpace<dim> &space,
                                const unsigned int      n_components)
  {
    add_space(space);
    add_field("u", n_components, 0);
  }


  template <int dim>
  unsigned int
  FieldLayout<dim>::add_space(const SplineSpace<dim> &space)
  {
    if (!spaces.empty())
      for (unsigned int d = 0; d < dim; ++d)
        AssertThrow(space.knot_vector(d).breakpoints()
                      == spaces[0].knot_vector(d).breakpoints(),
                    dealii::ExcMessage(
                      "All spaces of a field layout share the mesh: the "
                      "same breakpoints in every direction."));
    spaces.push_back(space);
    return spaces.size() - 1;
  }


  template <int dim>
  unsigned int
  FieldLayout<dim>::add_field(const std::string &name,
                              const unsigned int n_components,
                              const unsigned int space,
                              const FieldKind    kind,
                              const int          block)
  {
    AssertThrow(space < spaces.size(),
                dealii::ExcMessage("Field " + name + ": no such space."));
    AssertThrow(n_components > 0,
                dealii::ExcMessage("Field " + name + ": no components."));
    const unsigned int f = fields.size();
    fields.push_back({name,
                      n_components,
                      space,
                      kind,
                      block < 0 ? f : static_cast<unsigned int>(block),
                      static_cast<unsigned int>(component_field.size())});
    for (unsigned int c = 0; c < n_components; ++c)
      component_field.push_back(f);
    return f;
  }


  template <int dim>
  unsigned int
  FieldLayout<dim>::find(const std::string &name) const
  {
    for (unsigned int f = 0; f < fields.size(); ++f)
      if (fields[f].name == name)
        return f;
    // A model asked for a field it did not add: a programming error, not
    // bad input, reported with the name it looked for.
    throw std::invalid_argument("FieldLayout::find: no field named '" + name
                                + "'");
  }

  template class FieldLayout<1>;
  template class FieldLayout<2>;
  template class FieldLayout<3>;
} // namespace vesicle_iga
