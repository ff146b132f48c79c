#include <vesicle_iga/base/fault_injection.h>

#include <csignal>
#include <cstdlib>
#include <map>
#include <mutex>
#include <string>
#include <unistd.h>

namespace vesicle_iga
{
  namespace
  {
    struct Fault
    {
      unsigned int at = 0, count = 0;
      bool         persistent = false;
    };

    std::map<std::string, Fault> &
    faults()
    {
      static std::map<std::string, Fault> f = []() {
        std::map<std::string, Fault> m;
        const char *spec = std::getenv("VESICLE_IGA_TEST_FAULT");
        if (!spec)
          return m;
        std::string s(spec);
        std::size_t start = 0;
        while (start < s.size())
          {
            const std::size_t end   = std::min(s.find(',', start), s.size());
            const std::string item  = s.substr(start, end - start);
            const std::size_t colon = item.find(':');
            if (colon != std::string::npos)
              {
                Fault f;
                f.at                     = std::stoul(item.substr(colon + 1));
                f.persistent             = item.back() == '+';
                m[item.substr(0, colon)] = f;
              }
            start = end + 1;
          }
        return m;
      }();
      return f;
    }
  } // namespace


  bool
  fault_requested(const char *point)
  {
    auto &all = faults();
    if (all.empty())
      return false;
    static std::mutex           mutex;
    std::lock_guard<std::mutex> lock(mutex);
    const auto                  it = all.find(point);
    if (it == all.end())
      return false;
    Fault &f = it->second;
    ++f.count;
    return f.count == f.at || (f.persistent && f.count > f.at);
  }


  void
  kill_process()
  {
    ::kill(::getpid(), SIGKILL);
    std::_Exit(137);
  }
} // namespace vesicle_iga
