#include <deal.II/base/utilities.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/spline/box_space_parameters.h>

#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    template <typename T>
    std::vector<T>
    per_direction(const std::vector<T> &v,
                  const unsigned int    dim,
                  const std::string    &parameter,
                  const std::string    &text)
    {
      check_input(v.size() == 1 || v.size() == dim,
                  parameter,
                  text,
                  "one value, or one value per direction ("
                    + std::to_string(dim) + ")");
      return v.size() == 1 ? std::vector<T>(dim, v[0]) : v;
    }
  } // namespace


  void
  BoxSpaceParameters::declare(ParameterHandler  &prm,
                              const std::string &default_lower,
                              const std::string &default_upper,
                              const std::string &default_elements)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("Lower corner",
                      default_lower,
                      Patterns::Anything(),
                      "Lower corner of the box, one coordinate per direction "
                      "(or one value for all).");
    prm.declare_entry("Upper corner",
                      default_upper,
                      Patterns::Anything(),
                      "Upper corner of the box.");
    prm.declare_entry("Elements",
                      default_elements,
                      Patterns::Anything(),
                      "Number of elements (knot spans) per direction on the "
                      "coarsest level: one value or one per direction.");
    prm.declare_entry("Grading",
                      "1",
                      Patterns::Anything(),
                      "Ratio of consecutive element lengths per direction "
                      "(1: uniform; 1.1: each element 10% longer than the "
                      "previous one).");
    prm.declare_entry("Core lower corner",
                      "",
                      Patterns::Anything(),
                      "With 'Core upper corner': a refined core box. Each "
                      "direction then has 'Elements' equal elements inside "
                      "the core and elements growing by the factor "
                      "'Grading' (>= 1) from the core to the faces (sized "
                      "to end exactly on the faces, never shorter than the "
                      "core elements). Empty: no core.");
    prm.declare_entry("Core upper corner",
                      "",
                      Patterns::Anything(),
                      "Upper corner of the refined core box.");
    for (const char *d : {"x", "y", "z"})
      prm.declare_entry(std::string("Breakpoints ") + d,
                        "",
                        Patterns::Anything(),
                        std::string("Explicit increasing breakpoints in ") + d
                          + " (overrides corners, Elements and Grading for "
                            "this direction); empty: not used.");
    prm.declare_entry("Periodic directions",
                      "",
                      Patterns::Anything(),
                      "Directions (x, y, z, comma-separated) in which the "
                      "spline space is periodic, C^k across the seam.");
    prm.leave_subsection();
  }


  void
  BoxSpaceParameters::parse(ParameterHandler  &prm,
                            const unsigned int dim,
                            const std::string &section)
  {
    // The full path, as in the messages of the study's own entries.
    message_path     = section + "/Mesh/";
    const auto &mesh = message_path;
    prm.enter_subsection("Mesh");
    lower = per_direction(parse_double_list(prm.get("Lower corner"),
                                            mesh + "Lower corner"),
                          dim,
                          mesh + "Lower corner",
                          prm.get("Lower corner"));
    upper = per_direction(parse_double_list(prm.get("Upper corner"),
                                            mesh + "Upper corner"),
                          dim,
                          mesh + "Upper corner",
                          prm.get("Upper corner"));
    std::vector<unsigned int> n;
    for (const double x :
         parse_double_list(prm.get("Elements"), mesh + "Elements"))
      {
        check_input(x >= 1 && x == std::floor(x) && x <= 1e6,
                    mesh + "Elements",
                    prm.get("Elements"),
                    "positive integers up to 10^6 per direction");
        n.push_back(static_cast<unsigned int>(x));
      }
    elements = per_direction(n, dim, mesh + "Elements", prm.get("Elements"));
    double total = 1;
    for (const unsigned int e : elements)
      total *= e;
    check_input(total <= 1e9,
                mesh + "Elements",
                prm.get("Elements"),
                "at most 10^9 elements in all (the element and basis "
                "numbering is 32-bit)");
    grading
      = per_direction(parse_double_list(prm.get("Grading"), mesh + "Grading"),
                      dim,
                      mesh + "Grading",
                      prm.get("Grading"));
    for (unsigned int d = 0; d < dim; ++d)
      {
        check_input(upper[d] > lower[d],
                    mesh + "Upper corner",
                    prm.get("Upper corner"),
                    "each coordinate larger than that of 'Lower corner'");
        check_input(grading[d] > 0,
                    mesh + "Grading",
                    prm.get("Grading"),
                    "positive ratios");
      }
    const std::string core_lower_text = prm.get("Core lower corner"),
                      core_upper_text = prm.get("Core upper corner");
    core_lower.clear();
    core_upper.clear();
    check_input(Utilities::trim(core_lower_text).empty()
                  == Utilities::trim(core_upper_text).empty(),
                mesh + "Core upper corner",
                core_upper_text,
                "given together with 'Core lower corner' (or both empty)");
    if (!Utilities::trim(core_lower_text).empty())
      {
        core_lower
          = per_direction(parse_double_list(core_lower_text,
                                            mesh + "Core lower corner"),
                          dim,
                          mesh + "Core lower corner",
                          core_lower_text);
        core_upper
          = per_direction(parse_double_list(core_upper_text,
                                            mesh + "Core upper corner"),
                          dim,
                          mesh + "Core upper corner",
                          core_upper_text);
        for (unsigned int d = 0; d < dim; ++d)
          {
            check_input(lower[d] <= core_lower[d]
                          && core_lower[d] < core_upper[d]
                          && core_upper[d] <= upper[d],
                        mesh + "Core upper corner",
                        core_upper_text,
                        "a core box inside the domain: lower corner <= core "
                        "lower corner < core upper corner <= upper corner");
            check_input(grading[d] >= 1,
                        mesh + "Grading",
                        prm.get("Grading"),
                        "ratios >= 1 with a core box (elements grow "
                        "towards the faces)");
          }
      }
    breakpoints.assign(dim, {});
    for (unsigned int d = 0; d < dim; ++d)
      {
        const std::string name = std::string("Breakpoints ") + "xyz"[d];
        if (!Utilities::trim(prm.get(name)).empty())
          breakpoints[d] = parse_double_list(prm.get(name), mesh + name);
      }
    periodic.assign(dim, false);
    for (const auto &d :
         Utilities::split_string_list(prm.get("Periodic directions"), ','))
      {
        check_input(d.size() == 1 && d[0] >= 'x' && d[0] < char('x' + dim),
                    mesh + "Periodic directions",
                    prm.get("Periodic directions"),
                    "a comma-separated list of x, y, z (up to the dimension)");
        periodic[d[0] - 'x'] = true;
      }
    prm.leave_subsection();
  }


  template <int dim>
  SplineSpace<dim>
  BoxSpaceParameters::make_space(const unsigned int degree,
                                 const int          continuity) const
  {
    std::vector<KnotVector> kv;
    for (unsigned int d = 0; d < dim; ++d)
      {
        std::vector<double> z = breakpoints[d];
        if (z.empty() && !core_lower.empty())
          {
            // Uniform core, then sizes h q^k towards each face: as many as
            // fit, scaled up to end exactly on the face.
            const unsigned int n       = elements[d];
            const double       h       = (core_upper[d] - core_lower[d]) / n;
            const auto         outward = [&](const double length) {
              std::vector<double> sizes;
              double              sum = 0, s = h;
              while (true)
                {
                  s *= grading[d];
                  if (sum + s > length * (1 + 1e-12))
                    break;
                  sizes.push_back(s);
                  sum += s;
                }
              if (sizes.empty() && length > 1e-12 * h)
                sizes.push_back(length);
              else
                for (double &x : sizes)
                  x *= length / sum;
              return sizes;
            };
            const auto left  = outward(core_lower[d] - lower[d]);
            const auto right = outward(upper[d] - core_upper[d]);
            z.push_back(lower[d]);
            for (auto it = left.rbegin(); it != left.rend(); ++it)
              z.push_back(z.back() + *it);
            z.back() = core_lower[d];
            for (unsigned int i = 1; i <= n; ++i)
              z.push_back(core_lower[d] + i * h);
            for (const double x : right)
              z.push_back(z.back() + x);
            z.back() = upper[d];
          }
        else if (z.empty())
          {
            // Geometric grading: lengths proportional to q^i.
            const unsigned int n     = elements[d];
            const double       q     = grading[d];
            double             total = 0, len = 1;
            for (unsigned int i = 0; i < n; ++i, len *= q)
              total += len;
            z.push_back(lower[d]);
            len = 1;
            for (unsigned int i = 0; i < n; ++i, len *= q)
              z.push_back(z.back() + (upper[d] - lower[d]) * len / total);
            z.back() = upper[d];
          }
        check_input(z.size() >= 2,
                    message_path + "Breakpoints " + "xyz"[d],
                    std::to_string(z.size()) + " value(s)",
                    "at least two increasing breakpoints (one element)");
        const int k = continuity < 0 ? int(degree) - 1 : continuity;
        kv.emplace_back(degree,
                        z,
                        std::vector<int>(z.size() - 2, k),
                        periodic[d],
                        k,
                        std::string("Mesh (direction ") + "xyz"[d] + ")");
      }
    std::array<KnotVector, dim> a = [&]() {
      if constexpr (dim == 1)
        return std::array<KnotVector, 1>{{kv[0]}};
      else if constexpr (dim == 2)
        return std::array<KnotVector, 2>{{kv[0], kv[1]}};
      else
        return std::array<KnotVector, 3>{{kv[0], kv[1], kv[2]}};
    }();
    return SplineSpace<dim>(a);
  }

  template SplineSpace<1>
  BoxSpaceParameters::make_space<1>(const unsigned int, const int) const;
  template SplineSpace<2>
  BoxSpaceParameters::make_space<2>(const unsigned int, const int) const;
  template SplineSpace<3>
  BoxSpaceParameters::make_space<3>(const unsigned int, const int) const;
} // namespace vesicle_iga
