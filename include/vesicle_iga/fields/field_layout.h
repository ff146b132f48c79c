#pragma once

#include <vesicle_iga/spline/spline_space.h>

#include <string>
#include <vector>

namespace vesicle_iga
{
  /**
   * How a field enters the generalized-alpha method (spec 2.4, 4.9): a
   * differential field has a time derivative in its equation and is
   * evaluated at t_{n+alpha_f} (its rate at t_{n+alpha_m}); an algebraic
   * field (pressure, tension, a Lagrange multiplier field) has none and is
   * evaluated at t_{n+1} or at t_{n+alpha_f} (a parameter of the stepper).
   */
  enum class FieldKind
  {
    differential,
    algebraic
  };

  /**
   * The unknowns of a model: named fields, each with a number of scalar
   * components, on one of a list of spline spaces that share the mesh
   * (the same breakpoints; degree and continuity may differ), with a kind
   * and a block of the linear solver. Components are numbered flat: the
   * fields in the order they were added, their components in order. This
   * flat index is what terms use to address a component (kernel/term.h);
   * the parallel numbering of the unknowns is SplineDofHandler's.
   */
  template <int dim>
  class FieldLayout
  {
  public:
    struct Field
    {
      std::string  name;
      unsigned int n_components;
      unsigned int space;
      FieldKind    kind;
      unsigned int block;
      unsigned int first_component;
    };

    FieldLayout() = default;
    /// One field "u" of @p n_components on @p space (stationary problems).
    FieldLayout(const SplineSpace<dim> &space, const unsigned int n_components);

    /// Adds a space; returns its number.
    unsigned int
    add_space(const SplineSpace<dim> &space);
    /// Adds a field on space @p space; returns its number. The block
    /// defaults to the field number.
    unsigned int
    add_field(const std::string &name,
              const unsigned int n_components,
              const unsigned int space,
              const FieldKind    kind  = FieldKind::differential,
              const int          block = -1);

    unsigned int
    n_fields() const
    {
      return fields.size();
    }
    unsigned int
    n_spaces() const
    {
      return spaces.size();
    }
    unsigned int
    n_components() const
    {
      return component_field.size();
    }
    const Field &
    field(const unsigned int f) const
    {
      return fields[f];
    }
    const SplineSpace<dim> &
    space(const unsigned int s) const
    {
      return spaces[s];
    }
    /// Flat index of component c of field f.
    unsigned int
    component(const unsigned int f, const unsigned int c = 0) const
    {
      return fields[f].first_component + c;
    }
    unsigned int
    field_of_component(const unsigned int k) const
    {
      return component_field[k];
    }
    unsigned int
    space_of_component(const unsigned int k) const
    {
      return fields[component_field[k]].space;
    }
    /// The field of this name; throws if there is none.
    unsigned int
    find(const std::string &name) const;

  private:
    std::vector<SplineSpace<dim>> spaces;
    std::vector<Field>            fields;
    std::vector<unsigned int>     component_field;
  };
} // namespace vesicle_iga
