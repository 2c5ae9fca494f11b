#include "serve/hub.hpp"

#include "device_logic/isdu.hpp"
#include "device_logic/parameter_ids.hpp"

#include "device_logic/units.hpp"
#include "serve/event_names.hpp"
#include "serve/state_dir.hpp"
#include "twin/plant.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace sreh::serve {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::size_t kEventRing = 2048;      // per port; a slow subscriber skips older ones
constexpr std::size_t kJitterBuckets = 100000; // 1 us each, up to 100 ms
constexpr std::size_t kJitterOverMax = 100000;  // exact values beyond that (a stall over 1 s re-anchors)

// q-quantile of the 1 us histogram plus the exact values beyond it (no cap:
// issue 27 found p99 stuck at 99999 us).
double percentile(const std::vector<uint32_t>& hist, std::vector<double> over, uint64_t total, double q) {
  if (total == 0) return 0;
  const auto want = std::max<uint64_t>(1, static_cast<uint64_t>(std::ceil(q * static_cast<double>(total))));
  uint64_t seen = 0;
  for (std::size_t i = 0; i < hist.size(); ++i) {
    seen += hist[i];
    if (seen >= want) return static_cast<double>(i);
  }
  if (over.empty()) return static_cast<double>(hist.size());
  std::sort(over.begin(), over.end());
  return over[std::min<std::size_t>(over.size() - 1, static_cast<std::size_t>(want - seen - 1))];
}

std::string hex16(unsigned v) { return fmt::format("0x{:04X}", v); }

} // namespace

Hub::Hub(const std::vector<TwinConfig>& configs, const HubOptions& options)
    : options_(options), jitter_hist_(kJitterBuckets, 0) {
  if (!(options.cycle_s > 0) || !(options.speed > 0) || !std::isfinite(options.speed)) {
    throw std::invalid_argument("serve: cycle and speed must be positive");
  }
  for (const auto& c : configs) {
    TwinConfig tc = c;
    tc.cycle_s = options.cycle_s;
    tc.record_trace = false; // a server runs for hours: no unbounded trace
    ports_.push_back(std::make_unique<Port>(tc));
    Port& p = *ports_.back();
    p.seq_source = &event_seq_;
    p.faults.supply_V = p.nominal_supply_V = tc.supply.voltage_V;
    p.faults.ambient_C = p.nominal_ambient_C = tc.thermal.ambient_C;
  }
  stats_start_ = Clock::now();
  std::random_device rd;
  run_id_ = fmt::format("{:08x}{:04x}", rd(), static_cast<unsigned>(::getpid()) & 0xFFFF);
}

Hub::~Hub() { stop(); }

void Hub::push_event(Port& port, std::string type, std::string json) {
  port.last_seq = ++*port.seq_source;
  port.events.push_back(PortEvent{port.last_seq, std::move(type), std::move(json)});
  while (port.events.size() > kEventRing) port.events.pop_front();
  port.event_cv.notify_all();
}

std::vector<PortEvent> Hub::events_after(int p, uint64_t after_seq, std::chrono::milliseconds timeout) {
  Port& port_ref = port(p);
  std::unique_lock lock(port_ref.mutex);
  const auto has_new = [&] { return !running_.load() || port_ref.last_seq > after_seq; };
  port_ref.event_cv.wait_for(lock, timeout, has_new);
  std::vector<PortEvent> out;
  for (const auto& e : port_ref.events)
    if (e.seq > after_seq) out.push_back(e);
  return out;
}

uint64_t Hub::latest_seq(int p) {
  return with_port(p, [](Port& port_ref) { return port_ref.last_seq; });
}

void Hub::after_cycle(Port& port) {
  Twin& twin = port.twin;
  const Telemetry tel = twin.telemetry();
  const double t_s = twin.time_s();
  if (port.first || tel.state != port.last_state || tel.error_code != port.last_error ||
      tel.warning_code != port.last_warning || tel.led != port.last_led) {
    nlohmann::json j{{"t_s", t_s},
                     {"state", state_name(tel.state)},
                     {"error_code", tel.error_code},
                     {"warning_code", tel.warning_code},
                     {"led", led_name(tel.led)}};
    push_event(port, "state", j.dump());
    port.last_state = tel.state;
    port.last_error = tel.error_code;
    port.last_warning = tel.warning_code;
    port.last_led = tel.led;
  }
  const bool sample = port.first || twin.cycles() % static_cast<uint64_t>(options_.sample_every_cycles) == 0;
  if (sample) {
    // Device events (index 37, iolink.md): entries that appear or disappear.
    const IsduResult r = twin.isdu_read(param::kDetailedDeviceStatus.index, param::kDetailedDeviceStatus.subindex);
    std::vector<uint8_t> now = r.ok() ? r.data : std::vector<uint8_t>{};
    if (now != port.last_detailed_status) {
      const auto entries = [](const std::vector<uint8_t>& d) {
        std::set<std::pair<unsigned, unsigned>> s; // (qualifier, code)
        for (std::size_t i = 0; i + 2 < d.size(); i += 3)
          if (d[i] != 0 || d[i + 1] != 0 || d[i + 2] != 0) s.insert({d[i], (d[i + 1] << 8) | d[i + 2]});
        return s;
      };
      const auto before = entries(port.last_detailed_status);
      const auto after = entries(now);
      // Each with its name, cause and remedy from the code table (issue 39).
      const auto device_event = [&](const char* mode, unsigned q, unsigned code) {
        nlohmann::ordered_json j{{"t_s", t_s}, {"mode", mode}, {"qualifier", fmt::format("0x{:02X}", q)},
                                 {"code", hex16(code)}};
        j.update(describe_device_event(twin, static_cast<uint16_t>(code)));
        push_event(port, "device_event", j.dump());
      };
      for (const auto& [q, code] : after)
        if (!before.count({q, code})) device_event("appears", q, code);
      for (const auto& [q, code] : before)
        if (!after.count({q, code})) device_event("disappears", q, code);
      port.last_detailed_status = std::move(now);
    }
    nlohmann::json j{{"t_s", t_s},
                     {"state", state_name(tel.state)},
                     {"led", led_name(tel.led)},
                     {"position_deg", tel.position_deg},
                     {"setpoint_deg", tel.setpoint_deg},
                     {"tracking_error_deg", tel.tracking_error_deg},
                     {"velocity_dps", tel.velocity_dps},
                     {"torque_Nm", twin.plant().applied_torque_Nm()},
                     {"temperature_C", tel.temperature_C},
                     {"supply_V", tel.supply_V}};
    push_event(port, "sample", j.dump());
  }
  port.first = false;
}

void Hub::run_port_cycle(Port& port) {
  if (!port.failure.empty()) return;
  try {
    port.twin.run_cycle();
    // A replacement module got through start-up: the master restores its backup.
    if (port.ds_download_pending && port.twin.iolink_led() == IoLinkLedMode::Operate) {
      port.ds_download_pending = false;
      ++port.ds_generation; // no longer owed (written by the saver, after the memory)
      port.ds_last_error = port.ds_backup ? ds_download(port.twin, *port.ds_backup) : 0;
      push_event(port, "data_storage",
                 nlohmann::json{{"t_s", port.twin.time_s()},
                                {"action", port.ds_backup ? "download" : "none (no backup)"},
                                {"iolink_error", port.ds_last_error == 0 ? nlohmann::json(nullptr)
                                                                         : nlohmann::json(hex16(port.ds_last_error))}}
                     .dump());
    }
    after_cycle(port);
  } catch (const std::exception& e) {
    port.failure = e.what();
    push_event(port, "failure", nlohmann::json{{"t_s", port.twin.time_s()}, {"message", port.failure}}.dump());
  }
}

void Hub::step_all() {
  for (auto& p : ports_) {
    std::lock_guard lock(p->mutex);
    run_port_cycle(*p);
  }
}

void Hub::start() {
  if (running_.exchange(true)) return;
  reset_stats();
  thread_ = std::thread([this] { pace(); });
  saver_ = std::thread([this] { save_loop(); });
}

void Hub::ds_startup() {
  for (auto& p : ports_) {
    std::lock_guard lock(p->mutex);
    const bool another_module = p->ds_download_pending || p->fresh_module;
    if (!p->ds_backup || (!another_module && ds_upload_requested(p->twin))) { // a new backup, or the device asks
      p->ds_download_pending = false;
      if (auto b = ds_upload(p->twin)) {
        p->ds_backup = std::move(b);
        ++p->ds_generation;
      }
    } else if (another_module && p->ds_backup->checksum != ds_checksum(p->twin)) { // the backup goes in
      p->ds_download_pending = true;
    } else if (p->ds_download_pending) { // owed, but the module holds the backup already
      p->ds_download_pending = false;
      ++p->ds_generation;
    }
  }
}

void Hub::start_up_ports() {
  const auto up = [](Port& port) {
    return !port.failure.empty() || !port.faults.link_up || port.twin.iolink_led() == IoLinkLedMode::Operate;
  };
  for (int k = 0; k < 8; ++k) { // STARTUP, PREOPERATE, then the first exchange (A-LINK-3)
    bool all = true;
    for (auto& p : ports_) {
      std::lock_guard lock(p->mutex);
      all = all && up(*p) && !p->ds_download_pending;
    }
    if (all) return;
    step_all();
  }
}

void Hub::stop() {
  running_.store(false);
  if (thread_.joinable()) thread_.join();
  {
    std::lock_guard lock(saver_mutex_);
    saver_cv_.notify_all();
  }
  if (saver_.joinable()) saver_.join();
  if (state_ != nullptr) {
    state_saved_ = true;
    for (int p = 1; p <= port_count(); ++p) state_saved_ = persist(p) && state_saved_; // the last word: what the module holds at power-off
  }
  for (auto& p : ports_) {
    std::lock_guard lock(p->mutex);
    p->event_cv.notify_all();
  }
}

std::optional<TwinSnapshot> Hub::checkpoint(Port& port) const {
  if (state_ == nullptr) return std::nullopt;
  return port.twin.snapshot();
}

void Hub::throw_if_refused(uint16_t code, const Port& port) const {
  if (code != 0) throw StateWriteFailed(code, "not saved, so not done (nothing changed): " + port.state_write_error);
}

// Port lock held. A failure is said on stderr when it starts and when it ends.
void Hub::note_state_result(int p, Port& port, const std::string& error) {
  if (error == port.state_write_error) return;
  if (!error.empty()) {
    state_failures_.fetch_add(1);
    std::cerr << fmt::format("sreh-twin serve: port {}: state not saved: {}\n", p, error);
  } else {
    std::cerr << fmt::format("sreh-twin serve: port {}: state saved again\n", p);
  }
  port.state_write_error = error;
}

// The device's upload request (e.g. ParamDownloadStore) is served here, so
// its answer means the backup holds it too. The memory goes first: a kill
// or a failure between the two leaves a memory that no longer asks for the
// upload beside the old backup, which the next start downloads, as befits
// a request that was not answered.
uint16_t Hub::commit(int p, Port& port, const std::optional<TwinSnapshot>& before) {
  if (state_ == nullptr) return 0;
  const std::optional<DsBackup> backup_before = port.ds_backup;
  const uint64_t generation_before = port.ds_generation;
  if (port.failure.empty() && !port.ds_download_pending && ds_upload_requested(port.twin))
    if (auto b = ds_upload(port.twin)) {
      port.ds_backup = std::move(b);
      ++port.ds_generation;
    }
  const uint64_t seq = ++port.state_seq;
  try {
    const auto save_ds = [&] {
      return port.ds_backup && state_->save_ds(p, *port.ds_backup, port.ds_download_pending, port.ds_generation);
    };
    // A download owed (a replacement): the backup file saying so goes
    // first, so the next start knows the new module; otherwise (an upload,
    // a download done) the memory goes first, see above.
    const bool ds_first = port.ds_download_pending;
    bool wrote = ds_first && save_ds();
    wrote = state_->save_nvm(p, seq, port.twin.save_nvm()) || wrote;
    wrote = (!ds_first && save_ds()) || wrote;
    if (wrote) note_state_result(p, port, "");
    return 0;
  } catch (const std::exception& e) {
    if (!port.state_write_error.empty()) state_failures_.fetch_add(1); // each refused write counts
    note_state_result(p, port, e.what());
    if (before) port.twin.restore(*before);
    port.ds_backup = backup_before;
    port.ds_generation = generation_before;
    return kIsduApplicationNotReady;
  }
}

bool Hub::persist(int p) {
  if (state_ == nullptr) return true;
  std::vector<uint8_t> nvm;
  double flange_deg = 0;
  uint64_t seq = 0, ds_generation = 0;
  bool owed = false;
  std::optional<DsBackup> ds;
  with_port(p, [&](Port& port) {
    seq = ++port.state_seq;
    nvm = port.twin.save_nvm();
    flange_deg = rad_to_deg(port.twin.plant().angle_rad());
    ds_generation = port.ds_generation;
    owed = port.ds_download_pending;
    if (port.ds_backup) ds = port.ds_backup;
  });
  const bool failing = with_port(p, [](Port& port) { return !port.state_write_error.empty(); });
  std::string error;
  bool wrote = false;
  try { // outside the port lock: the clock goes on while the files are written
    // The memory first: after a download, "no longer owed" must not be on
    // disk before the module that got it (a kill between: downloaded again).
    wrote = state_->save_nvm(p, seq, nvm);
    if (ds) wrote = state_->save_ds(p, *ds, owed, ds_generation) || wrote;
    wrote = state_->save_flange(p, flange_deg, failing) || wrote; // after a failure: does the folder take writes again?
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (wrote || !error.empty()) with_port(p, [&](Port& port) { note_state_result(p, port, error); });
  return error.empty();
}

// Counters and a moving flange change without a request: checked every kPersistEvery.
void Hub::save_loop() {
  std::unique_lock lock(saver_mutex_);
  while (running_.load()) {
    saver_cv_.wait_for(lock, kPersistEvery, [this] { return !running_.load(); });
    if (!running_.load()) break;
    lock.unlock();
    for (int p = 1; p <= port_count(); ++p) {
      with_port(p, [](Port& port) { // the device asks the master to back its set up (manual 8)
        if (port.failure.empty() && port.twin.powered() && !port.ds_download_pending && ds_upload_requested(port.twin))
          if (auto b = ds_upload(port.twin)) {
            port.ds_backup = std::move(b);
            ++port.ds_generation;
          }
      });
      persist(p);
    }
    lock.lock();
  }
}

void Hub::reset_stats() {
  std::lock_guard lock(stats_mutex_);
  std::fill(jitter_hist_.begin(), jitter_hist_.end(), 0);
  jitter_over_us_.clear();
  cycles_ = late_ = 0;
  jitter_max_us_ = 0;
  busy_s_ = 0;
  stats_start_ = Clock::now();
}

PacingStats Hub::stats() const {
  std::lock_guard lock(stats_mutex_);
  PacingStats s;
  s.cycles = cycles_;
  s.late_cycles = late_;
  s.jitter_p50_us = percentile(jitter_hist_, jitter_over_us_, cycles_, 0.50);
  s.jitter_p99_us = percentile(jitter_hist_, jitter_over_us_, cycles_, 0.99);
  s.jitter_max_us = jitter_max_us_;
  s.sim_time_s = static_cast<double>(cycles_) * options_.cycle_s;
  s.wall_time_s = std::chrono::duration<double>(Clock::now() - stats_start_).count();
  s.busy_fraction = s.wall_time_s > 0 ? busy_s_ / s.wall_time_s : 0;
  s.realtime_scheduling = realtime_.load();
  return s;
}

// Cycle k starts at t0 + k * cycle / speed of the steady clock. A late
// cycle runs at once (catching up, no cycle is skipped: the twin's time
// stays an integer number of cycles); after a stall of more than a second
// (a suspended process) the schedule is re-anchored instead.
void Hub::pace() {
  const double period_s = options_.cycle_s / options_.speed;
  prctl(PR_SET_TIMERSLACK, 1UL, 0, 0, 0); // wake at the deadline, not up to 50 us later
  if (options_.rt_priority > 0) {
    sched_param param{};
    param.sched_priority = options_.rt_priority;
    realtime_.store(pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0);
  }
  auto t0 = Clock::now();
  uint64_t k = 0;
  while (running_.load(std::memory_order_relaxed)) {
    const auto deadline = t0 + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double>(static_cast<double>(k) * period_s));
    std::this_thread::sleep_until(deadline);
    const auto start = Clock::now();
    const double late_s = std::chrono::duration<double>(start - deadline).count();
    for (auto& p : ports_) {
      std::lock_guard lock(p->mutex);
      run_port_cycle(*p);
    }
    const double busy = std::chrono::duration<double>(Clock::now() - start).count();
    {
      std::lock_guard lock(stats_mutex_);
      const double us = std::max(0.0, late_s * 1e6);
      if (us < static_cast<double>(kJitterBuckets)) jitter_hist_[static_cast<std::size_t>(us)]++;
      else if (jitter_over_us_.size() < kJitterOverMax) jitter_over_us_.push_back(us);
      jitter_max_us_ = std::max(jitter_max_us_, us);
      ++cycles_;
      if (late_s > period_s) ++late_;
      busy_s_ += busy;
    }
    ++k;
    if (late_s > 1.0) { // stalled: do not replay the lost second at full speed
      t0 = Clock::now() - std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(static_cast<double>(k) * period_s));
    }
  }
}

} // namespace sreh::serve
