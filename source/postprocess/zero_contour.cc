#include <vesicle_iga/postprocess/edge_root.h>
#include <vesicle_iga/postprocess/zero_contour.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    /// The sample grid of one direction: the breakpoints, each element cut
    /// into @p samples equal parts.
    std::vector<double>
    sample_coordinates(const KnotVector &kv, const unsigned int samples)
    {
      const auto         &z = kv.breakpoints();
      std::vector<double> x;
      for (unsigned int e = 0; e + 1 < z.size(); ++e)
        for (unsigned int k = 0; k < samples; ++k)
          x.push_back(z[e] + (z[e + 1] - z[e]) * k / samples);
      x.push_back(z.back());
      return x;
    }


    /// Marching squares on the sample grid of one component, with the
    /// crossings on the grid edges found on the spline itself.
    class MarchingSquares
    {
    public:
      MarchingSquares(const SplineSpace<2>      &space,
                      const std::vector<double> &natural,
                      const unsigned int         n_components,
                      const unsigned int         component,
                      const unsigned int         samples_per_element)
        : space(space)
        , natural(natural)
        , n_components(n_components)
        , component(component)
        , samples(samples_per_element)
        , x(sample_coordinates(space.knot_vector(0), samples))
        , y(sample_coordinates(space.knot_vector(1), samples))
        , nx(x.size())
        , ny(y.size())
        , node_value(nx * ny, std::numeric_limits<double>::quiet_NaN())
      {
        // A B-spline lies in the convex hull of its coefficients: on an
        // element whose coefficients all have one sign (>= 0, or < 0) no
        // sample cell changes sign, so only the other elements are sampled,
        // and their nodes evaluated when first needed. The tolerance is
        // relative to the coefficients' range, which bounds the field's.
        double range = 0;
        for (unsigned int i = component; i < natural.size(); i += n_components)
          range = std::max(range, std::abs(natural[i]));
        tolerance = 1e-12 * std::max(range, 1e-300);
        std::vector<unsigned int> indices;
        for (unsigned int e = 0; e < space.n_elements(); ++e)
          {
            space.element_basis_indices(e, indices);
            bool all_negative = true, all_nonnegative = true;
            for (const unsigned int i : indices)
              {
                const double c  = natural[i * n_components + component];
                all_negative    = all_negative && c < 0;
                all_nonnegative = all_nonnegative && c >= 0;
              }
            if (all_negative || all_nonnegative)
              continue;
            const auto element = space.element_multi_index(e);
            for (unsigned int j = 0; j < samples; ++j)
              for (unsigned int i = 0; i < samples; ++i)
                add_cell(element[0] * samples + i, element[1] * samples + j);
          }
      }

      /// The chained pieces, each as its sequence of crossing points.
      std::vector<std::pair<std::vector<Point<2>>, bool>>
      curves()
      {
        std::vector<std::pair<std::vector<Point<2>>, bool>> result;
        std::map<long, bool>                                visited;
        // Open pieces first (they start at an edge with one neighbour),
        // then the closed ones.
        for (const bool open : {true, false})
          for (const auto &[edge, neighbours] : adjacency)
            if (!visited[edge] && (!open || neighbours.size() == 1))
              {
                std::vector<Point<2>> points;
                long                  previous = -1, current = edge;
                bool                  closed = false;
                for (;;)
                  {
                    visited[current] = true;
                    points.push_back(crossing(current));
                    long next = -1;
                    for (const long n : adjacency[current])
                      if (n != previous && !visited[n])
                        next = n;
                    if (next < 0)
                      {
                        for (const long n : adjacency[current])
                          if (n == edge && n != previous && points.size() > 2)
                            closed = true;
                        break;
                      }
                    previous = current;
                    current  = next;
                  }
                result.emplace_back(points, closed);
              }
        return result;
      }

      double
      value(const Point<2> &p) const
      {
        space.evaluate(natural, n_components, p, values);
        return values[component];
      }

    private:
      /// The field at sample node (i, j), evaluated on first use.
      double
      node(const unsigned int i, const unsigned int j)
      {
        double &v = node_value[j * nx + i];
        if (std::isnan(v))
          v = value({x[i], y[j]});
        return v;
      }

      /// Global id of the edge from node (i, j) along direction d.
      long
      edge_id(const unsigned int i,
              const unsigned int j,
              const unsigned int d) const
      {
        return d == 0 ? long(j) * (nx - 1) + i :
                        long(ny) * (nx - 1) + long(j) * nx + i;
      }

      void
      add_cell(const unsigned int i, const unsigned int j)
      {
        const double v[4]
          = {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)};
        // Edges: bottom (corners 0-1), right (1-2), top (3-2), left (0-3).
        const long edges[4]     = {edge_id(i, j, 0),
                                   edge_id(i + 1, j, 1),
                                   edge_id(i, j + 1, 0),
                                   edge_id(i, j, 1)};
        const int  corner[4][2] = {{0, 1}, {1, 2}, {3, 2}, {0, 3}};
        std::vector<unsigned int> cut;
        for (unsigned int k = 0; k < 4; ++k)
          if ((v[corner[k][0]] >= 0) != (v[corner[k][1]] >= 0))
            cut.push_back(k);
        if (cut.size() == 2)
          connect(edges[cut[0]], edges[cut[1]]);
        else if (cut.size() == 4)
          {
            // Saddle: the centre's sign says which pair of corners is
            // connected through the cell.
            const double centre
              = value({(x[i] + x[i + 1]) / 2, (y[j] + y[j + 1]) / 2});
            if ((centre >= 0) == (v[0] >= 0))
              {
                connect(edges[0], edges[1]); // corner 1 cut off
                connect(edges[2], edges[3]); // corner 3 cut off
              }
            else
              {
                connect(edges[3], edges[0]); // corner 0 cut off
                connect(edges[1], edges[2]); // corner 2 cut off
              }
          }
      }

      void
      connect(const long a, const long b)
      {
        adjacency[a].push_back(b);
        adjacency[b].push_back(a);
      }

      /// The zero of the spline on edge @p id, by the Illinois variant of
      /// regula falsi between the edge's end nodes.
      Point<2>
      crossing(const long id)
      {
        const long horizontal = long(ny) * (nx - 1);
        Point<2>   a, b;
        if (id < horizontal)
          {
            const unsigned int j = id / (nx - 1), i = id % (nx - 1);
            a = Point<2>(x[i], y[j]);
            b = Point<2>(x[i + 1], y[j]);
          }
        else
          {
            const unsigned int j = (id - horizontal) / nx,
                               i = (id - horizontal) % nx;
            a                    = Point<2>(x[i], y[j]);
            b                    = Point<2>(x[i], y[j + 1]);
          }
        const double t
          = edge_root([&](const double t) { return value(a + t * (b - a)); },
                      value(a),
                      value(b),
                      tolerance);
        return a + t * (b - a);
      }

      const SplineSpace<2>             &space;
      const std::vector<double>        &natural;
      const unsigned int                n_components, component;
      const unsigned int                samples;
      const std::vector<double>         x, y;
      const unsigned int                nx, ny;
      std::vector<double>               node_value;
      double                            tolerance;
      std::map<long, std::vector<long>> adjacency;
      mutable std::vector<double>       values;
    };


    double
    signed_area(const std::vector<Point<2>> &p)
    {
      double a = 0;
      for (unsigned int k = 0; k < p.size(); ++k)
        {
          const auto &q = p[k], &r = p[(k + 1) % p.size()];
          a += q[0] * r[1] - r[0] * q[1];
        }
      return a / 2;
    }
  } // namespace


  double
  ZeroContour::enclosed_area() const
  {
    // the repeated first point closes the polygon with a zero-length edge
    return closed ? signed_area(points) : 0.;
  }


  double
  ZeroContour::reduced_area() const
  {
    return closed && length() > 0 ?
             4 * M_PI * std::abs(enclosed_area()) / (length() * length()) :
             0.;
  }


  std::vector<ZeroContour>
  zero_contours(const SplineSpace<2>      &space,
                const std::vector<double> &natural,
                const unsigned int         n_components,
                const unsigned int         component,
                const unsigned int         samples_per_element)
  {
    MarchingSquares squares(
      space, natural, n_components, component, samples_per_element);
    std::vector<ZeroContour> contours;
    for (auto &[points, closed] : squares.curves())
      {
        if (closed)
          {
            // Counter-clockwise, starting at the rightmost point, so that
            // the files of two runs can be compared point by point.
            if (signed_area(points) < 0)
              std::reverse(points.begin(), points.end());
            const auto start
              = std::max_element(points.begin(),
                                 points.end(),
                                 [](const Point<2> &a, const Point<2> &b) {
                                   return a[0] < b[0]
                                          || (a[0] == b[0] && a[1] > b[1]);
                                 });
            std::rotate(points.begin(), start, points.end());
            points.push_back(points.front());
          }
        ZeroContour c;
        c.closed = closed;
        c.points = points;
        double s = 0;
        for (unsigned int k = 0; k < points.size(); ++k)
          {
            if (k > 0)
              s += points[k].distance(points[k - 1]);
            c.arc_length.push_back(s);
            std::vector<double> v;
            space.evaluate(natural, n_components, points[k], v);
            c.values.push_back(v);
          }
        contours.push_back(std::move(c));
      }
    std::sort(contours.begin(),
              contours.end(),
              [](const ZeroContour &a, const ZeroContour &b) {
                return a.length() > b.length();
              });
    return contours;
  }
} // namespace vesicle_iga
