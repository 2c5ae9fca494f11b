// `sreh-twin serve` pacing and round trips (issue 18). Figures:
// docs/performance-serve.md. Every port moves 0 <-> 90 deg by handshake
// (a PLC thread, as a real client load) while the hub paces the 2 ms master
// cycle against the wall clock.
//   BM_Pacing/N/P           N ports for 10 s, pacing thread SCHED_FIFO priority P (0: normal): cycle-start lateness p50/p99/max,
//                           late cycles (> 1 cycle behind), sim/wall ratio
//   BM_ModbusRoundTrip/C    FC3 read of PD in (4 registers), libmodbus client, loopback, C clients reading at once
//   BM_HttpRoundTrip        GET /v1/ports/1/processdata, cpp-httplib client, keep-alive
#include <benchmark/benchmark.h>
#include <httplib.h>
#include <modbus/modbus.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "device_logic/units.hpp"
#include "serve/http_server.hpp"
#include "serve/hub.hpp"
#include "serve/modbus_server.hpp"

namespace sreh::serve {
namespace {

using Clock = std::chrono::steady_clock;

std::vector<TwinConfig> ports(int n) {
  TwinConfig c;
  c.load = InertiaLoad{2000};
  return std::vector<TwinConfig>(static_cast<std::size_t>(n), c);
}

// Moves every port 0 <-> 90 deg with the manual 3.2 handshake, polling every 4 ms.
struct Plc {
  Hub& hub;
  std::atomic<bool> run{true};
  std::thread thread;
  explicit Plc(Hub& h) : hub(h) {
    for (int p = 1; p <= hub.port_count(); ++p)
      hub.with_port(p, [](Hub::Port& port) {
        const uint8_t load[2] = {2000 >> 8, 2000 & 0xFF};
        port.twin.isdu_write(65, 4, load); // set 1 configured for the load
        ProcessDataOut out;
        out.motor_on = true;
        out.parameter_set = 1;
        port.twin.set_pd_out(out);
      });
    thread = std::thread([this] {
      while (run.load()) {
        for (int p = 1; p <= hub.port_count(); ++p)
          hub.with_port(p, [](Hub::Port& port) {
            ProcessDataOut out = port.twin.pd_out();
            const ProcessDataIn in = port.twin.pd_in();
            if (in.ready && !out.move) {
              out.target_raw = out.target_raw == 0 ? static_cast<int32_t>(deg_to_wire_counts(90)) : 0;
              out.move = true;
            } else if (in.done && out.move) {
              out.move = false;
            } else if (in.error) {
              out.reset_error = !out.reset_error;
            }
            port.twin.set_pd_out(out);
          });
        std::this_thread::sleep_for(std::chrono::milliseconds(4));
      }
    });
  }
  ~Plc() {
    run.store(false);
    thread.join();
  }
};

void BM_Pacing(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  HubOptions options;
  options.rt_priority = static_cast<int>(state.range(1));
  for (auto _ : state) {
    Hub hub(ports(n), options);
    Plc plc(hub);
    hub.start();
    std::this_thread::sleep_for(std::chrono::seconds(10));
    const PacingStats s = hub.stats();
    hub.stop();
    state.SetIterationTime(s.wall_time_s);
    state.counters["jitter_p50_us"] = s.jitter_p50_us;
    state.counters["jitter_p99_us"] = s.jitter_p99_us;
    state.counters["jitter_max_us"] = s.jitter_max_us;
    state.counters["late_pct"] = 100.0 * static_cast<double>(s.late_cycles) / static_cast<double>(std::max<uint64_t>(1, s.cycles));
    state.counters["sim_per_wall"] = s.sim_time_s / s.wall_time_s;
    state.counters["busy_pct"] = 100.0 * s.busy_fraction;
    state.counters["sched_fifo"] = s.realtime_scheduling ? 1 : 0;
  }
}
// Args: ports, SCHED_FIFO priority (0: normal scheduling, as `serve` by default).
BENCHMARK(BM_Pacing)->ArgsProduct({{1, 8}, {0, 20}})->Args({4, 20})->Args({12, 20})->Args({16, 20})->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

void percentiles(benchmark::State& state, std::vector<double>& us) {
  std::sort(us.begin(), us.end());
  const auto at = [&](double q) { return us[std::min(us.size() - 1, static_cast<std::size_t>(q * static_cast<double>(us.size())))]; };
  state.counters["p50_us"] = at(0.50);
  state.counters["p99_us"] = at(0.99);
  state.counters["max_us"] = us.back();
}

// Arg: clients reading at once (this one measured, the others as fast as they can).
void BM_ModbusRoundTrip(benchmark::State& state) {
  Hub hub(ports(1), HubOptions{});
  Plc plc(hub);
  ModbusOptions mo;
  mo.port = 0;
  ModbusServer server(hub, mo);
  hub.start();
  server.start();
  std::atomic<bool> others_run{true};
  std::vector<std::thread> others;
  for (int k = 1; k < state.range(0); ++k)
    others.emplace_back([&] {
      modbus_t* o = modbus_new_tcp("127.0.0.1", server.bound_port());
      uint16_t r[4];
      if (modbus_connect(o) == 0)
        while (others_run.load()) modbus_read_registers(o, 1001, 4, r);
      modbus_close(o);
      modbus_free(o);
    });
  modbus_t* c = modbus_new_tcp("127.0.0.1", server.bound_port());
  if (modbus_connect(c) != 0) state.SkipWithError("modbus connect");
  std::vector<double> us;
  uint16_t regs[4];
  for (auto _ : state) {
    const auto t0 = Clock::now();
    if (modbus_read_registers(c, 1001, 4, regs) != 4) state.SkipWithError("modbus read");
    const double d = std::chrono::duration<double>(Clock::now() - t0).count();
    state.SetIterationTime(d);
    us.push_back(d * 1e6);
  }
  modbus_close(c);
  modbus_free(c);
  others_run.store(false);
  for (auto& t : others) t.join();
  server.stop();
  hub.stop();
  percentiles(state, us);
}
BENCHMARK(BM_ModbusRoundTrip)->Arg(1)->Arg(4)->Iterations(5000)->UseManualTime()->Unit(benchmark::kMicrosecond);

void BM_HttpRoundTrip(benchmark::State& state) {
  Hub hub(ports(1), HubOptions{});
  Plc plc(hub);
  HttpOptions o;
  o.port = 0;
  HttpServer server(hub, o);
  hub.start();
  server.start();
  httplib::Client client("127.0.0.1", server.bound_port());
  client.set_keep_alive(true);
  client.set_tcp_nodelay(true);
  std::vector<double> us;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    auto res = client.Get("/v1/ports/1/processdata");
    if (!res || res->status != 200) state.SkipWithError("http get");
    const double d = std::chrono::duration<double>(Clock::now() - t0).count();
    state.SetIterationTime(d);
    us.push_back(d * 1e6);
  }
  server.stop();
  hub.stop();
  percentiles(state, us);
}
BENCHMARK(BM_HttpRoundTrip)->Iterations(3000)->UseManualTime()->Unit(benchmark::kMicrosecond);

} // namespace
} // namespace sreh::serve

BENCHMARK_MAIN();
