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

pyb::bytes pd_out_bytes(double target_deg, std::optional<int64_t> target_raw, std::optional<int64_t> target_counts,
                        int parameter_set, bool shortest_path, bool relative, bool set_origin, bool reset_error, bool stop,
                        bool move, bool motor_on) {
  if (parameter_set < 0 || parameter_set > 255) {
    throw input_error("parameter_set " + std::to_string(parameter_set) + ": one octet, 0 .. 255 (valid sets 0 .. 7)");
  }
  if (!std::isfinite(target_deg)) throw input_error("target_deg must be finite");
  if (target_counts) { // the name before issue 30
    if (target_raw) throw input_error("pd_out: give target_raw, not target_raw and target_counts");
    if (PyErr_WarnEx(PyExc_DeprecationWarning, "pd_out(target_counts=...) is deprecated: use target_raw=", 1) != 0) {
      throw pyb::error_already_set();
    }
    target_raw = target_counts;
  }
  ProcessDataOut pd;
  // Manual 2.5: the int32 carries the low 32 bits of the position in 2^16 counts/rev.
  pd.target_raw = wrap_wire_position(target_raw ? *target_raw : deg_to_wire_counts(target_deg));
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

// A frame's fields by name, read through the layout table (kPdInFields /
// kPdOutFields): the same names as scenarios and serve (issue 30).
template <std::size_t N, class Row, std::size_t F>
pyb::dict fields_dict(const std::array<uint8_t, N>& frame, const std::array<Row, F>& fields) {
  pyb::dict d;
  for (const PdField& f : fields) {
    const int64_t v = pd_field_value(frame, f);
    const std::string name(f.name);
    if (f.type == PdFieldType::Bool) d[name.c_str()] = v != 0;
    else d[name.c_str()] = v;
    if (!f.deg_name.empty()) d[std::string(f.deg_name).c_str()] = wire_counts_to_deg(static_cast<int32_t>(v));
  }
  return d;
}

} // namespace

pyb::dict pd_in_dict(const ProcessDataIn& in) { return fields_dict(encode(in), kPdInFields); }

pyb::error_already_set input_error(const std::string& message) {
  PyErr_SetString(input_error_type().ptr(), message.c_str());
  return pyb::error_already_set();
}

void bind_process_data(pyb::module_& m) {
  using pyb::arg;
  m.def("pd_out", &pd_out_bytes, arg("target_deg") = 0.0, pyb::kw_only(), arg("target_raw") = pyb::none(),
        arg("target_counts") = pyb::none(), arg("parameter_set") = 0, arg("shortest_path") = false,
        arg("relative") = false, arg("set_origin") = false, arg("reset_error") = false, arg("stop") = false,
        arg("move") = false, arg("motor_on") = false,
        R"(The 6-byte output process data frame (manual 2.2), PLC -> module.

target_deg is rounded to the wire's 2^16 counts per revolution (manual 2.5);
target_raw gives the raw int32 value instead (target_counts: its old name,
deprecated).)");
  m.def(
      "decode_pd_out",
      [](const pyb::handle& frame) { return fields_dict(frame_of<kPdOutBytes>(frame, "decode_pd_out"), kPdOutFields); },
      arg("frame"),
      "The fields of a 6-byte output frame (manual 2.2): target_raw (counts), target_deg, parameter_set and the "
      "command bits.");
  m.def(
      "decode_pd_in", [](const pyb::handle& frame) { return pd_in_dict(decode_in(frame_of<kPdInBytes>(frame, "decode_pd_in"))); },
      arg("frame"),
      "The fields of a 7-byte input frame (manual 2.3): position_raw (counts), position_deg, error_code, "
      "warning_code and the status bits.");
}

} // namespace sreh::py
