#pragma once

#include <vesicle_iga/kernel/pointwise_term.h>
#include <vesicle_iga/physics/hydrodynamic_membrane.h>

namespace vesicle_iga
{
  /**
   * The global area and volume multipliers of one vesicle in the flow:
   * the part -lambda_g f - lambda_v beta(phi) of the chemical potential of
   * (H1), with f of (H2), in the phase-field equation (H16) and, with the
   * sign of (H14), in the momentum forcing, beta = delta_eps(phi) of (H12b)
   * (membrane volume multiplier, default) or 1 (the source's (H1)); see
   * MembraneCoefficients.
   *
   * -(v, f) enters as the first variation of the diffuse area (H12c),
   *   A'(phi)[v] = eps (grad v, grad phi) + (v, W'(phi) / eps),
   * i.e. integrated by parts with the natural condition d_n phi = 0 of spec
   * 4.10, in both places (v = r in (H16), v = w . grad phi in (H14)):
   *   eta_phi (lambda_g A'[r] - lambda_v (r, beta))
   *   - lambda_g A'[w . grad phi] + lambda_v (w . grad phi, beta),
   * grad(w . grad phi) . grad phi = d_k w_a d_a phi d_k phi
   *                                 + w_a d_a d_k phi d_k phi.
   * The same pairing in both keeps the advection-forcing cancellation of
   * the energy law (spec 4.3), and A'[phi_t] = dA/dt is the rate (H13)
   * relaxes. The pointwise form (v, eps Delta phi - W' / eps) is the same up
   * to eps (v, d_n phi) on the boundary, but its Jacobian is not: for the
   * functions at the boundary -(N, Delta N) = |grad N|^2 - (N d_n N) is
   * negative, so that once lambda_g had grown to 115 (HD3 at t = 0.09) the
   * phase-field blocks at dt = 1e-3 had near-zero diagonal entries on the
   * walls and their multigrid smoothers (ILU, Gauss-Seidel) blew up
   * (doc/hydrodynamics.md, "Linear solver").
   * lambda_g, lambda_v are constants within a step, from the (H13) solve
   * after the previous step (set_multipliers).
   */
  template <int dim>
  struct GlobalConstraintForcingFormula
  {
    static constexpr int n_hessian  = dim * (dim + 1) / 2;
    static constexpr int max_inputs = 1 + dim + n_hessian;
    GlobalConstraintForcingFormula(const unsigned int          velocity,
                                   const unsigned int          phi,
                                   const MembraneCoefficients &coefficients);
    std::string
    name() const
    {
      return "global_constraint_forcing";
    }
    void
    set_multipliers(const double area, const double volume)
    {
      lambda_g = area;
      lambda_v = volume;
    }
    double
    area_multiplier() const
    {
      return lambda_g;
    }
    double
    volume_multiplier() const
    {
      return lambda_v;
    }
    template <typename T>
    void
    residual(const T *in, T *out) const
    {
      // in: phi, d_a phi, d_a d_b phi (a <= b, row by row).
      // out: phi value, phi gradient (a), w_a value, d_k w_a (a, k).
      const T *grad = in + 1;
      const T  well = (in[0] * in[0] - 1.) * in[0] / eps; // W'(phi) / eps
      const T  beta = membrane::volume_multiplier_weight(in[0], eps, local);
      out[0]        = eta * (lambda_g * well - lambda_v * beta);
      for (unsigned int a = 0; a < dim; ++a)
        out[1 + a] = eta * lambda_g * eps * grad[a];
      for (unsigned int a = 0; a < dim; ++a)
        {
          T hessian_grad = 0.; // (grad grad phi . grad phi)_a
          for (unsigned int k = 0; k < dim; ++k)
            hessian_grad += in[1 + dim + hessian_index(a, k)] * grad[k];
          out[1 + dim + a] = -lambda_g * (eps * hessian_grad + well * grad[a])
                             + lambda_v * beta * grad[a];
          for (unsigned int k = 0; k < dim; ++k)
            out[1 + 2 * dim + a * dim + k]
              = -lambda_g * eps * grad[a] * grad[k];
        }
    }

    std::vector<FormulaInput>  inputs;
    std::vector<FormulaOutput> outputs;

  private:
    /// Position of d_a d_k phi among the inputs after the gradient.
    static constexpr unsigned int
    hessian_index(const unsigned int a, const unsigned int k)
    {
      const unsigned int i = a < k ? a : k, j = a < k ? k : a;
      // Row i holds (i, i), ..., (i, dim - 1).
      return i * dim - i * (i - 1) / 2 + (j - i);
    }
    double eps, eta;
    bool   local;
    /// Nonzero while the pattern of the Jacobian is probed.
    double lambda_g = 1, lambda_v = 1;
  };

  template <int dim>
  using GlobalConstraintForcing
    = PointwiseTerm<dim, GlobalConstraintForcingFormula<dim>>;

  extern template class PointwiseTerm<2, GlobalConstraintForcingFormula<2>>;
  extern template class PointwiseTerm<3, GlobalConstraintForcingFormula<3>>;
} // namespace vesicle_iga
