#include <deal.II/base/mpi.h>

#include <vesicle_iga/postprocess/crossing_tolerance.h>
#include <vesicle_iga/postprocess/edge_root.h>
#include <vesicle_iga/postprocess/zero_contour.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <unordered_map>

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


    /// Marching squares on the sample grid, element by element, with the
    /// crossings on the grid edges found on the spline itself. The segments
    /// are kept as pairs of edge ids with one crossing point per edge, so
    /// that the segments of several ranks can be chained on one.
    class MarchingSquares
    {
    public:
      using Field = std::function<double(const Point<2> &)>;

      MarchingSquares(const SplineSpace<2> &space,
                      const unsigned int    samples_per_element,
                      const double          tolerance)
        : samples(samples_per_element)
        , x(sample_coordinates(space.knot_vector(0), samples))
        , y(sample_coordinates(space.knot_vector(1), samples))
        , nx(x.size())
        , ny(y.size())
        , tolerance(tolerance)
      {}

      /// The sample cells of element (ex, ey), on which @p f evaluates
      /// the spline.
      void
      add_element(const std::array<unsigned int, 2> &element, const Field &f)
      {
        field = &f;
        for (unsigned int j = 0; j < samples; ++j)
          for (unsigned int i = 0; i < samples; ++i)
            add_cell(element[0] * samples + i, element[1] * samples + j);
        field = nullptr;
      }

      /// What add_element() found: segments as edge pairs, and the
      /// crossing point of every edge they use (flattened: id, x, y).
      const std::vector<long> &
      segment_edges() const
      {
        return segments;
      }
      std::vector<double>
      flat_crossings() const
      {
        std::vector<double> flat;
        for (const auto &[id, p] : crossings)
          flat.insert(flat.end(), {double(id), p[0], p[1]});
        return flat;
      }
      /// Adds segments and crossings found elsewhere (another rank).
      void
      merge(const std::vector<long> &edges, const std::vector<double> &flat)
      {
        for (unsigned int k = 0; k + 1 < edges.size(); k += 2)
          connect(edges[k], edges[k + 1]);
        for (unsigned int k = 0; k + 2 < flat.size(); k += 3)
          crossings.emplace(long(flat[k]), Point<2>(flat[k + 1], flat[k + 2]));
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
                    points.push_back(crossings.at(current));
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

    private:
      /// The field at sample node (i, j), evaluated on first use.
      double
      node(const unsigned int i, const unsigned int j)
      {
        const long key   = long(j) * nx + i;
        const auto found = node_value.find(key);
        if (found != node_value.end())
          return found->second;
        return node_value[key] = (*field)({x[i], y[j]});
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
        for (const unsigned int k : cut)
          add_crossing(edges[k]);
        if (cut.size() == 2)
          add_segment(edges[cut[0]], edges[cut[1]]);
        else if (cut.size() == 4)
          {
            // Saddle: the centre's sign says which pair of corners is
            // connected through the cell.
            const double centre
              = (*field)({(x[i] + x[i + 1]) / 2, (y[j] + y[j + 1]) / 2});
            if ((centre >= 0) == (v[0] >= 0))
              {
                add_segment(edges[0], edges[1]); // corner 1 cut off
                add_segment(edges[2], edges[3]); // corner 3 cut off
              }
            else
              {
                add_segment(edges[3], edges[0]); // corner 0 cut off
                add_segment(edges[1], edges[2]); // corner 2 cut off
              }
          }
      }

      void
      add_segment(const long a, const long b)
      {
        segments.insert(segments.end(), {a, b});
        connect(a, b);
      }

      void
      connect(const long a, const long b)
      {
        adjacency[a].push_back(b);
        adjacency[b].push_back(a);
      }

      /// The zero of the spline on edge @p id, by the Illinois variant of
      /// regula falsi between the edge's end nodes.
      void
      add_crossing(const long id)
      {
        if (crossings.count(id) != 0)
          return;
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
          = edge_root([&](const double t) { return (*field)(a + t * (b - a)); },
                      (*field)(a),
                      (*field)(b),
                      tolerance);
        crossings[id] = a + t * (b - a);
      }

      const unsigned int                samples;
      const std::vector<double>         x, y;
      const unsigned int                nx, ny;
      const double                      tolerance;
      const Field                      *field = nullptr;
      std::unordered_map<long, double>  node_value;
      std::map<long, Point<2>>          crossings;
      std::map<long, std::vector<long>> adjacency;
      std::vector<long>                 segments;
    };


    /// Does the component change sign among the coefficients @p c of an
    /// element? If not, the element holds no zero: a B-spline lies in the
    /// convex hull of its coefficients.
    bool
    changes_sign(const std::vector<double> &c)
    {
      bool all_negative = true, all_nonnegative = true;
      for (const double v : c)
        {
          all_negative    = all_negative && v < 0;
          all_nonnegative = all_nonnegative && v >= 0;
        }
      return !all_negative && !all_nonnegative;
    }


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


    /// The pieces of @p squares as contours (without values), closed ones
    /// counter-clockwise from their rightmost point, longest first.
    std::vector<ZeroContour>
    chain(MarchingSquares &squares)
    {
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
    MarchingSquares              squares(space,
                            samples_per_element,
                            crossing_tolerance(natural,
                                               n_components,
                                               component));
    std::vector<double>          values;
    const MarchingSquares::Field field = [&](const Point<2> &p) {
      space.evaluate(natural, n_components, p, values);
      return values[component];
    };
    std::vector<unsigned int> indices;
    std::vector<double>       c;
    for (unsigned int e = 0; e < space.n_elements(); ++e)
      {
        space.element_basis_indices(e, indices);
        c.clear();
        for (const unsigned int i : indices)
          c.push_back(natural[i * n_components + component]);
        if (changes_sign(c))
          squares.add_element(space.element_multi_index(e), field);
      }
    auto contours = chain(squares);
    for (ZeroContour &c : contours)
      for (const Point<2> &p : c.points)
        {
          std::vector<double> v;
          space.evaluate(natural, n_components, p, v);
          c.values.push_back(v);
        }
    return contours;
  }


  std::vector<ZeroContour>
  zero_contours(const SplineDofHandler<2>           &dofs,
                const TrilinosWrappers::MPI::Vector &ghosted,
                const unsigned int                   component,
                const unsigned int                   samples_per_element)
  {
    const SplineSpace<2> &space = dofs.get_space();
    const MPI_Comm        comm  = dofs.get_mesh().get_communicator();
    const auto           &own   = dofs.get_mesh().locally_owned_elements();
    std::vector<std::vector<double>> c;
    MarchingSquares                  squares(space,
                            samples_per_element,
                            crossing_tolerance(dofs, ghosted, component));
    for (const unsigned int e : own)
      {
        get_element_coefficients(dofs, ghosted, e, c);
        const std::vector<double> &coefficients = c[component];
        if (changes_sign(coefficients))
          squares.add_element(
            space.element_multi_index(e), [&](const Point<2> &p) {
              return space.evaluate_on_element(e, coefficients, p);
            });
      }
    // Only the segments and their crossings travel: O(length of the set).
    const auto edges = Utilities::MPI::gather(comm, squares.segment_edges());
    const auto flat  = Utilities::MPI::gather(comm, squares.flat_crossings());
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return {};
    MarchingSquares all(space, samples_per_element, 0.);
    for (unsigned int r = 0; r < edges.size(); ++r)
      all.merge(edges[r], flat[r]);
    return chain(all);
  }
} // namespace vesicle_iga
