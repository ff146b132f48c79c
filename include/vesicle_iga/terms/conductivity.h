#pragma once

#include <vesicle_iga/kernel/term.h>
#include <vesicle_iga/physics/electromechanics_material.h>

namespace vesicle_iga
{
  /**
   * The conductivity-weighted Laplacian of the electric potential, spec
   * (E17): residual (sigma(phi) grad psi, grad v), Jacobian
   * (sigma(phi) grad dpsi, grad v), with psi the unknown and phi an
   * auxiliary field (phi_n of the staggered scheme, spec 3.9) and sigma of
   * (E10) from the material.
   */
  template <int dim>
  class ConductivityTerm : public Term<dim>
  {
  public:
    /// @p psi: component of the potential; @p phase_field: the auxiliary
    /// field of phi.
    ConductivityTerm(const unsigned int              psi,
                     const unsigned int              phase_field,
                     const ElectromechanicsMaterial &material)
      : psi(psi)
      , phase_field(phase_field)
      , material(material)
    {}
    std::string
    name() const override
    {
      return "conductivity";
    }
    void
    declare(TermDeclaration<dim> &d) override
    {
      using D = Derivative<dim>;
      phi     = d.auxiliary(phase_field, 0, D::value);
      for (unsigned int k = 0; k < dim; ++k)
        {
          gradient[k] = d.value(psi, D::gradient(k));
          residual[k] = d.residual(psi, D::gradient(k));
          jacobian[k] = d.jacobian(psi, D::gradient(k), psi, D::gradient(k));
        }
    }
    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override
    {
      const double *p = in[phi];
      for (unsigned int q = 0; q < in.size(); ++q)
        {
          const double s = material.conductivity(p[q]);
          for (unsigned int k = 0; k < dim; ++k)
            {
              out[residual[k]][q] += s * in[gradient[k]][q];
              if (out.matrix())
                out[jacobian[k]][q] += s;
            }
        }
    }

  private:
    const unsigned int              psi, phase_field;
    const ElectromechanicsMaterial &material;
    InputHandle                     phi;
    std::array<InputHandle, dim>    gradient;
    std::array<ResidualHandle, dim> residual;
    std::array<JacobianHandle, dim> jacobian;
  };
} // namespace vesicle_iga
