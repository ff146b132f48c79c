// add_zero_normal_derivative_constraints (fields/dirichlet_constraints), the
// strong d phi / dn = 0 of the Part H phase fields (spec 4.10):
//  - the number of constrained coefficients is that of the first layer of
//    every non-periodic side (all functions minus the interior ones), each
//    counted once at edges and corners, summed over the ranks' owned
//    unknowns;
//  - arbitrary coefficients (c_g = sin(1.3 g + 0.7)) with the constraints
//    applied give a spline whose normal derivative vanishes on every
//    non-periodic face, edges and corners included, to round-off (checked
//    at 7^(dim-1) points per face and element, from the univariate
//    derivatives), while the component left out keeps a derivative of order
//    one there (so the check can fail);
//  - a periodic direction gets no condition.
// Cases: 2D cubic C^2, 6 x 4 elements on [0,3] x [0,2], two components of
// which the second is constrained; 3D cubic C^2, 4 x 3 x 5 elements,
// periodic in z. On 1 and 2 ranks (the constraint targets of a rank's
// lines are ghost unknowns on the partition boundary).

#include <deal.II/base/mpi.h>

#include <vesicle_iga/fields/dirichlet_constraints.h>
#include <vesicle_iga/parallel/patch_mesh.h>

#include <cmath>
#include <fstream>

using namespace vesicle_iga;
using namespace dealii;

template <int dim>
void
check(const std::string                 &name,
      const std::array<KnotVector, dim> &kv,
      const std::vector<bool>           &mask,
      const unsigned int                 expected_lines,
      std::ostream                      &out)
{
  const MPI_Comm              comm = MPI_COMM_WORLD;
  const SplineSpace<dim>      space(kv);
  const PatchMesh<dim>        mesh(comm, space, nullptr);
  const SplineDofHandler<dim> dofs(mesh, space, mask.size());

  AffineConstraints<double> constraints(dofs.locally_relevant_dofs());
  add_zero_normal_derivative_constraints<dim>(dofs, mask, constraints);
  constraints.close();
  unsigned int lines = 0;
  for (const auto g : dofs.locally_owned_dofs())
    lines += constraints.is_constrained(g) ? 1 : 0;
  lines = Utilities::MPI::sum(lines, comm);

  // Every rank holds all coefficients; the constraints of its relevant
  // unknowns cover the functions of its own elements.
  const unsigned int  n_dofs = dofs.n_dofs();
  std::vector<double> c(n_dofs);
  for (unsigned int g = 0; g < n_dofs; ++g)
    c[g] = std::sin(1.3 * g + 0.7);
  for (const auto &line : constraints.get_lines())
    {
      double v = line.inhomogeneity;
      for (const auto &[j, w] : line.entries)
        v += w * c[j];
      c[line.index] = v;
    }

  const unsigned int        p = space.knot_vector(0).degree();
  std::vector<unsigned int> basis;
  std::vector<double>       worst(mask.size(), 0.); // max |du/dn| per component
  for (const unsigned int e : mesh.locally_owned_elements())
    for (unsigned int f = 0; f < 2 * dim; ++f)
      {
        if (!space.element_at_face(e, f))
          continue;
        const unsigned int normal = f / 2;
        const auto         me     = space.element_multi_index(e);
        space.element_basis_indices(e, basis);
        const unsigned int n_points = Utilities::pow(7u, dim - 1);
        for (unsigned int s = 0; s < n_points; ++s)
          {
            // Univariate values (derivative in the normal direction).
            std::array<std::vector<double>, dim> value;
            for (unsigned int d = 0, t = s; d < dim; ++d)
              {
                const KnotVector &k = space.knot_vector(d);
                const double      a = k.breakpoints()[me[d]];
                const double      h = k.element_length(me[d]);
                double            x = a + h * ((t % 7) + 0.5) / 7.;
                if (d == normal)
                  x = (f % 2) ? a + h : a;
                else
                  t /= 7;
                value[d] = k.evaluate_on_element(me[d], x, 1)[d == normal];
              }
            for (unsigned int comp = 0; comp < mask.size(); ++comp)
              {
                double derivative = 0;
                for (unsigned int j = 0; j < basis.size(); ++j)
                  {
                    double       product = 1;
                    unsigned int r       = j;
                    for (unsigned int d = 0; d < dim; ++d, r /= p + 1)
                      product *= value[d][r % (p + 1)];
                    derivative += product * c[dofs.dof_index(basis[j], comp)];
                  }
                worst[comp] = std::max(worst[comp], std::abs(derivative));
              }
          }
      }
  out << name << ": constrained coefficients " << lines << " (expected "
      << expected_lines << ") " << (lines == expected_lines ? "ok" : "FAILED")
      << std::endl;
  for (unsigned int comp = 0; comp < mask.size(); ++comp)
    {
      const double w = Utilities::MPI::max(worst[comp], comm);
      out << "  component " << comp
          << (mask[comp] ? " (constrained): max |du/dn| on the faces < 1e-12 " :
                           " (free): max |du/dn| on the faces > 0.1 ")
          << ((mask[comp] ? w < 1e-12 : w > 0.1) ? "ok" : "FAILED")
          << std::endl;
    }
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    file("output");
  std::ostream &out = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ?
                        static_cast<std::ostream &>(file) :
                        static_cast<std::ostream &>(std::cerr);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    out.setstate(std::ios::badbit);

  // 9 x 7 functions, 7 x 5 interior: 28 in the first layer.
  check<2>("2D 6 x 4, second of two components",
           {KnotVector::uniform(3, 6, 0., 3.),
            KnotVector::uniform(3, 4, 0., 2.)},
           {false, true},
           28,
           out);
  // 7 x 6 x 5 functions (z periodic: 5), 5 x 4 x 5 interior: 110.
  check<3>("3D 4 x 3 x 5, periodic in z",
           {KnotVector::uniform(3, 4, 0., 1.),
            KnotVector::uniform(3, 3, 0., 1.),
            KnotVector::uniform(3, 5, 0., 1., -1, true)},
           {true},
           110,
           out);
}
