#pragma once

#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace vesicle_iga
{

  /**
   * A set of boundary pieces of a patch, read from a .prm string such as
   *   "x-min; x-max; y-min{x:0.25:0.75}"
   * Face names are x-min, x-max, y-min, y-max, z-min, z-max (the faces of
   * the parametric box: on an axis-aligned box these are the physical faces;
   * on a NURBS patch x/y/z name the parametric directions xi/eta/zeta). A
   * piece may be cut to a part of its face by one or more coordinate ranges
   * {coordinate:min:max} in physical coordinates. "all" selects every face
   * of the open (non-periodic) directions; "" or "none" selects nothing.
   */
  template <int dim>
  class BoundarySelection
  {
  public:
    BoundarySelection() = default;
    /// Throws InputError naming @p parameter on a malformed string.
    BoundarySelection(const std::string &text, const std::string &parameter);

    bool
    empty() const
    {
      return pieces.empty();
    }
    /// Whether some piece lies on face f (deal.II numbering 2*direction+side).
    bool
    touches_face(const unsigned int face) const;
    /// Whether the physical point x of face f belongs to the selection.
    bool
    contains(const unsigned int face, const dealii::Point<dim> &x) const;

    static std::string
    face_name(const unsigned int face);

    struct Range
    {
      unsigned int coordinate;
      double       min, max;
    };
    /// The pieces on face f, each as its list of coordinate ranges (empty:
    /// the whole face).
    std::vector<std::vector<Range>>
    pieces_on_face(const unsigned int face) const;

    /// The .prm entry this selection was read from (for messages).
    const std::string &
    parameter_name() const
    {
      return parameter;
    }

  private:
    struct Piece
    {
      unsigned int       face;
      std::vector<Range> ranges;
    };
    std::vector<Piece> pieces;
    std::string        parameter;
  };
} // namespace vesicle_iga
