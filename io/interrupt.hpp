// SIGINT / SIGTERM for batch commands (issue 12): the handler only sets a
// flag (async-signal-safe); long loops call throw_if_interrupted(), the
// exception unwinds the stack so that every io::AtomicFile / AtomicDir
// removes its temporary, and main() exits 128 + signal (130 / 143). A second
// signal is absorbed (timeout(1) sends two), a third exits at once.
#pragma once
#include <stdexcept>

namespace sreh::io {

struct Interrupted : std::runtime_error {
  explicit Interrupted(int signal_number);
  int signal_number;
  int exit_code() const { return 128 + signal_number; }
};

void install_interrupt_handlers();  // SIGINT and SIGTERM; idempotent
int interrupt_signal();             // 0, or the signal received
void throw_if_interrupted();        // throws Interrupted once a signal arrived

} // namespace sreh::io
