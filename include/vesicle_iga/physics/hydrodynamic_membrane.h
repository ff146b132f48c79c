#pragma once

#include <vesicle_iga/kernel/forward_ad.h>

#include <cmath>

namespace vesicle_iga
{
  /**
   * The coefficients of the vesicle-hydrodynamics model, spec 4.2 and 4.9
   * (non-dimensional): Reynolds number Re, bending capillary number Ca
   * (bending force scaled by 1 / (Re Ca)), interaction number IN, mobility
   * eta_phi, inextensibility regularisation xi, viscosity ratio beta_mu and
   * the interface width eps.
   */
  struct MembraneCoefficients
  {
    double reynolds_number    = 5e-3;
    double capillary_number   = 1e4;
    double interaction_number = 0.5;
    double mobility           = 0.1;
    double inextensibility_xi = 1;
    double viscosity_ratio    = 1;
    double epsilon            = 1. / 16;
    /// Whether the interaction energy (H10) acts.
    bool interaction = true;
    /// Where the volume multiplier acts in (H1): true (this project's
    /// default) on the membrane only, -lambda_v delta_eps(phi) with
    /// delta_eps of (H12b); false as in the source, -lambda_v on the whole
    /// domain, which lifts phi_i off -1 everywhere ("fog") and so moves
    /// volume between the far field and the vesicle (doc/hydrodynamics.md,
    /// "Volume multiplier").
    bool membrane_volume_multiplier = true;
    /// Which values of the global multipliers a step uses: true (this
    /// project's default) the (H13) values of the last accepted step
    /// extrapolated linearly to the end of the step (but where their rate
    /// changed sign), false the (H13)
    /// values themselves, lagged by a step as in the source
    /// (doc/hydrodynamics.md, "Global multipliers in time").
    bool extrapolated_multipliers = true;
    /// Whether a step iterates its global multipliers until it ends on
    /// V_i(0), A_i(0) (H7) (not in the source; the step is solved about 2-3
    /// times), to the relative tolerance given, in at most the number of
    /// iterations given (doc/hydrodynamics.md, "Implicit global
    /// multipliers"). The first iterate is the extrapolated one.
    bool         implicit_multipliers      = false;
    double       multiplier_tolerance      = 1e-5;
    unsigned int max_multiplier_iterations = 8;
    /// Boundary condition of the phase fields: true (default) the source's
    /// d phi_i / dn = 0 of spec 4.10, strongly; together with (H24) it
    /// leaves d f_i / dn = 0 natural, the source's pair. false: natural
    /// conditions only (f_i = d f_i / dn = 0), under which the kernel of
    /// the bending operator holds boundary layers that a negative lambda_g
    /// amplifies without bound (doc/hydrodynamics.md, "Phase-field
    /// boundary condition").
    bool zero_normal_derivative = true;

    /// 1 / (Re Ca), the factor of the bending force (H3).
    double
    bending_factor() const
    {
      return 1. / (reynolds_number * capillary_number);
    }
    /// 1 / (Re IN), the factor of the interaction energy (H10).
    double
    interaction_factor() const
    {
      return 1. / (reynolds_number * interaction_number);
    }
  };


  /**
   * The pointwise functions of the Part H phase fields (phi = +1 inside,
   * spec (H0)), templated in the number type so that the terms get their
   * Jacobians by automatic differentiation.
   */
  namespace membrane
  {
    /// f = eps Delta phi - (phi^2 - 1) phi / eps, (H2): -f = dA / dphi.
    template <typename T>
    inline T
    chemical_potential(const T &phi, const T &laplacian, const double eps)
    {
      return eps * laplacian - (phi * phi - 1.) * phi / eps;
    }

    /// Diffuse surface delta (H12b), integrates to 1 across the profile.
    template <typename T>
    inline T
    surface_delta(const T &phi, const double eps)
    {
      const T s = 1. - phi * phi;
      return 3. / (4. * std::sqrt(2.) * eps) * s * s;
    }

    /// The weight of the volume multiplier lambda_v in (H1): delta_eps(phi)
    /// of (H12b) on the membrane, or 1 on the whole domain (the source).
    template <typename T>
    inline T
    volume_multiplier_weight(const T &phi, const double eps, const bool local)
    {
      return local ? surface_delta(phi, eps) : T(1.);
    }

    /// B(phi) = (phi^2 - 1)^2 / eps of (H8).
    template <typename T>
    inline T
    interaction_b(const T &phi, const double eps)
    {
      const T s = phi * phi - 1.;
      return s * s / eps;
    }

    /// B'(phi) = 4 phi (phi^2 - 1) / eps, (H9).
    template <typename T>
    inline T
    interaction_b_derivative(const T &phi, const double eps)
    {
      return 4. / eps * phi * (phi * phi - 1.);
    }

    /// L = ln((1 + phi) / (1 - phi)) of (H8) with the numerics of spec 4.4:
    /// phi clipped to |phi| <= 1 - 1e-14 (into @p x). Returns false where w
    /// and w' vanish: |phi| >= 1 and |L| > 40 (underflow of exp(-L^2 / 2)).
    template <typename T>
    inline bool
    interaction_log_ratio(const T &phi, T &x, T &L)
    {
      using std::log;
      const double p = value_of(phi);
      if (std::abs(p) >= 1)
        return false;
      const double clip = 1 - 1e-14;
      x                 = std::abs(p) > clip ? T(p > 0 ? clip : -clip) : phi;
      L                 = log((1. + x) / (1. - x));
      return std::abs(value_of(L)) <= 40;
    }

    /// w(phi) = exp(-L^2 / 2), (H8).
    template <typename T>
    inline T
    interaction_w(const T &phi)
    {
      using std::exp;
      T x, L;
      if (!interaction_log_ratio(phi, x, L))
        return T(0.);
      return exp(-0.5 * L * L);
    }

    /// w'(phi) = 2 w L / (phi^2 - 1), (H9).
    template <typename T>
    inline T
    interaction_w_derivative(const T &phi)
    {
      using std::exp;
      T x, L;
      if (!interaction_log_ratio(phi, x, L))
        return T(0.);
      return 2. * exp(-0.5 * L * L) * L / (x * x - 1.);
    }
  } // namespace membrane
} // namespace vesicle_iga
