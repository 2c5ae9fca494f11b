// Process data frames from Python (manual 2.2, 2.3, 2.5): build the 6-byte
// output frame from named fields, decode the 7-byte input frame.
#include <pybind11/stl.h>

#include <cmath>

#include "device_logic/process_data.hpp"
#include "device_logic/units.hpp"
#include "python/bindings.hpp"

namespace sreh::py {
namespace {

template <std::size_t N>
std::array<uint8_t, N> frame_of(const pyb::handle& value, const char* what) {
  const std::string b = bytes_of(value, what);
  if (b.size() != N) {
    throw input_error(std::string(what) + ": a frame has " + std::to_string(N) + " bytes, got " + std::to_string(b.size()));
  }
  std::array<uint8_t, N> f{};
  std::copy(b.begin(), b.end(), f.begin());
  return f;
}

pyb::bytes pd_out_bytes(double target_deg, std::optional<int64_t> target_counts, int parameter_set, bool shortest_path,
                        bool relative, bool set_origin, bool reset_error, bool stop, bool move, bool motor_on) {
  if (parameter_set < 0 || parameter_set > 255) {
    throw input_error("parameter_set " + std::to_string(parameter_set) + ": one octet, 0 .. 255 (valid sets 0 .. 7)");
  }
  if (!std::isfinite(target_deg)) throw input_error("target_deg must be finite");
  ProcessDataOut pd;
  // Manual 2.5: the int32 carries the low 32 bits of the position in 2^16 counts/rev.
  pd.target_position = wrap_wire_position(target_counts ? *target_counts : deg_to_wire_counts(target_deg));
  pd.parameter_set = static_cast<uint8_t>(parameter_set);
  pd.shortest_path = shortest_path;
  pd.relative = relative;
  pd.set_origin = set_origin;
  pd.reset_error = reset_error;
  pd.stop = stop;
  pd.move = move;
  pd.motor_on = motor_on;
  const PdOutFrame f = encode(pd);
  return pyb::bytes(reinterpret_cast<const char*>(f.data()), f.size());
}

} // namespace

pyb::dict pd_in_dict(const ProcessDataIn& in) {
  pyb::dict d;
  d["actual_position"] = in.actual_position;
  d["position_deg"] = wire_counts_to_deg(in.actual_position);
  d["error_code"] = in.error_code;
  d["warning_code"] = in.warning_code;
  d["error"] = in.error;
  d["warning"] = in.warning;
  d["done"] = in.done;
  d["busy"] = in.busy;
  d["ready"] = in.ready;
  d["motor_off"] = in.motor_off;
  return d;
}

pyb::error_already_set input_error(const std::string& message) {
  PyErr_SetString(input_error_type().ptr(), message.c_str());
  return pyb::error_already_set();
}

void bind_process_data(pyb::module_& m) {
  using pyb::arg;
  m.def("pd_out", &pd_out_bytes, arg("target_deg") = 0.0, pyb::kw_only(), arg("target_counts") = pyb::none(),
        arg("parameter_set") = 0, arg("shortest_path") = false, arg("relative") = false, arg("set_origin") = false,
        arg("reset_error") = false, arg("stop") = false, arg("move") = false, arg("motor_on") = false,
        R"(The 6-byte output process data frame (manual 2.2), PLC -> module.

target_deg is rounded to the wire's 2^16 counts per revolution (manual 2.5);
target_counts gives the raw int32 value instead.)");
  m.def(
      "decode_pd_out",
      [](const pyb::handle& frame) {
        const ProcessDataOut o = decode_out(frame_of<kPdOutBytes>(frame, "decode_pd_out"));
        pyb::dict d;
        d["target_position"] = o.target_position;
        d["target_deg"] = wire_counts_to_deg(o.target_position);
        d["parameter_set"] = o.parameter_set;
        d["shortest_path"] = o.shortest_path;
        d["relative"] = o.relative;
        d["set_origin"] = o.set_origin;
        d["reset_error"] = o.reset_error;
        d["stop"] = o.stop;
        d["move"] = o.move;
        d["motor_on"] = o.motor_on;
        return d;
      },
      arg("frame"), "The fields of a 6-byte output frame (manual 2.2).");
  m.def(
      "decode_pd_in", [](const pyb::handle& frame) { return pd_in_dict(decode_in(frame_of<kPdInBytes>(frame, "decode_pd_in"))); },
      arg("frame"),
      "The fields of a 7-byte input frame (manual 2.3): actual_position (counts), position_deg, error_code, "
      "warning_code and the status bits.");
}

} // namespace sreh::py
