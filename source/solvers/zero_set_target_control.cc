// Targets of the diffuse constraints (E9) that hold the zero level set's own
// area and volume (issue 16, item 1; doc/validation.md 1d).

#include <vesicle_iga/solvers/zero_set_target_control.h>

namespace vesicle_iga
{
  void
  ZeroSetTargetControl::set_reference(const Measures &sharp)
  {
    sharp_reference = sharp;
  }


  std::pair<double, double>
  ZeroSetTargetControl::targets(const Measures &diffuse,
                                const Measures &sharp,
                                const Measures &current) const
  {
    if (!(sharp.area > 0 && sharp.volume > 0 && sharp_reference.area > 0
          && sharp_reference.volume > 0))
      return {current.volume, current.area};
    return {sharp_reference.volume + (diffuse.volume - sharp.volume),
            sharp_reference.area + (diffuse.area - sharp.area)};
  }


  void
  ZeroSetTargetControl::save(Checkpoint &c, const std::string &prefix) const
  {
    c.scalars[prefix + ".sharp_area_reference"]   = sharp_reference.area;
    c.scalars[prefix + ".sharp_volume_reference"] = sharp_reference.volume;
  }


  void
  ZeroSetTargetControl::load(const Checkpoint &c, const std::string &prefix)
  {
    const auto area   = c.scalars.find(prefix + ".sharp_area_reference");
    const auto volume = c.scalars.find(prefix + ".sharp_volume_reference");
    if (area != c.scalars.end() && volume != c.scalars.end())
      sharp_reference = {area->second, volume->second};
  }
} // namespace vesicle_iga
