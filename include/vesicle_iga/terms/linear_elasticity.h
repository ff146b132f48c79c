#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <vesicle_iga/assembly/assembly_term.h>
#include <vesicle_iga/assembly/boundary_selection.h>

#include <functional>

namespace vesicle_iga
{
  /**
   * Isotropic linear elasticity (eps(v), C eps(u)) with the displacement as
   * dim components (spec Part P, (P3)-(P4) context). In 2D either plane
   * stress (the plate of spec section 5.3: lambda* = 2 lambda mu /
   * (lambda + 2 mu)) or plane strain.
   */
  template <int dim>
  class LinearElasticityTerm : public AssemblyTerm<dim>
  {
  public:
    LinearElasticityTerm(const double young_modulus,
                         const double poisson_ratio,
                         const bool   plane_stress);
    unsigned int
    derivative_order() const override
    {
      return 1;
    }
    void
    assemble_cell(const SplineCellValues<dim> &v,
                  FullMatrix<double>          &A,
                  Vector<double>              &b) const override;

    /// sigma = lambda tr(eps) I + 2 mu eps.
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &strain) const;
    /// eps : C eps, the energy density times two.
    double
    energy_product(const SymmetricTensor<2, dim> &strain) const
    {
      return stress(strain) * strain;
    }

  private:
    double lambda, mu;
  };

  /// Prescribed traction t(x, n) on the selected boundary: (v, t).
  template <int dim>
  class TractionTerm : public AssemblyTerm<dim>
  {
  public:
    using TractionFunction
      = std::function<Tensor<1, dim>(const Point<dim> &,
                                     const Tensor<1, dim> &)>;
    TractionTerm(const BoundarySelection<dim> &selection, TractionFunction t)
      : selection(selection)
      , traction(t)
    {}
    unsigned int
    derivative_order() const override
    {
      return 0;
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
    TractionFunction             traction;
  };
} // namespace vesicle_iga
