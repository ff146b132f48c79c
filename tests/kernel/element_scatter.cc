// The direct scatter of element matrices (kernel/element_scatter) against
// AffineConstraints::distribute_local_to_global, which it replaces on most
// elements: the same random element matrices and vectors go through both
// into two matrices and two vectors on the same sparsity pattern, and the
// results must be equal to the last bit (the direct path makes the same
// additions in the same order; any missing, doubled or misplaced entry, a
// wrong diagonal of a constrained row or a wrong row owned by another rank
// shows up as a non-zero difference). The constraints have all three kinds
// the scatter tells apart: dofs fixed to zero (direct path), dofs tied to
// others and an inhomogeneous one (general path). 2D with two components
// and a periodic direction, 3D with one component; the counts of elements
// on each path are summed over the ranks (the same on 1 and 2 ranks).

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <vesicle_iga/fields/spline_dof_handler.h>
#include <vesicle_iga/kernel/element_scatter.h>
#include <vesicle_iga/parallel/patch_mesh.h>

#include <fstream>
#include <random>

#include "../root_output.h"

using namespace vesicle_iga;
using namespace dealii;

template <int dim>
void
check(const SplineSpace<dim> &space,
      const unsigned int      n_components,
      std::ostream           &out)
{
  const MPI_Comm              comm = MPI_COMM_WORLD;
  const PatchMesh<dim>        mesh(comm, space, nullptr);
  const SplineDofHandler<dim> dofs(mesh, space, n_components);

  // Component 0 fixed to zero where its Greville point has x = 0; a few
  // dofs tied to two neighbours; one fixed to 1.3.
  AffineConstraints<double> constraints(dofs.locally_relevant_dofs());
  for (unsigned int i = 0; i < space.n_basis(); ++i)
    {
      const auto g = dofs.dof_index(i, 0);
      if (!dofs.locally_relevant_dofs().is_element(g))
        continue;
      if (space.greville_point(i)[0] == 0.)
        constraints.add_line(g);
      else if (i % 37 == 5 && i + 2 < space.n_basis())
        {
          constraints.add_line(g);
          constraints.add_entry(g, dofs.dof_index(i + 1, 0), 0.5);
          constraints.add_entry(g, dofs.dof_index(i + 2, 0), 0.25);
        }
      else if (i == space.n_basis() / 2)
        {
          constraints.add_line(g);
          constraints.set_inhomogeneity(g, 1.3);
        }
    }
  constraints.close();

  std::vector<types::global_dof_index> indices;
  // Rows of every dof (a tied dof distributes to dofs this rank may not
  // otherwise see; the problems are small).
  const IndexSet         all = complete_index_set(dofs.n_dofs());
  DynamicSparsityPattern dsp(dofs.n_dofs(), dofs.n_dofs(), all);
  for (const unsigned int e : mesh.locally_owned_elements())
    {
      dofs.element_dof_indices(e, indices);
      constraints.add_entries_local_to_global(indices, dsp, true);
    }
  SparsityTools::distribute_sparsity_pattern(dsp,
                                             dofs.locally_owned_dofs(),
                                             comm,
                                             all);
  TrilinosWrappers::SparseMatrix direct, reference;
  direct.reinit(dofs.locally_owned_dofs(),
                dofs.locally_owned_dofs(),
                dsp,
                comm);
  reference.reinit(dofs.locally_owned_dofs(),
                   dofs.locally_owned_dofs(),
                   dsp,
                   comm);
  TrilinosWrappers::MPI::Vector direct_rhs(dofs.locally_owned_dofs(), comm),
    reference_rhs(dofs.locally_owned_dofs(), comm);

  ElementScatter     scatter(constraints, &direct, &direct_rhs);
  const unsigned int n = dofs.n_element_dofs();
  FullMatrix<double> local(n, n);
  Vector<double>     local_rhs(n);
  for (const unsigned int e : mesh.locally_owned_elements())
    {
      // The element's own random numbers: the same on any number of ranks.
      std::mt19937                           rng(1000 + e);
      std::uniform_real_distribution<double> U(-1., 1.);
      for (unsigned int i = 0; i < n; ++i)
        {
          local_rhs(i) = U(rng);
          for (unsigned int j = 0; j < n; ++j)
            local(i, j) = (i + j) % 11 == 3 ? 0. : U(rng);
        }
      dofs.element_dof_indices(e, indices);
      scatter.add(local, local_rhs, indices);
      constraints.distribute_local_to_global(
        local, local_rhs, indices, reference, reference_rhs);
    }
  direct.compress(VectorOperation::add);
  reference.compress(VectorOperation::add);
  direct_rhs.compress(VectorOperation::add);
  reference_rhs.compress(VectorOperation::add);

  double difference = 0;
  for (const auto row : dofs.locally_owned_dofs())
    for (auto entry = reference.begin(row); entry != reference.end(row);
         ++entry)
      difference
        = std::max(difference,
                   std::abs(entry->value() - direct.el(row, entry->column())));
  difference = Utilities::MPI::max(difference, comm);
  reference.add(-1., direct);
  reference_rhs -= direct_rhs;
  const unsigned int n_direct
    = Utilities::MPI::sum(scatter.n_direct_elements(), comm);
  out << dim << "D, " << n_components << " component(s), " << space.n_elements()
      << " elements: " << n_direct << " on the direct path, "
      << space.n_elements() - n_direct << " on the general one; matrix "
      << (difference == 0. && reference.frobenius_norm() == 0. ? "identical" :
                                                                 "DIFFERS")
      << ", vector "
      << (reference_rhs.linfty_norm() == 0. ? "identical" : "DIFFERS")
      << std::endl;
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = root_output();
  check<2>(SplineSpace<2>(std::array<KnotVector, 2>{
             {KnotVector::uniform(2, 9, 0, 1),
              KnotVector::uniform(2, 8, 0, 1, -1, true)}}),
           2,
           out);
  check<3>(SplineSpace<3>(
             std::array<KnotVector, 3>{{KnotVector::uniform(3, 5, 0, 1),
                                        KnotVector::uniform(3, 4, 0, 1),
                                        KnotVector::uniform(2, 6, 0, 1)}}),
           1,
           out);
}
