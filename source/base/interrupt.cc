#include <vesicle_iga/base/interrupt.h>

#include <csignal>
#include <unistd.h>

namespace vesicle_iga
{
  namespace
  {
    volatile std::sig_atomic_t received  = 0;
    const int                  handled[] = {SIGTERM, SIGINT, SIGUSR1};
    struct sigaction           previous[3];

    extern "C" void
    on_signal(const int signal)
    {
      if (received != 0)
        ::_exit(128 + signal); // the second signal: at once
      received = signal;
    }
  } // namespace


  InterruptHandler::InterruptHandler()
  {
    received                = 0;
    struct sigaction action = {};
    action.sa_handler       = on_signal;
    action.sa_flags         = SA_RESTART;
    sigemptyset(&action.sa_mask);
    for (unsigned int k = 0; k < 3; ++k)
      sigaction(handled[k], &action, &previous[k]);
  }


  InterruptHandler::~InterruptHandler()
  {
    for (unsigned int k = 0; k < 3; ++k)
      sigaction(handled[k], &previous[k], nullptr);
  }


  int
  InterruptHandler::signal_received()
  {
    return received;
  }


  std::string
  InterruptHandler::name(const int signal)
  {
    switch (signal)
      {
        case SIGTERM:
          return "SIGTERM";
        case SIGINT:
          return "SIGINT";
        case SIGUSR1:
          return "SIGUSR1";
        default:
          return "signal " + std::to_string(signal);
      }
  }
} // namespace vesicle_iga
