#pragma once

#include <deal.II/base/mpi.h>

#include <string>

namespace vesicle_iga
{
  /**
   * One run per output directory: a lock file <directory>/.vesicle-iga.lock
   * holding the host and process id of the run that owns the directory,
   * created when the run starts and removed when it ends (normally, on an
   * error or on a signal). A second run refuses to start while the lock's
   * process lives; a lock left by a killed run on this host (its process is
   * gone) is taken over, so that a restart after a kill -9 starts. A lock
   * from another host cannot be checked: the message says how to remove it.
   */
  class OutputLock
  {
  public:
    /// Collective; throws InputError naming "Output directory".
    OutputLock(const std::string &directory, const MPI_Comm comm);
    ~OutputLock();
    OutputLock(const OutputLock &) = delete;
    OutputLock &
    operator=(const OutputLock &)
      = delete;

  private:
    std::string filename;
    bool        owner = false;
  };
} // namespace vesicle_iga
