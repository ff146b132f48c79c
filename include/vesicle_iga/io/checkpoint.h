#pragma once

#include <deal.II/base/mpi.h>

#include <map>
#include <string>
#include <vector>

namespace vesicle_iga
{
  /**
   * A checkpoint: named vectors (full, in the natural numbering of the
   * spline basis, so that a run can restart on any number of ranks) and
   * named scalars, stored as an HDF5 file (datasets and attributes).
   * Writing goes to "<file>.tmp" and is renamed when complete, so a run
   * killed while writing still has its previous checkpoint.
   */
  struct Checkpoint
  {
    std::map<std::string, std::vector<double>> vectors;
    std::map<std::string, double>              scalars;

    /// Collective; the vectors must be complete on rank 0.
    void
    write(const std::string &filename, const MPI_Comm comm) const;
    /// Collective; every rank gets everything. Throws InputError naming
    /// "Restart from" if the file cannot be read.
    static Checkpoint
    read(const std::string              &filename,
         const MPI_Comm                  comm,
         const std::vector<std::string> &vector_names,
         const std::vector<std::string> &scalar_names);
  };
} // namespace vesicle_iga
