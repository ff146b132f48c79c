// Fields through a checkpoint file and back (io/field_checkpoint,
// fields/natural_numbering): a two-component field on a 2D space and a
// one-component field on a 3D space, with values f(natural index) so that
// a misplaced entry shows, are saved, written, read and loaded:
//  - in the layout of format 4 (save_field: gathered on rank 0 only);
//  - in the layout of format 2 and 3 (the natural vector as a small
//    vector on every rank), which a restart must still read;
//  - both load the original field exactly (max difference 0);
//  - after the read, the fields are held by rank 0 only (sizes on every
//    rank, data on rank 0, none elsewhere);
//  - the natural vector gathered on rank 0 is f itself.
// Serial and on 2 and 3 ranks (the partition, hence the numbering of the
// unknowns, differs; the natural values must not).

#include <deal.II/base/mpi.h>

#include <vesicle_iga/fields/natural_numbering.h>
#include <vesicle_iga/io/field_checkpoint.h>
#include <vesicle_iga/parallel/patch_mesh.h>

#include <cmath>
#include <fstream>

using namespace vesicle_iga;
using namespace dealii;

double
f(const unsigned int i)
{
  return std::sin(0.37 * i) + 0.001 * i;
}

template <int dim>
void
check(const std::string      &name,
      const SplineSpace<dim> &space,
      const unsigned int      n_components,
      std::ostream           &out)
{
  const MPI_Comm       comm = MPI_COMM_WORLD;
  const bool           root = Utilities::MPI::this_mpi_process(comm) == 0;
  const PatchMesh<dim> mesh(comm, space, nullptr);
  const SplineDofHandler<dim> dofs(mesh, space, n_components);
  std::vector<double>         natural(dofs.n_dofs());
  for (unsigned int i = 0; i < natural.size(); ++i)
    natural[i] = f(i);
  TrilinosWrappers::MPI::Vector v(dofs.locally_owned_dofs(), comm);
  scatter_natural(dofs, natural, v);

  const auto gathered    = gather_natural_on_rank_0(dofs, v);
  const bool gathered_ok = root ? gathered == natural : gathered.empty();

  Checkpoint current, older;
  save_field(current, "test.field", dofs, v);
  older.vectors["test.field"] = natural;
  current.write("current.h5", comm);
  older.write("older.h5", comm);

  std::string result;
  for (const auto &[layout, file] : {std::make_pair("format 4", "current.h5"),
                                     std::make_pair("format 2/3", "older.h5")})
    {
      const Checkpoint              c = Checkpoint::read(file, comm);
      TrilinosWrappers::MPI::Vector w(dofs.locally_owned_dofs(), comm);
      load_field(c, "test.field", dofs, w);
      w -= v;
      const bool on_rank_0_only
        = !c.has_field("test.field")
          || (c.field_sizes.at("test.field") == dofs.n_dofs()
              && c.fields.size() == (root ? 1u : 0u));
      result
        += std::string(", ") + layout + ": loaded exactly "
           + (w.linfty_norm() == 0 ? "ok" : "FAILED") + ", held by rank 0 only "
           + (Utilities::MPI::min(int(on_rank_0_only), comm) == 1 ? "ok" :
                                                                    "FAILED");
    }
  out << name << " (" << dofs.n_dofs() << " unknowns): gathered on rank 0 "
      << (Utilities::MPI::min(int(gathered_ok), comm) == 1 ? "ok" : "FAILED")
      << result << "\n";
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ?
                      "output" :
                      "/dev/null");
  check<2>("2D, 2 components",
           SplineSpace<2>(std::array<KnotVector, 2>{
             {KnotVector::uniform(2, 9, 0, 1),
              KnotVector::uniform(3, 6, 0, 1, -1, true)}}),
           2,
           out);
  check<3>("3D, 1 component",
           SplineSpace<3>(
             std::array<KnotVector, 3>{{KnotVector::uniform(2, 5, 0, 1),
                                        KnotVector::uniform(2, 4, 0, 1),
                                        KnotVector::uniform(3, 6, 0, 1)}}),
           1,
           out);
}
