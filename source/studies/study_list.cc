#include <vesicle_iga/studies/study.h>

namespace vesicle_iga
{
  using namespace dealii;

  // Each study file defines its description; the list is explicit so that
  // the set of studies is visible in one place (no static registration).
  StudyDescription
  poisson_mms_description();
  StudyDescription
  biharmonic_mms_description();
  StudyDescription
  plate_with_hole_description();
  StudyDescription
  willmore_flow_description();
  StudyDescription
  navier_stokes_description();
  StudyDescription
  vesicle_hydrodynamics_description();

  const std::vector<StudyDescription> &
  available_studies()
  {
    static const std::vector<StudyDescription> studies
      = {poisson_mms_description(),
         biharmonic_mms_description(),
         plate_with_hole_description(),
         willmore_flow_description(),
         navier_stokes_description(),
         vesicle_hydrodynamics_description()};
    return studies;
  }
} // namespace vesicle_iga
