#include "core/interruption.h"

#include "core/output_file.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

namespace shadelab
{
namespace
{
std::atomic<int> Caught{ 0 };

void Say(const char* text)
{
  (void)!write(STDERR_FILENO, text, std::strlen(text));
}

// SIGINT, SIGTERM: the first is noted, and the grace's alarm set.
void Note(int signal)
{
  int none = 0;
  if (Caught.compare_exchange_strong(none, signal))
  {
    alarm(GraceSeconds);
  }
}

// The grace is over: only async-signal-safe calls from here.
void Stop(int)
{
  const int signal = Caught.load();
  RemoveTemporariesNow();
  Say("shadelab: interrupted (");
  Say(SignalName(signal));
  Say("): stopped; no file was left unfinished\n");
  _exit(128 + signal);
}

void Handle(int signal, void (*handler)(int))
{
  struct sigaction action = {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(signal, &action, nullptr);
}
}

void CatchInterruptions()
{
  Handle(SIGALRM, Stop);
  Handle(SIGINT, Note);
  Handle(SIGTERM, Note);
}

int Interruption()
{
  return Caught.load();
}

const char* SignalName(int signal)
{
  return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal";
}
}
