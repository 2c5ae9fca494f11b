// A consumer of the installed libraries: brings the module up over process
// data, moves 90 deg with set 1 and prints where the flange ended (manual
// 3.2: Motor on -> Ready, Move -> Busy -> Done). Exit 0 only if it got there.
#include <cmath>
#include <cstdio>

#include "device_logic/device.hpp"
#include "twin/twin.hpp"

int main() {
  sreh::Device bare(sreh::default_module_model().drive); // the firmware with the card's drive
  if (bare.telemetry().state != sreh::State::MotorOff) return 1;

  sreh::TwinConfig config;
  config.load = sreh::InertiaLoad{1000};
  sreh::Twin twin(config);
  // Configure the load in set 1 (index 65.4, g cm^2, manual 3.5.6) as a PLC would.
  const uint8_t load_gcm2[2] = {0x03, 0xE8}; // 1000, big-endian
  if (!twin.isdu_write(65, 4, load_gcm2).ok()) return 1;
  sreh::ProcessDataOut out;
  out.motor_on = true;
  twin.set_pd_out(out);
  for (int i = 0; i < 25; ++i) twin.run_cycle();
  out.target_raw = 16384; // 90 deg, manual 2.5
  out.parameter_set = 1;
  out.move = true;
  twin.set_pd_out(out);
  for (int i = 0; i < 250 && !twin.pd_in().done; ++i) twin.run_cycle();
  const sreh::ProcessDataIn in = twin.pd_in();
  const double position_deg = in.position_raw * 360.0 / 65536.0;
  std::printf("done=%d position_deg=%.3f\n", in.done ? 1 : 0, position_deg);
  return in.done && std::fabs(position_deg - 90.0) < 0.2 ? 0 : 1;
}
