#pragma once

#include <vesicle_iga/io/checkpoint.h>

#include <string>
#include <utility>

namespace vesicle_iga
{
  /**
   * Constraints on the zero level set's own area and volume, an option of
   * the Willmore flow (`Constraint targets = zero level set`; issue 16,
   * item 1; doc/validation.md 1d).
   *
   * The diffuse area and volume of (E9) differ from those of the zero level
   * set by a curvature correction of order eps^2 that depends on the shape
   * (for a sphere V_diffuse - V = 4 pi R pi^2 eps^2 / 6, section 1c), so
   * holding (E9) at its initial values lets the sharp measures drift as the
   * shape changes: by 15 % in volume in prolate-to-dumbbell-3d. This
   * control holds the sharp measures instead. After every accepted step it
   * sets the targets of (E9) to
   *
   *   target = sharp reference + (diffuse measure - sharp measure),
   *
   * i.e. the reference plus the correction of the present shape, so that
   * once the next step holds the diffuse constraint, the sharp measure
   * equals its reference up to the change of the correction over that step.
   * The reference is the sharp measures of the initial state. In 2D "area"
   * is the length of the zero contour and "volume" the area it encloses,
   * as for (E9).
   */
  class ZeroSetTargetControl : public Checkpointable
  {
  public:
    struct Measures
    {
      double area, volume;
    };

    /// The sharp measures of the initial state.
    void
    set_reference(const Measures &sharp);

    /// The targets (volume, area) of (E9) for the present diffuse and sharp
    /// measures. A sharp measure that is not positive (no closed zero level
    /// set found) leaves the diffuse targets as they are: returns `current`.
    std::pair<double, double>
    targets(const Measures &diffuse,
            const Measures &sharp,
            const Measures &current) const;

    /// The reference; a checkpoint written without this control keeps the
    /// reference of the initial state computed at set-up.
    void
    save(Checkpoint &c, const std::string &prefix) const override;
    void
    load(const Checkpoint &c, const std::string &prefix) override;

  private:
    Measures sharp_reference{0., 0.};
  };
} // namespace vesicle_iga
