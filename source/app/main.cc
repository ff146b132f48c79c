#include <deal.II/base/mpi.h>

#include <vesicle_iga/app/program.h>

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  return vesicle_iga::run_program(
    std::vector<std::string>(argv + 1, argv + argc));
}
