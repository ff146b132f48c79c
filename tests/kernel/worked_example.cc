// The worked example of doc/engine.md: a double-well term written in one
// header (double_well_example.h) checked against finite differences by the
// one checker, like every term of the program. Theory: the term is cubic
// in phi, so the central difference error falls as h^2 (>= 50 per factor
// 10 in h) until round-off.

#include <deal.II/base/quadrature_lib.h>

#include <vesicle_iga/fields/natural_numbering.h>
#include <vesicle_iga/kernel/jacobian_check.h>

#include <cmath>
#include <fstream>

#include "../root_output.h"
#include "double_well_example.h"

using namespace vesicle_iga;
using namespace dealii;

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = root_output();
  std::array<KnotVector, 2>        kv{
    {KnotVector::uniform(3, 6, -1, 1), KnotVector::uniform(3, 5, -1, 1)}};
  const SplineSpace<2>      space(kv);
  const PatchMesh<2>        mesh(MPI_COMM_WORLD, space, nullptr);
  const SplineDofHandler<2> dofs(mesh, space, 1);
  std::vector<double>       natural(space.n_basis());
  for (unsigned int i = 0; i < space.n_basis(); ++i)
    natural[i] = std::tanh(3 * space.greville_point(i).norm() - 1.5);
  TrilinosWrappers::MPI::Vector owned(dofs.locally_owned_dofs(),
                                      MPI_COMM_WORLD),
    phi(dofs.locally_owned_dofs(),
        dofs.locally_relevant_dofs(),
        MPI_COMM_WORLD);
  scatter_natural(dofs, natural, owned);
  phi = owned;

  DoubleWellTerm<2>  well(0, 0.7, 0.2);
  SystemAssembler<2> assembler(dofs, QGauss<1>(4));
  assembler.add_term(well);
  AssemblyState state;
  state.value = &phi;
  const AffineConstraints<double> none;
  const auto                      r = check_jacobian(
    assembler, state, none, test_direction(dofs, none), {1e-2, 1e-3, 1e-4});
  const auto &e = r.relative_difference;
  out << "double well: |FD - K d| / |K d| falls by >= 50 per factor 10 in h: "
      << (e[1] < 2e-2 * e[0] && e[2] < 2e-2 * e[1] ? "yes" : "NO") << std::endl;
}
