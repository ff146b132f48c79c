#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <vesicle_iga/spline/nurbs_geometry.h>

#include <memory>

namespace vesicle_iga
{
  /// The coarse NURBS quarter plate with a hole of spec (P1)-(P2).
  std::shared_ptr<const NurbsGeometry<2>>
  make_plate_with_hole_geometry();

  /// Kirsch's solution for the infinite plate, plane stress, (P3)-(P4).
  class KirschSolution
  {
  public:
    KirschSolution(const double E,
                   const double nu,
                   const double Tx,
                   const double R);
    dealii::SymmetricTensor<2, 2>
    stress(const dealii::Point<2> &x) const;
    dealii::Tensor<1, 2>
    displacement(const dealii::Point<2> &x) const;

  private:
    double E, nu, Tx, R;
  };
} // namespace vesicle_iga
