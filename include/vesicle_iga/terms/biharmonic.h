#pragma once

#include <deal.II/base/function.h>

#include <vesicle_iga/assembly/assembly_term.h>
#include <vesicle_iga/assembly/boundary_selection.h>

namespace vesicle_iga
{
  /**
   * Primal H^2 form of the biharmonic equation Delta^2 u = f on a C^1 (or
   * smoother) spline space: (Delta v, Delta u) - (v, f). No mixed variable:
   * the basis Hessians come straight from the spline space.
   */
  template <int dim>
  class BiharmonicTerm : public AssemblyTerm<dim>
  {
  public:
    explicit BiharmonicTerm(const Function<dim> &f)
      : f(f)
    {}
    unsigned int
    derivative_order() const override
    {
      return 2;
    }
    void
    assemble_cell(const SplineCellValues<dim> &v,
                  FullMatrix<double>          &A,
                  Vector<double>              &b) const override;

  private:
    const Function<dim> &f;
  };

  /**
   * Simply supported edge: u = g strongly, Delta u = m naturally. Integrating
   * (Delta^2 u, v) by parts twice with v = 0 on the edge leaves the boundary
   * term (Delta u, dv/dn), so the right-hand side gains (m, dv/dn).
   */
  template <int dim>
  class BoundaryLaplacianTerm : public AssemblyTerm<dim>
  {
  public:
    BoundaryLaplacianTerm(const BoundarySelection<dim> &selection,
                          const Function<dim>          &m)
      : selection(selection)
      , m(m)
    {}
    unsigned int
    derivative_order() const override
    {
      return 1;
    }
    bool
    acts_on_face(const unsigned int face) const override
    {
      return selection.touches_face(face);
    }
    void
    assemble_face(const unsigned int           face,
                  const SplineCellValues<dim> &v,
                  FullMatrix<double>          &A,
                  Vector<double>              &b) const override;

  private:
    const BoundarySelection<dim> selection;
    const Function<dim>         &m;
  };
} // namespace vesicle_iga
