#pragma once

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vesicle_iga/spline/spline_cell_values.h>

namespace vesicle_iga
{
  /**
   * One term of a weak form: its contribution to the element matrix and
   * right-hand side, on the element and on the element's boundary faces.
   * The assembler (assemble_linear_system) loops over the elements and asks
   * every active term for its share; a model is a list of terms, and a term
   * lives in one file under terms/. Local indices are
   * component * n_basis_per_element + j.
   */
  template <int dim>
  class AssemblyTerm
  {
  public:
    virtual ~AssemblyTerm() = default;

    /// The highest derivative order of the basis this term needs.
    virtual unsigned int
    derivative_order() const = 0;

    /// Whether assemble_cell reads the full basis tables of
    /// SplineCellValues; a term that works on the univariate factors by
    /// sum factorisation returns false and saves their computation.
    virtual bool
    needs_shape_tables() const
    {
      return true;
    }

    virtual void
    assemble_cell(const SplineCellValues<dim> & /*values*/,
                  FullMatrix<double> & /*matrix*/,
                  Vector<double> & /*rhs*/) const
    {}

    /// Whether assemble_face has anything to add on boundary face f.
    virtual bool
    acts_on_face(const unsigned int /*face*/) const
    {
      return false;
    }

    virtual void
    assemble_face(const unsigned int /*face*/,
                  const SplineCellValues<dim> & /*face_values*/,
                  FullMatrix<double> & /*matrix*/,
                  Vector<double> & /*rhs*/) const
    {}
  };
} // namespace vesicle_iga
