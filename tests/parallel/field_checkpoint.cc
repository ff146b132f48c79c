// Fields through a checkpoint file and back (io/field_checkpoint,
// io/checkpoint, fields/natural_numbering): a two-component field on a 2D
// space and a one-component field on a 3D space, with values f(natural
// index) so that a misplaced entry shows, are saved, written, read and
// loaded:
//  - save_field leaves each rank its own entries only (as many as it owns,
//    n in all), and every rank writes them into the file itself;
//  - the file holds f at its natural indices, whatever the number of ranks
//    that wrote it (rank 0 reads every entry back with read_field);
//  - after read(), no rank holds any value of a field, only its size;
//  - the layout of format 2 and 3 (the natural vector as a small vector on
//    every rank), which a restart must still read, and the current one
//    both load the original field exactly (max difference 0);
//  - the natural vector gathered on rank 0 (for samples) is f itself.
// Serial and on 2 and 3 ranks (the partition, hence the numbering of the
// unknowns and the runs of natural indices each rank writes, differs; the
// file must not).

#include <deal.II/base/mpi.h>

#include <vesicle_iga/fields/natural_numbering.h>
#include <vesicle_iga/io/field_checkpoint.h>
#include <vesicle_iga/parallel/patch_mesh.h>

#include <cmath>
#include <fstream>

#include "../root_output.h"

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
  const FieldPart &part = current.fields.at("test.field");
  const bool       own_part_only
    = part.values.size() == dofs.locally_owned_dofs().n_elements()
      && Utilities::MPI::sum(part.values.size(), comm) == dofs.n_dofs();
  older.vectors["test.field"] = natural;
  current.write("current.h5", comm);
  older.write("older.h5", comm);

  std::string result
    = std::string(", each rank saves its own part ")
      + (Utilities::MPI::min(int(own_part_only), comm) == 1 ? "ok" : "FAILED");
  {
    const Checkpoint           c = Checkpoint::read("current.h5", comm);
    std::vector<std::uint64_t> all;
    if (root)
      for (std::uint64_t i = 0; i < natural.size(); ++i)
        all.push_back(i);
    const bool in_file = c.read_field("test.field", all, comm)
                         == (root ? natural : std::vector<double>());
    result
      += std::string(", the file holds the natural field ")
         + (Utilities::MPI::min(int(in_file), comm) == 1 ? "ok" : "FAILED");
  }
  for (const auto &[layout, file] : {std::make_pair("current", "current.h5"),
                                     std::make_pair("format 2/3", "older.h5")})
    {
      const Checkpoint              c = Checkpoint::read(file, comm);
      TrilinosWrappers::MPI::Vector w(dofs.locally_owned_dofs(), comm);
      load_field(c, "test.field", dofs, w);
      w -= v;
      const bool sizes_only
        = !c.has_field("test.field")
          || (c.fields.at("test.field").size == dofs.n_dofs()
              && c.fields.at("test.field").values.empty());
      result += std::string(", ") + layout + ": loaded exactly "
                + (w.linfty_norm() == 0 ? "ok" : "FAILED") + ", no values held "
                + (Utilities::MPI::min(int(sizes_only), comm) == 1 ? "ok" :
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
  std::ofstream                    out = root_output();
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
