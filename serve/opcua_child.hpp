// A child process with its stdin and stdout as pipes (the OPC UA front's
// Node.js process, issue 38): started with the parent's blocked signals
// unblocked and a parent-death signal, so it never outlives serve; stderr is
// serve's. Lines are written whole under a lock; read_line() blocks.
#pragma once
#include <sys/types.h>

#include <cstdio>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace sreh::serve {

class ChildProcess {
 public:
  // Throws std::runtime_error if it cannot be started (fork, pipes, exec).
  ChildProcess(const std::vector<std::string>& argv, const std::string& cwd);
  ~ChildProcess(); // kills and reaps it if still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  bool write_line(const std::string& line); // false once the pipe is broken
  std::optional<std::string> read_line();   // nullopt at end of file
  void close_stdin();
  // Waits up to timeout_ms for it to exit (then SIGKILL); returns the wait status.
  int stop(int timeout_ms);
  // Non-blocking: the wait status if it has exited.
  std::optional<int> poll();

 private:
  pid_t pid_ = -1;
  int in_fd_ = -1;          // its stdin
  std::FILE* out_ = nullptr; // its stdout
  std::mutex write_mutex_;
  std::optional<int> status_;
};

// "exit code 1", "signal 9 (Killed)".
std::string describe_wait_status(int status);

} // namespace sreh::serve
