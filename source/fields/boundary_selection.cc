#include <deal.II/base/utilities.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/fields/boundary_selection.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  template <int dim>
  std::string
  BoundarySelection<dim>::face_name(const unsigned int face)
  {
    return std::string(1, "xyz"[face / 2]) + (face % 2 ? "-max" : "-min");
  }


  template <int dim>
  BoundarySelection<dim>::BoundarySelection(const std::string &text,
                                            const std::string &parameter_)
    : parameter(parameter_)
  {
    const std::string allowed
      = "'all', 'none', or a ';'-separated list of faces out of " +
        [] {
          std::string s;
          for (unsigned int f = 0; f < 2 * dim; ++f)
            s += (f ? ", " : "") + face_name(f);
          return s;
        }()
        + ", each optionally followed by ranges {coordinate:min:max} with "
          "coordinate in x"
        + (dim > 1 ? std::string(", y") : "") + (dim > 2 ? ", z" : "");
    const std::string trimmed = Utilities::trim(text);
    if (trimmed.empty() || trimmed == "none")
      return;
    if (trimmed == "all")
      {
        for (unsigned int f = 0; f < 2 * dim; ++f)
          pieces.push_back({f, {}});
        return;
      }
    for (const std::string &item : Utilities::split_string_list(trimmed, ';'))
      {
        const std::string name = item.substr(0, item.find('{'));
        Piece             piece{numbers::invalid_unsigned_int, {}};
        for (unsigned int f = 0; f < 2 * dim; ++f)
          if (Utilities::trim(name) == face_name(f))
            piece.face = f;
        check_input(piece.face != numbers::invalid_unsigned_int,
                    parameter,
                    text,
                    allowed);
        std::string rest = item.substr(name.size());
        while (!rest.empty())
          {
            const auto close = rest.find('}');
            check_input(rest[0] == '{' && close != std::string::npos,
                        parameter,
                        text,
                        allowed);
            const auto fields
              = Utilities::split_string_list(rest.substr(1, close - 1), ':');
            check_input(fields.size() == 3 && fields[0].size() == 1
                          && std::string("xyz").substr(0, dim).find(
                               fields[0][0])
                               != std::string::npos,
                        parameter,
                        text,
                        allowed);
            Range r;
            r.coordinate = fields[0][0] - 'x';
            // Whole, finite numbers only: "6x" or "inf" is refused, not
            // read as 6 or as the end of the domain.
            const auto number = [&](const std::string &field) {
              std::size_t used = 0;
              double      v    = 0;
              try
                {
                  v = std::stod(field, &used);
                }
              catch (...)
                {
                  used = 0;
                }
              check_input(used == field.size() && std::isfinite(v),
                          parameter,
                          text,
                          "ranges {coordinate:min:max} with finite numbers "
                          "min < max");
              return v;
            };
            r.min = number(fields[1]);
            r.max = number(fields[2]);
            check_input(r.min < r.max,
                        parameter,
                        text,
                        "ranges {coordinate:min:max} with min < max");
            piece.ranges.push_back(r);
            rest = Utilities::trim(rest.substr(close + 1));
          }
        pieces.push_back(piece);
      }
  }


  template <int dim>
  bool
  BoundarySelection<dim>::touches_face(const unsigned int face) const
  {
    for (const auto &p : pieces)
      if (p.face == face)
        return true;
    return false;
  }


  template <int dim>
  bool
  BoundarySelection<dim>::contains(const unsigned int face,
                                   const Point<dim>  &x) const
  {
    for (const auto &p : pieces)
      if (p.face == face)
        {
          bool inside = true;
          for (const auto &r : p.ranges)
            inside = inside && x[r.coordinate] >= r.min - 1e-12
                     && x[r.coordinate] <= r.max + 1e-12;
          if (inside)
            return true;
        }
    return false;
  }


  template <int dim>
  std::vector<std::vector<typename BoundarySelection<dim>::Range>>
  BoundarySelection<dim>::pieces_on_face(const unsigned int face) const
  {
    std::vector<std::vector<Range>> result;
    for (const auto &p : pieces)
      if (p.face == face)
        result.push_back(p.ranges);
    return result;
  }


  template class BoundarySelection<1>;
  template class BoundarySelection<2>;
  template class BoundarySelection<3>;
} // namespace vesicle_iga
