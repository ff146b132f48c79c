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
    /// The volume multiplier lambda_v of (H1) and the volume V_i it holds
    /// ("Volume multiplier"):
    /// - domain: -lambda_v on the whole domain and V_i = int phi_i, the
    ///   source's (H1), (H12c); it lifts phi_i off -1 everywhere ("fog")
    ///   and so moves volume between the far field and the vesicle;
    /// - membrane: -lambda_v delta_eps(phi) with delta_eps of (H12b), V_i =
    ///   int phi_i; (H13) is then not a Gram system, and its determinant
    ///   changes sign near a circle or sphere;
    /// - indicator (default): -lambda_v delta_eps(phi) as membrane, V_i =
    ///   int chi(phi_i) with chi' proportional to delta_eps
    ///   (membrane::smoothed_indicator), so that (H13) is a Gram system,
    ///   well posed for every shape that is not a circle or sphere.
    /// doc/hydrodynamics.md, "Volume multiplier" and "A Gram form of (H13)".
    enum class VolumeMultiplier
    {
      domain,
      membrane,
      indicator
    };
    VolumeMultiplier volume_multiplier = VolumeMultiplier::indicator;
    /// Whether lambda_v acts on the membrane only (membrane, indicator).
    bool
    local_volume_multiplier() const
    {
      return volume_multiplier != VolumeMultiplier::domain;
    }
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

    /// The smoothed indicator chi(phi) = 15/8 (phi - 2 phi^3 / 3 + phi^5 / 5)
    /// whose volume int chi(phi_i) 'Volume multiplier = indicator' holds:
    /// chi(+-1) = +-1 as phi, chi odd (a symmetric profile encloses the
    /// same volume as with int phi), and chi'(phi) = 15/8 (1 - phi^2)^2 =
    /// indicator_slope_per_delta(eps) delta_eps(phi) of (H12b), so that the
    /// rate of int chi(phi_i) is the membrane weight of lambda_v tested
    /// with d_t phi_i, and (H13) becomes a Gram system. chi' >= 0 also
    /// beyond |phi| = 1.
    template <typename T>
    inline T
    smoothed_indicator(const T &phi)
    {
      const T p2 = phi * phi;
      return 15. / 8. * phi * (1. - p2 * (2. / 3.) + p2 * p2 * 0.2);
    }

    /// chi'(phi) / delta_eps(phi) = 15/8 * 4 sqrt(2) eps / 3 =
    /// 5 eps / sqrt(2).
    inline double
    indicator_slope_per_delta(const double eps)
    {
      return 5. * eps / std::sqrt(2.);
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
