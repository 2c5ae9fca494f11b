// The virtual IO-Link master's ports (issue 18): one twin per port, paced to
// the wall clock by one thread, shared by the Modbus, HTTP and MQTT fronts.
// Every access to a twin goes through with_port() under that port's lock, so
// a request lands between two IO-Link cycles, as on a real master.
#pragma once
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <string>
#include <thread>
#include <vector>

#include "scenarios/data_storage_master.hpp"
#include "twin/twin.hpp"
#include "twin/twin_snapshot.hpp"

namespace sreh::serve {

class StateDir; // serve/state_dir.hpp

// What a port shows beyond the twin itself: the faults injected so far.
struct FaultState {
  bool link_up = true;
  double supply_V = 24.0;
  double external_torque_Nm = 0.0;
  bool flange_blocked = false;
  double ambient_C = 25.0;
  uint32_t power_cycles = 0;
  uint32_t device_replacements = 0;
};

// A change the state folder could not take (full disk, I/O error, read-only):
// the twin was put back as it was before it and nothing is acknowledged. The
// fronts answer the IO-Link code (0x8082 Application not ready: the master's
// non-volatile store cannot take the write now; retry once it can).
struct StateWriteFailed : std::runtime_error {
  StateWriteFailed(uint16_t code_, const std::string& what) : std::runtime_error(what), code(code_) {}
  uint16_t code;
};

// One entry of a port's event stream (SSE, MQTT): `type` is "state",
// "device_event" or "sample"; `json` the payload object as text. `seq`
// counts over every port of the hub (one cursor follows several ports).
struct PortEvent {
  uint64_t seq = 0;
  std::string type;
  std::string json;
};

// Pacing figures: lateness of each cycle's start against its wall-clock
// deadline (the jitter of the master cycle).
struct PacingStats {
  uint64_t cycles = 0;
  uint64_t late_cycles = 0;    // started more than one cycle after their deadline
  double jitter_p50_us = 0;
  double jitter_p99_us = 0;
  double jitter_max_us = 0;
  double sim_time_s = 0;
  double wall_time_s = 0;      // since start
  double busy_fraction = 0;    // time spent computing cycles / wall time
  bool realtime_scheduling = false; // SCHED_FIFO granted to the pacing thread
};

struct HubOptions {
  double cycle_s = 0.002;      // IO-Link master cycle
  double speed = 1.0;          // simulated seconds per wall-clock second
  int rt_priority = 0;         // > 0: the pacing thread asks for SCHED_FIFO at this priority
  int sample_every_cycles = 5; // telemetry samples for the live page (every 10 ms at 2 ms)
};

class Hub {
 public:
  struct Port {
    explicit Port(const TwinConfig& config) : twin(config) {}
    std::mutex mutex;          // guards everything below
    Twin twin;
    bool outputs_valid = true;
    FaultState faults;
    double nominal_supply_V = 24.0, nominal_ambient_C = 25.0; // the port configuration's, not a fault
    // Event log for subscribers (bounded ring).
    std::deque<PortEvent> events;
    std::atomic<uint64_t>* seq_source = nullptr; // the hub's counter, shared by every port
    uint64_t last_seq = 0;                        // of the newest event in `events`
    std::condition_variable event_cv;
    // Change detection for events.
    State last_state = State::MotorOff;
    uint8_t last_error = 0, last_warning = 0;
    LedColor last_led = LedColor::Off;
    std::vector<uint8_t> last_detailed_status; // index 37
    bool first = true;
    std::string failure; // the plant failed (MuJoCo instability): the port stops, the server goes on
    // Data Storage at the master (scenarios/data_storage_master.hpp): the backup, whether it
    // changed since it was written, and a download owed to a replacement
    // module (made in its first cycle in OPERATE).
    std::optional<DsBackup> ds_backup;
    uint64_t ds_generation = 0;
    bool ds_download_pending = false; // also in the backup file (download_owed)
    bool fresh_module = false;        // started without a memory image in the state folder
    uint16_t ds_last_error = 0; // IO-Link code of the last refused download, 0 if none
    // --state-dir: captures are numbered so an older image never overwrites
    // a newer one; the last write's failure ("" once a write succeeds again).
    uint64_t state_seq = 0;
    std::string state_write_error;
  };

  Hub(const std::vector<TwinConfig>& configs, const HubOptions& options);
  ~Hub();
  Hub(const Hub&) = delete;
  Hub& operator=(const Hub&) = delete;

  int port_count() const { return static_cast<int>(ports_.size()); }
  bool valid_port(int p) const { return p >= 1 && p <= port_count(); }
  Port& port(int p) { return *ports_.at(static_cast<std::size_t>(p - 1)); } // 1-based as on a master
  const HubOptions& options() const { return options_; }

  // Runs f(Port&) under the port's lock; returns what f returns.
  template <class F>
  auto with_port(int p, F&& f) {
    Port& port_ref = port(p);
    std::lock_guard lock(port_ref.mutex);
    return f(port_ref);
  }

  // Appends an event (port lock held by the caller) and wakes subscribers.
  static void push_event(Port& port, std::string type, std::string json);
  // Events after `after_seq`, waiting up to `timeout` for one to arrive.
  std::vector<PortEvent> events_after(int p, uint64_t after_seq, std::chrono::milliseconds timeout);
  uint64_t latest_seq(int p);
  uint64_t latest_event_seq() const { return event_seq_.load(); } // of every port
  // This process's run: a random id, the prefix of every event id, so a
  // client resuming with an id of another run starts over (issue 40).
  const std::string& run_id() const { return run_id_; }

  void start();               // starts the pacing thread
  void stop();                // stops it (idempotent) and wakes every subscriber
  bool running() const { return running_.load(); }
  PacingStats stats() const;
  void reset_stats();

  // Runs one cycle of every port now (tests, without the pacing thread).
  void step_all();

  // --state-dir (issues 27, 40): set before start().
  //  - durable(p, f): f(Port&) under the port lock as a change that is on
  //    disk (fsync'd) before durable() returns; if the state folder cannot
  //    take it, the twin is put back as before f and StateWriteFailed is
  //    thrown. The fronts run ISDU writes and faults through it, so nothing
  //    is acknowledged that a SIGKILL or a power loss could take back.
  //  - checkpoint()/commit(): the same in two halves for a caller that holds
  //    the lock already; commit() returns 0 or the IO-Link code (rolled back).
  //  - persist(p): what changed without a request (counters, a moving
  //    flange, a Data Storage upload), by a saver thread every
  //    kPersistEvery and by stop() for every port; a failure is kept in
  //    Port::state_write_error, counted in stats and said on stderr.
  void set_state_dir(StateDir* state) { state_ = state; }
  template <class F>
  auto durable(int p, F&& f) {
    Port& port_ref = port(p);
    std::lock_guard lock(port_ref.mutex);
    const auto before = checkpoint(port_ref);
    if constexpr (std::is_void_v<decltype(f(port_ref))>) {
      f(port_ref);
      throw_if_refused(commit(p, port_ref, before), port_ref);
    } else {
      auto out = f(port_ref);
      throw_if_refused(commit(p, port_ref, before), port_ref);
      return out;
    }
  }
  std::optional<TwinSnapshot> checkpoint(Port& port) const;
  uint16_t commit(int p, Port& port, const std::optional<TwinSnapshot>& before);
  bool persist(int p);
  uint64_t state_write_failures() const { return state_failures_.load(); }
  // After stop(): whether the state folder holds everything (false: stop
  // could not write something; serve exits non-zero).
  bool state_saved() const { return state_saved_; }
  // The master's Data Storage start-up for every port (before start(),
  // IO-Link Data Storage, docs/serve.md has the table, A-SERVE-19):
  //  - no backup: upload;
  //  - a module that is not the one whose memory the master kept (a
  //    replacement not restored yet, Port::ds_download_pending from the
  //    backup file; no memory image in the state folder): download, in its
  //    first cycle in OPERATE;
  //  - the module asks for an upload (3.2 bit 7): upload;
  //  - else the same module, changed only by the PLC's acknowledged writes:
  //    kept as it is (its single writes are not in the backup).
  // While running, an upload request is served before the answer to the
  // write that raised it (commit()), else within kPersistEvery.
  void ds_startup();
  // Runs cycles (unpaced) until every port's module has started up and
  // exchanged process data (at most a few cycles): before the fronts open.
  void start_up_ports();
  static constexpr std::chrono::milliseconds kPersistEvery{200};

 private:
  void pace();
  void after_cycle(Port& port);
  void run_port_cycle(Port& port);
  void save_loop();

  HubOptions options_;
  std::vector<std::unique_ptr<Port>> ports_;
  std::atomic<bool> running_{false};
  std::thread thread_;
  mutable std::mutex stats_mutex_;
  std::vector<uint32_t> jitter_hist_; // 1 us buckets up to 100 ms
  std::vector<double> jitter_over_us_; // the rare cycles later than that, exactly (bounded)
  uint64_t cycles_ = 0, late_ = 0;
  double jitter_max_us_ = 0;
  double busy_s_ = 0;
  std::atomic<bool> realtime_{false};
  std::chrono::steady_clock::time_point stats_start_;
  uint64_t stats_cycle0_ = 0;
  StateDir* state_ = nullptr;
  void throw_if_refused(uint16_t code, const Port& port) const;
  void note_state_result(int p, Port& port, const std::string& error);
  std::string run_id_;
  std::atomic<uint64_t> event_seq_{0};
  std::atomic<uint64_t> state_failures_{0};
  bool state_saved_ = true;
  std::thread saver_;
  std::mutex saver_mutex_;
  std::condition_variable saver_cv_;
};

} // namespace sreh::serve
