#pragma once

#include <vesicle_iga/kernel/term.h>

#include <array>

namespace vesicle_iga
{
  /**
   * The inputs the Part E phase-field terms read at a quadrature point:
   * phi at the stage (its value, gradient and Laplacian; spec (E4)-(E9))
   * and the gradient of the frozen potential psi^n (an auxiliary field,
   * spec 3.9). Each term declares the ones it uses.
   */
  template <int dim>
  struct PhaseFieldInputs
  {
    using D = Derivative<dim>;

    /// @p phi: flat component of the phase field; @p potential: the
    /// auxiliary field of psi (or -1 without a field).
    PhaseFieldInputs(const unsigned int phi, const int potential = -1)
      : phi(phi)
      , potential(potential)
    {}

    void
    declare_value(TermDeclaration<dim> &d)
    {
      value = d.value(phi, D::value);
    }
    void
    declare_gradient(TermDeclaration<dim> &d)
    {
      for (unsigned int k = 0; k < dim; ++k)
        gradient[k] = d.value(phi, D::gradient(k));
    }
    void
    declare_laplacian(TermDeclaration<dim> &d)
    {
      laplacian = d.value(phi, D::laplacian);
    }
    void
    declare_potential_gradient(TermDeclaration<dim> &d)
    {
      for (unsigned int k = 0; k < dim; ++k)
        potential_gradient[k] = d.auxiliary(potential, 0, D::gradient(k));
    }

    const unsigned int           phi;
    const int                    potential;
    InputHandle                  value, laplacian;
    std::array<InputHandle, dim> gradient, potential_gradient;
  };
} // namespace vesicle_iga
