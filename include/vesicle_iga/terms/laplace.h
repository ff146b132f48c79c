#pragma once

#include <deal.II/base/function.h>

#include <vesicle_iga/assembly/assembly_term.h>
#include <vesicle_iga/assembly/boundary_selection.h>

#include <functional>

namespace vesicle_iga
{
  /// (grad v, grad u) - (v, f): the Poisson operator -div grad u = f.
  template <int dim>
  class LaplaceTerm : public AssemblyTerm<dim>
  {
  public:
    explicit LaplaceTerm(const Function<dim> &f)
      : f(f)
    {}
    unsigned int
    derivative_order() const override
    {
      return 1;
    }
    void
    assemble_cell(const SplineCellValues<dim> &v,
                  FullMatrix<double>          &A,
                  Vector<double>              &b) const override;

  private:
    const Function<dim> &f;
  };

  /**
   * Nitsche's weak Dirichlet condition u = g on the selected boundary
   * (symmetric variant):
   *   -(dv/dn, u) - (v, du/dn) + (C/h_n) (v, u)
   *     = -(dv/dn, g) + (C/h_n) (v, g),
   * with h_n the element size normal to the face. Coercive for C above the
   * inverse-estimate constant of the space.
   */
  template <int dim>
  class NitscheDirichletTerm : public AssemblyTerm<dim>
  {
  public:
    NitscheDirichletTerm(const BoundarySelection<dim> &selection,
                         const Function<dim>          &g,
                         const double                  penalty)
      : selection(selection)
      , g(g)
      , penalty(penalty)
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
    const Function<dim>         &g;
    const double                 penalty;
  };

  /// Natural condition of the Poisson problem: (v, q.n) where @p where
  /// holds, with q a prescribed flux vector (q = grad u for a known
  /// solution).
  template <int dim>
  class NeumannTerm : public AssemblyTerm<dim>
  {
  public:
    NeumannTerm(std::function<bool(unsigned int, const Point<dim> &)> where,
                std::function<Tensor<1, dim>(const Point<dim> &)>     flux)
      : where(where)
      , flux(flux)
    {}
    unsigned int
    derivative_order() const override
    {
      return 0;
    }
    bool
    acts_on_face(const unsigned int) const override
    {
      return true;
    }
    void
    assemble_face(const unsigned int           face,
                  const SplineCellValues<dim> &v,
                  FullMatrix<double>          &A,
                  Vector<double>              &b) const override;

  private:
    std::function<bool(unsigned int, const Point<dim> &)> where;
    std::function<Tensor<1, dim>(const Point<dim> &)>     flux;
  };
} // namespace vesicle_iga
