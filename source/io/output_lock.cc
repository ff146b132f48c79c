#include <deal.II/base/utilities.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/io/output_lock.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <fstream>
#include <thread>
#include <unistd.h>

namespace vesicle_iga
{
  namespace
  {
    std::string
    this_host()
    {
      char name[256] = {};
      gethostname(name, sizeof(name) - 1);
      return name;
    }

    /// Whether process @p pid exists and is not a zombie.
    bool
    alive(const long pid)
    {
      if (::kill(pid, 0) != 0 && errno == ESRCH)
        return false;
      std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
      std::string   line;
      std::getline(stat, line);
      const auto close = line.rfind(')');
      return close == std::string::npos || close + 2 >= line.size()
             || line[close + 2] != 'Z';
    }

    /// Try to create the lock; "" on success, else why not.
    std::string
    acquire(const std::string &filename)
    {
      for (unsigned int attempt = 0; attempt < 2; ++attempt)
        {
          const int fd
            = ::open(filename.c_str(), O_CREAT | O_EXCL | O_WRONLY, 0644);
          if (fd >= 0)
            {
              const std::string content
                = this_host() + " " + std::to_string(::getpid()) + "\n";
              const bool written = ::write(fd, content.data(), content.size())
                                   == static_cast<ssize_t>(content.size());
              ::close(fd);
              return written ? "" : "the lock file could not be written";
            }
          if (errno != EEXIST)
            return "the lock file cannot be created";
          std::string host;
          long        pid = -1;
          std::ifstream(filename) >> host >> pid;
          // A run that has just been killed may take a moment to be gone
          // (mpirun returns while its ranks still exit): wait up to 5 s.
          bool stale = false;
          for (unsigned int wait = 0; wait < 50 && !stale; ++wait)
            {
              stale = host == this_host() && pid > 0 && !alive(pid);
              if (!stale && host == this_host())
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
            }
          if (!stale)
            return "the run of process " + std::to_string(pid) + " on host "
                   + host + " holds " + filename
                   + " (if that run has ended, remove the file)";
          std::remove(filename.c_str()); // left by a killed run: take over
        }
      return "the lock file cannot be created";
    }
  } // namespace


  OutputLock::OutputLock(const std::string &directory, const MPI_Comm comm)
    : filename(directory + "/.vesicle-iga.lock")
  {
    const bool  root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    std::string why  = root ? acquire(filename) : "";
    why              = dealii::Utilities::MPI::broadcast(comm, why, 0);
    owner            = root && why.empty();
    check_input(why.empty(),
                "Output directory",
                directory,
                "a directory no other run is writing to: " + why);
  }


  OutputLock::~OutputLock()
  {
    if (owner)
      std::remove(filename.c_str());
  }
} // namespace vesicle_iga
