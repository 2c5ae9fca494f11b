#include "io/interrupt.hpp"

#include <unistd.h>

#include <csignal>
#include <string>

namespace sreh::io {
namespace {

volatile std::sig_atomic_t g_signal = 0;
volatile std::sig_atomic_t g_count = 0;

// The first signal sets the flag; a repeat (timeout(1) and process-group
// kills deliver two) is absorbed so the cleanup can finish; the third ends
// the process at once (a stuck run can always be stopped).
extern "C" void on_signal(int signal_number) {
  if (g_signal == 0) g_signal = signal_number;
  g_count = g_count + 1;
  if (g_count >= 3) _exit(128 + signal_number);
}

} // namespace

Interrupted::Interrupted(int s)
    : std::runtime_error(std::string("interrupted by ") + (s == SIGINT ? "SIGINT" : s == SIGTERM ? "SIGTERM" : "a signal")),
      signal_number(s) {}

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interrupt_signal() { return g_signal; }

void throw_if_interrupted() {
  if (const int s = g_signal; s != 0) throw Interrupted(s);
}

} // namespace sreh::io
