// cpp-httplib's task queue for the HTTP front (issue 27): one thread per
// connection up to `max_threads`, so an event stream or a silent socket
// holds only its own thread and plain requests never wait behind them (the
// fixed pool of 12 let 100 event-stream clients or 16 silent sockets starve
// every GET). Beyond the cap connections wait in order.
#pragma once
#include <httplib.h>

#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <list>
#include <mutex>
#include <thread>

namespace sreh::serve {

class ConnectionThreads final : public httplib::TaskQueue {
 public:
  explicit ConnectionThreads(std::size_t max_threads) : max_(max_threads) {}
  ~ConnectionThreads() override { shutdown(); }
  void enqueue(std::function<void()> fn) override;
  void shutdown() override; // waits for every connection to finish
  std::size_t active() const;

 private:
  struct Worker {
    std::thread thread;
    std::atomic<bool> finished{false};
  };
  void run(Worker& self, std::function<void()> fn);
  void reap(); // joins finished workers (lock held)

  std::size_t max_;
  mutable std::mutex mutex_;
  std::list<Worker> workers_;
  std::size_t busy_ = 0;
  std::deque<std::function<void()>> pending_;
};

} // namespace sreh::serve
