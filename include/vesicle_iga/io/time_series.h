#pragma once

#include <deal.II/base/mpi.h>

#include <fstream>
#include <string>
#include <vector>

namespace vesicle_iga
{
  /**
   * A CSV time series written by rank 0 (time-series.csv of the flow
   * studies): a header naming the columns, then one row per accepted step
   * whose first column is the integer step number. Every row is flushed at
   * once, so a run that is killed keeps every row written so far. On a
   * restart from step n the rows up to n are kept and the file continues;
   * if the file has other columns (written by another version), its rows
   * are rewritten in the new columns, matched by name, "nan" where the old
   * file had no such column. A row cut short by a killed run is dropped,
   * and the kept rows are rewritten through a temporary file, so that a run
   * killed during a restart still has them. A row that cannot be written
   * (full disk, quota) is an error on every rank, naming the file.
   */
  class TimeSeriesWriter
  {
  public:
    /// @p restart_step < 0: a new file.
    TimeSeriesWriter(const std::string              &filename,
                     const std::vector<std::string> &columns,
                     const MPI_Comm                  communicator,
                     const long                      restart_step = -1);

    /// One value per column; the first is the step number.
    void
    add_row(const std::vector<double> &values);

    const std::vector<std::string> &
    columns() const
    {
      return names;
    }

  private:
    /// Rank 0: the header and the kept rows; false if it cannot write.
    bool
    start(const long restart_step);

    std::vector<std::string> names;
    std::string              filename;
    MPI_Comm                 communicator;
    std::ofstream            file;
  };
} // namespace vesicle_iga
