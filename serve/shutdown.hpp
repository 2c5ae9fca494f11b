// Clean shutdown on SIGINT / SIGTERM without an asynchronous handler: the
// signals are blocked in every thread (block() before any thread starts)
// and the main thread takes them synchronously with sigtimedwait, so nothing
// runs in signal context. Self-contained, to be swapped for the project-wide
// handling (issue 12) by replacing this file's two calls.
#pragma once
#include <chrono>
#include <optional>

namespace sreh::serve {

// Blocks SIGINT and SIGTERM for this thread and the threads it starts later.
void block_shutdown_signals();

// Waits up to `timeout` for SIGINT/SIGTERM; returns the signal number, or
// nothing on timeout.
std::optional<int> wait_for_shutdown_signal(std::chrono::milliseconds timeout);

} // namespace sreh::serve
