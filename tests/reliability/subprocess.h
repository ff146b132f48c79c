// For the tests of runs that are killed, interrupted or fail on one rank:
// these must run the real program as a separate process (or a separate
// mpirun job), since what is tested ends the process. Linux only (fork,
// exec, /proc).
#pragma once

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

/// The program under test and how to start it on N ranks (compile
/// definitions of tests/reliability/CMakeLists.txt).
inline std::string
program_command(const unsigned int ranks, const std::string &prm)
{
  const std::string binary = VESICLE_IGA_BINARY;
  if (ranks == 1)
    return binary + " " + prm;
  return std::string(VESICLE_IGA_MPIEXEC)
         + " --allow-run-as-root --oversubscribe -n " + std::to_string(ranks)
         + " " + binary + " " + prm;
}

struct ProcessResult
{
  int         exit_code = -1; ///< exit status, or -1 if killed by a signal
  int         signal    = 0;  ///< the signal that killed it, if any
  bool        timed_out = false;
  std::string output; ///< stdout and stderr
};

/// Starts "/bin/sh -c command" with stdout and stderr to @p log and the
/// extra environment @p environment ("NAME=value" entries).
inline pid_t
start_process(const std::string              &command,
              const std::string              &log,
              const std::vector<std::string> &environment = {})
{
  const pid_t pid = fork();
  if (pid == 0)
    {
      for (const auto &e : environment)
        putenv(const_cast<char *>(e.c_str()));
      if (!std::freopen(log.c_str(), "w", stdout))
        _exit(126);
      dup2(fileno(stdout), fileno(stderr));
      execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), nullptr);
      _exit(127);
    }
  return pid;
}

/// Waits for @p pid at most @p timeout seconds (then kills it).
inline ProcessResult
wait_process(const pid_t pid, const double timeout, const std::string &log)
{
  ProcessResult r;
  const auto    start  = std::chrono::steady_clock::now();
  int           status = 0;
  for (;;)
    {
      if (waitpid(pid, &status, WNOHANG) == pid)
        break;
      if (std::chrono::duration<double>(std::chrono::steady_clock::now()
                                        - start)
            .count()
          > timeout)
        {
          r.timed_out = true;
          kill(pid, SIGKILL);
          waitpid(pid, &status, 0);
          break;
        }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  if (WIFEXITED(status))
    r.exit_code = WEXITSTATUS(status);
  else if (WIFSIGNALED(status))
    r.signal = WTERMSIG(status);
  std::ifstream     f(log);
  std::stringstream s;
  s << f.rdbuf();
  r.output = s.str();
  return r;
}

inline ProcessResult
run_process(const std::string              &command,
            const double                    timeout,
            const std::vector<std::string> &environment = {})
{
  return wait_process(start_process(command, "process.log", environment),
                      timeout,
                      "process.log");
}

/// The processes whose parent is @p parent (the ranks of an mpirun job).
inline std::vector<pid_t>
children_of(const pid_t parent)
{
  std::vector<pid_t> children;
  for (const auto &entry : std::filesystem::directory_iterator("/proc"))
    {
      const std::string name = entry.path().filename();
      if (name.find_first_not_of("0123456789") != std::string::npos)
        continue;
      std::ifstream stat(entry.path() / "stat");
      std::string   line;
      std::getline(stat, line);
      // pid (comm) state ppid ...: comm may hold spaces, so parse after ')'.
      const auto close = line.rfind(')');
      if (close == std::string::npos)
        continue;
      std::istringstream rest(line.substr(close + 1));
      std::string        state;
      long               ppid = -1;
      rest >> state >> ppid;
      if (ppid == parent)
        children.push_back(std::stoi(name));
    }
  return children;
}

/// Number of lines of a file (0 if it does not exist).
inline unsigned int
count_lines(const std::string &filename)
{
  std::ifstream f(filename);
  unsigned int  n = 0;
  for (std::string line; std::getline(f, line);)
    ++n;
  return n;
}

/// The whole content of a file ("" if missing), to check that a file was
/// not touched.
inline std::string
file_content(const std::string &filename)
{
  std::ifstream     f(filename, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/// Whether @p text contains @p part, as "yes"/"no" for the outputs.
inline std::string
contains(const std::string &text, const std::string &part)
{
  return text.find(part) != std::string::npos ? "yes" : "no";
}
