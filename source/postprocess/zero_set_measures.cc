#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <vesicle_iga/postprocess/crossing_tolerance.h>
#include <vesicle_iga/postprocess/edge_root.h>
#include <vesicle_iga/postprocess/zero_set_measures.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>

namespace vesicle_iga
{
  using namespace dealii;

  double
  ZeroSetMeasures::reduced(const unsigned int dim) const
  {
    if (boundary <= 0)
      return 0.;
    return dim == 3 ? 6 * std::sqrt(M_PI) * inside / std::pow(boundary, 1.5) :
                      4 * M_PI * inside / (boundary * boundary);
  }


  namespace
  {
    double
    triangle_area(const Point<2> &p0, const Point<2> &p1, const Point<2> &p2)
    {
      const Tensor<1, 2> a = p1 - p0, b = p2 - p0;
      return std::abs(a[0] * b[1] - a[1] * b[0]) / 2;
    }

    double
    tetrahedron_volume(const Point<3> &p0,
                       const Point<3> &p1,
                       const Point<3> &p2,
                       const Point<3> &p3)
    {
      Tensor<2, 3> edges;
      for (unsigned int d = 0; d < 3; ++d)
        {
          edges[0][d] = p1[d] - p0[d];
          edges[1][d] = p2[d] - p0[d];
          edges[2][d] = p3[d] - p0[d];
        }
      return std::abs(determinant(edges)) / 6;
    }

    double
    simplex_volume(const std::array<Point<2>, 3> &p)
    {
      return triangle_area(p[0], p[1], p[2]);
    }

    double
    simplex_volume(const std::array<Point<3>, 4> &p)
    {
      return tetrahedron_volume(p[0], p[1], p[2], p[3]);
    }

    double
    triangle_area(const Point<3> &a, const Point<3> &b, const Point<3> &c)
    {
      return cross_product_3d(b - a, c - a).norm() / 2;
    }


    /**
     * One element cut into sample sub-boxes and simplices; adds the
     * simplices' parts of {phi < 0} and of {phi = 0} to the measures.
     */
    template <int dim>
    class ElementCutter
    {
    public:
      ElementCutter(const SplineSpace<dim> &space,
                    const unsigned int      samples,
                    const double            tolerance)
        : space(space)
        , samples(samples)
        , tolerance(tolerance)
      {
        std::array<unsigned int, dim> order;
        std::iota(order.begin(), order.end(), 0u);
        do
          permutations.push_back(order);
        while (std::next_permutation(order.begin(), order.end()));
      }

      /// Adds element @p e, on which @p field evaluates the spline.
      void
      add(const unsigned int                               e,
          const std::function<double(const Point<dim> &)> &field,
          ZeroSetMeasures                                 &m)
      {
        value                      = field;
        lower                      = space.element_lower_corner(e);
        step                       = space.element_lengths(e) / double(samples);
        const unsigned int n       = samples + 1;
        unsigned int       n_nodes = 1;
        for (unsigned int d = 0; d < dim; ++d)
          n_nodes *= n;
        node_value.resize(n_nodes);
        for (unsigned int i = 0; i < n_nodes; ++i)
          node_value[i] = value(node_point(i));
        crossings.clear();

        unsigned int n_boxes = 1;
        for (unsigned int d = 0; d < dim; ++d)
          n_boxes *= samples;
        for (unsigned int b = 0; b < n_boxes; ++b)
          {
            // The box's lowest node, then Kuhn's simplices: from it, one
            // unit step along each direction in the order of a permutation.
            unsigned int origin = 0, stride = 1, rest = b;
            for (unsigned int d = 0; d < dim; ++d)
              {
                origin += (rest % samples) * stride;
                rest /= samples;
                stride *= n;
              }
            for (const auto &order : permutations)
              {
                std::array<unsigned int, dim + 1> v;
                v[0] = origin;
                for (unsigned int k = 0; k < dim; ++k)
                  v[k + 1] = v[k] + node_stride(order[k]);
                add_simplex(v, m);
              }
          }
      }

    private:
      unsigned int
      node_stride(const unsigned int d) const
      {
        unsigned int s = 1;
        for (unsigned int k = 0; k < d; ++k)
          s *= samples + 1;
        return s;
      }

      Point<dim>
      node_point(unsigned int i) const
      {
        Point<dim> p = lower;
        for (unsigned int d = 0; d < dim; ++d)
          {
            p[d] += (i % (samples + 1)) * step[d];
            i /= samples + 1;
          }
        return p;
      }

      /// The zero of the spline between node a (phi < 0) and node b
      /// (phi >= 0), by the Illinois variant of regula falsi; cached, so
      /// that the simplices sharing the edge share the point.
      const Point<dim> &
      crossing(const unsigned int a, const unsigned int b)
      {
        const auto key   = std::make_pair(a, b);
        const auto found = crossings.find(key);
        if (found != crossings.end())
          return found->second;
        const Point<dim> pa = node_point(a), pb = node_point(b);
        const double     t
          = edge_root([&](const double t) { return value(pa + t * (pb - pa)); },
                      node_value[a],
                      node_value[b],
                      tolerance);
        return crossings[key] = pa + t * (pb - pa);
      }

      void
      add_simplex(const std::array<unsigned int, dim + 1> &v,
                  ZeroSetMeasures                         &m)
      {
        std::vector<unsigned int> in, out;
        for (const unsigned int i : v)
          (node_value[i] < 0 ? in : out).push_back(i);
        std::array<Point<dim>, dim + 1> p;
        for (unsigned int k = 0; k <= dim; ++k)
          p[k] = node_point(v[k]);
        if (out.empty())
          m.inside += simplex_volume(p);
        if (in.empty() || out.empty())
          return;
        add_cut(in, out, p, m);
      }

      void
      add_cut(const std::vector<unsigned int>       &in,
              const std::vector<unsigned int>       &out,
              const std::array<Point<dim>, dim + 1> &p,
              ZeroSetMeasures                       &m);

      const SplineSpace<dim>                                     &space;
      const unsigned int                                          samples;
      std::function<double(const Point<dim> &)>                   value;
      const double                                                tolerance;
      std::vector<std::array<unsigned int, dim>>                  permutations;
      Point<dim>                                                  lower;
      Tensor<1, dim>                                              step;
      std::vector<double>                                         node_value;
      std::map<std::pair<unsigned int, unsigned int>, Point<dim>> crossings;
    };


    // A triangle with one or two vertices inside: the part inside is a
    // triangle, or the triangle less the corner outside; the cut is the
    // segment between the two crossings.
    template <>
    void
    ElementCutter<2>::add_cut(const std::vector<unsigned int> &in,
                              const std::vector<unsigned int> &out,
                              const std::array<Point<2>, 3>   &p,
                              ZeroSetMeasures                 &m)
    {
      const bool         corner_inside = in.size() == 1;
      const unsigned int apex          = corner_inside ? in[0] : out[0];
      const auto        &others        = corner_inside ? out : in;
      const Point<2>     a
        = corner_inside ? crossing(apex, others[0]) : crossing(others[0], apex);
      const Point<2> b
        = corner_inside ? crossing(apex, others[1]) : crossing(others[1], apex);
      const double corner = triangle_area(node_point(apex), a, b);
      m.inside += corner_inside ? corner : simplex_volume(p) - corner;
      m.boundary += a.distance(b);
    }


    // A tetrahedron: one vertex inside (a corner tetrahedron), three inside
    // (the tetrahedron less the corner outside), or two (a prism between
    // the two inner vertices' faces, cut into three tetrahedra; the cut
    // quadrilateral into two triangles along the same diagonal).
    template <>
    void
    ElementCutter<3>::add_cut(const std::vector<unsigned int> &in,
                              const std::vector<unsigned int> &out,
                              const std::array<Point<3>, 4>   &p,
                              ZeroSetMeasures                 &m)
    {
      if (in.size() != 2)
        {
          const bool              corner_inside = in.size() == 1;
          const unsigned int      apex   = corner_inside ? in[0] : out[0];
          const auto             &others = corner_inside ? out : in;
          std::array<Point<3>, 3> q;
          for (unsigned int k = 0; k < 3; ++k)
            q[k] = corner_inside ? crossing(apex, others[k]) :
                                   crossing(others[k], apex);
          const double corner
            = tetrahedron_volume(node_point(apex), q[0], q[1], q[2]);
          m.inside += corner_inside ? corner : simplex_volume(p) - corner;
          m.boundary += triangle_area(q[0], q[1], q[2]);
          return;
        }
      const Point<3> a0 = node_point(in[0]), a1 = crossing(in[0], out[0]),
                     a2 = crossing(in[0], out[1]);
      const Point<3> b0 = node_point(in[1]), b1 = crossing(in[1], out[0]),
                     b2 = crossing(in[1], out[1]);
      m.inside += tetrahedron_volume(a0, a1, a2, b2)
                  + tetrahedron_volume(a0, a1, b1, b2)
                  + tetrahedron_volume(a0, b0, b1, b2);
      m.boundary += triangle_area(a1, a2, b2) + triangle_area(a1, b2, b1);
    }

    /// Element @p e with coefficients @p c of the component: counted whole
    /// when they all lie below zero, cut when they change sign (a B-spline
    /// lies in the convex hull of its coefficients).
    template <int dim>
    void
    add_element(const SplineSpace<dim>                          &space,
                ElementCutter<dim>                              &cutter,
                const unsigned int                               e,
                const std::vector<double>                       &c,
                const std::function<double(const Point<dim> &)> &field,
                ZeroSetMeasures                                 &m)
    {
      bool all_in = true, all_out = true;
      for (const double v : c)
        {
          all_in  = all_in && v < 0;
          all_out = all_out && v >= 0;
        }
      if (all_in)
        {
          const auto length = space.element_lengths(e);
          double     volume = 1;
          for (unsigned int d = 0; d < dim; ++d)
            volume *= length[d];
          m.inside += volume;
        }
      else if (!all_out)
        cutter.add(e, field, m);
    }
  } // namespace


  template <int dim>
  ZeroSetMeasures
  zero_set_measures(const SplineSpace<dim>    &space,
                    const std::vector<double> &natural,
                    const unsigned int         n_components,
                    const unsigned int         component,
                    const unsigned int         samples_per_element)
  {
    ElementCutter<dim>                              cutter(space,
                              std::max(1u, samples_per_element),
                              crossing_tolerance(natural,
                                                 n_components,
                                                 component));
    ZeroSetMeasures                                 m;
    std::vector<unsigned int>                       indices;
    std::vector<double>                             values;
    const std::function<double(const Point<dim> &)> field
      = [&](const Point<dim> &p) {
          space.evaluate(natural, n_components, p, values);
          return values[component];
        };
    for (unsigned int e = 0; e < space.n_elements(); ++e)
      {
        space.element_basis_indices(e, indices);
        std::vector<double> c;
        for (const unsigned int i : indices)
          c.push_back(natural[i * n_components + component]);
        add_element(space, cutter, e, c, field, m);
      }
    return m;
  }


  template <int dim>
  ZeroSetMeasures
  zero_set_measures(const SplineDofHandler<dim>         &dofs,
                    const TrilinosWrappers::MPI::Vector &ghosted,
                    const unsigned int                   component,
                    const unsigned int                   samples_per_element)
  {
    const SplineSpace<dim> &space = dofs.get_space();
    const MPI_Comm          comm  = dofs.get_mesh().get_communicator();
    const auto             &own   = dofs.get_mesh().locally_owned_elements();
    std::vector<std::vector<double>> c;
    ElementCutter<dim>               cutter(space,
                              std::max(1u, samples_per_element),
                              crossing_tolerance(dofs, ghosted, component));
    ZeroSetMeasures                  m;
    for (const unsigned int e : own)
      {
        get_element_coefficients(dofs, ghosted, e, c);
        const std::vector<double> &coefficients = c[component];
        add_element<dim>(
          space,
          cutter,
          e,
          coefficients,
          [&](const Point<dim> &p) {
            return space.evaluate_on_element(e, coefficients, p);
          },
          m);
      }
    m.boundary = Utilities::MPI::sum(m.boundary, comm);
    m.inside   = Utilities::MPI::sum(m.inside, comm);
    return m;
  }


  template ZeroSetMeasures
  zero_set_measures(const SplineSpace<2> &,
                    const std::vector<double> &,
                    unsigned int,
                    unsigned int,
                    unsigned int);
  template ZeroSetMeasures
  zero_set_measures(const SplineSpace<3> &,
                    const std::vector<double> &,
                    unsigned int,
                    unsigned int,
                    unsigned int);
  template ZeroSetMeasures
  zero_set_measures(const SplineDofHandler<2> &,
                    const TrilinosWrappers::MPI::Vector &,
                    unsigned int,
                    unsigned int);
  template ZeroSetMeasures
  zero_set_measures(const SplineDofHandler<3> &,
                    const TrilinosWrappers::MPI::Vector &,
                    unsigned int,
                    unsigned int);
} // namespace vesicle_iga
