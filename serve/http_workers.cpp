#include "serve/http_workers.hpp"

namespace sreh::serve {

void ConnectionThreads::reap() {
  for (auto it = workers_.begin(); it != workers_.end();) {
    if (it->finished.load()) {
      it->thread.join();
      it = workers_.erase(it);
    } else {
      ++it;
    }
  }
}

void ConnectionThreads::enqueue(std::function<void()> fn) {
  std::lock_guard lock(mutex_);
  reap();
  if (busy_ >= max_) {
    pending_.push_back(std::move(fn));
    return;
  }
  ++busy_;
  Worker& w = workers_.emplace_back();
  w.thread = std::thread([this, &w, fn = std::move(fn)]() mutable { run(w, std::move(fn)); });
}

void ConnectionThreads::run(Worker& self, std::function<void()> fn) {
  for (;;) {
    fn();
    std::lock_guard lock(mutex_);
    if (pending_.empty()) {
      --busy_;
      self.finished.store(true);
      return;
    }
    fn = std::move(pending_.front());
    pending_.pop_front();
  }
}

void ConnectionThreads::shutdown() {
  std::list<Worker> all;
  {
    std::lock_guard lock(mutex_);
    all.splice(all.end(), workers_);
  }
  for (auto& w : all) w.thread.join(); // a worker also drains what is pending
}

std::size_t ConnectionThreads::active() const {
  std::lock_guard lock(mutex_);
  return busy_;
}

} // namespace sreh::serve
