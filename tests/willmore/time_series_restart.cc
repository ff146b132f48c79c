// TimeSeriesWriter on a restart (io/time_series): the rows up to the
// restart step are kept, later rows dropped, and a file written with other
// columns (an older version, before interface_speed was added) is rewritten
// in the new columns by name, with "nan" where the old file had none. A
// last row cut short by a killed run (here "5,51,5": a value and a column
// missing) is dropped on restart, whatever the restart step. (A row cut
// inside its last number looks complete, but it is always later than the
// last checkpoint, so the restart step drops it.)
// Expected output checked by hand: the header is the new one; rows 1 and 2
// keep their values under the same names (a = 10, 20; c = 30, 40), b is
// nan in them; row 3 of the old file is gone; the new row 3 follows; row 4
// is kept, the cut row 5 is gone and the new row 5 follows.

#include <deal.II/base/mpi.h>

#include <vesicle_iga/io/time_series.h>

#include <fstream>
#include <iostream>

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream("series.csv") << "step,a,c\n1,10,30\n2,20,40\n3,99,99\n";
  {
    vesicle_iga::TimeSeriesWriter series("series.csv",
                                         {"step", "a", "b", "c"},
                                         MPI_COMM_WORLD,
                                         2);
    series.add_row({3, 31, 32, 33});
  }
  {
    // Same columns: the rows are kept as they are.
    vesicle_iga::TimeSeriesWriter series("series.csv",
                                         {"step", "a", "b", "c"},
                                         MPI_COMM_WORLD,
                                         3);
    series.add_row({4, 41, 42, 43});
  }
  std::ofstream("series.csv", std::ios::app) << "5,51,5";
  {
    vesicle_iga::TimeSeriesWriter series("series.csv",
                                         {"step", "a", "b", "c"},
                                         MPI_COMM_WORLD,
                                         10);
    series.add_row({5, 51, 52, 53});
  }
  std::ifstream in("series.csv");
  std::ofstream out("output");
  for (std::string line; std::getline(in, line);)
    out << line << '\n';
}
