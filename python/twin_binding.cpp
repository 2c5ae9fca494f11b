// sreh_twin.Twin: one module on a simulated IO-Link master (issue 19). The
// device is reached only through process data and ISDU, as from a PLC;
// fault injection acts on the world (supply, link, flange, ambient).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <memory>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "device_logic/parameter_table.hpp"
#include "device_logic/units.hpp"
#include "python/bindings.hpp"
#include "twin/model_card.hpp"
#include "scenarios/result_json.hpp"
#include "io/atomic_file.hpp"
#include "scenarios/isdu_value.hpp"
#include "scenarios/scenario.hpp"
#include "sizing/size_options.hpp"
#include "sizing/twin_factory.hpp"
#include "twin/plant.hpp"
#include "twin/twin.hpp"
#include "twin/twin_snapshot.hpp"

namespace sreh::py {
namespace {

constexpr uint16_t kIndexSystemCommand = 2; // manual 6.6

// "ISDU 65.1 refused: error 0x8030 (Parameter value out of range)"; .name
// carries the IO-Link name alone (issue 29), .remedy what to do (issue 39).
[[noreturn]] void raise_isdu(uint16_t code, uint16_t index, uint8_t subindex) {
  const std::string text = "ISDU " + std::to_string(index) + "." + std::to_string(subindex) +
                           " refused: error " + isdu_error_label(code);
  const IsduErrorDefinition* row = find_isdu_error(code); // the one table (issue 39)
  PyErr_SetObject(isdu_error_type().ptr(),
                  pyb::make_tuple(code, index, subindex, text, std::string(isdu_error_name(code)),
                                  row ? pyb::object(pyb::str(std::string(row->remedy))) : pyb::object(pyb::none()))
                      .ptr());
  throw pyb::error_already_set();
}

void check_finite(double v, const char* what) {
  if (!std::isfinite(v)) throw input_error(std::string(what) + " must be finite");
}

// Python value -> ISDU bytes with the parameter table's types, exactly as a
// scenario's `isdu: value:` (scenarios/isdu_value.hpp): bytes as given.
std::vector<uint8_t> encode_value(const pyb::handle& value, uint16_t index, uint8_t subindex) {
  if (PyBytes_Check(value.ptr()) || PyByteArray_Check(value.ptr())) {
    const std::string b = bytes_of(value, "isdu_write value");
    return {b.begin(), b.end()};
  }
  YAML::Node node;
  auto scalar = [](const pyb::handle& v) -> YAML::Node {
    if (PyBool_Check(v.ptr())) return YAML::Node(v.cast<bool>() ? 1 : 0);
    if (PyLong_Check(v.ptr()) || pyb::hasattr(v, "__index__")) {
      return YAML::Node(pyb::str(pyb::int_(pyb::reinterpret_borrow<pyb::object>(v))).cast<std::string>());
    }
    if (PyUnicode_Check(v.ptr())) {
      YAML::Node n(v.cast<std::string>());
      n.SetStyle(YAML::EmitterStyle::Flow);
      return n;
    }
    throw pyb::type_error("isdu_write value: expected an int, a str, bytes or a list of ints, got " +
                          pyb::str(pyb::type::handle_of(v).attr("__name__")).cast<std::string>());
  };
  if (PyList_Check(value.ptr()) || PyTuple_Check(value.ptr())) {
    node = YAML::Node(YAML::NodeType::Sequence);
    for (const auto& item : value) node.push_back(scalar(item));
  } else {
    node = scalar(value);
  }
  // A Python str is text even if it looks like a number: mark it quoted.
  const bool quoted = PyUnicode_Check(value.ptr());
  try {
    if (quoted && find_parameter(index, subindex) == nullptr) {
      const std::string s = value.cast<std::string>();
      return {s.begin(), s.end()};
    }
    return detail::encode_isdu_value(detail::YamlReader("isdu_write"), node, index, subindex, "isdu_write value");
  } catch (const ScenarioError& e) {
    throw input_error(e.message());
  }
}

pyb::object decode_value(const IsduResult& r, uint16_t index, uint8_t subindex, bool raw) {
  const pyb::bytes bytes(reinterpret_cast<const char*>(r.data.data()), r.data.size());
  if (raw) return bytes;
  if (detail::is_text_parameter(index, subindex)) return pyb::str(detail::decode_isdu_text(r.data));
  const ParameterEntry* entry = find_parameter(index, subindex);
  if (entry != nullptr && is_numeric(entry->type)) {
    if (const auto v = detail::decode_isdu_number(index, subindex, r.data)) return pyb::int_(*v);
  }
  if (subindex == 0 && is_record(index)) { // a whole record: its numeric members in order
    pyb::list values;
    std::size_t at = 0;
    for (const ParameterEntry* member : record_members(index)) {
      const std::size_t n = wire_size(member->type);
      if (n == 0 || at + n > r.data.size()) return bytes;
      values.append(decode_number(member->type, std::span(r.data).subspan(at, n)));
      at += n;
    }
    return values;
  }
  return bytes;
}

template <class T, class F>
pyb::array_t<T> column(const std::vector<TraceRow>& rows, F get) {
  pyb::array_t<T> a(static_cast<pyb::ssize_t>(rows.size()));
  T* out = a.mutable_data();
  for (std::size_t i = 0; i < rows.size(); ++i) out[i] = static_cast<T>(get(rows[i]));
  return a;
}

// A frame as one integer whose bit numbers are the manual's (2.2, 2.3):
// pd_in >> 24 is the actual position, (pd_in >> 3) & 1 is Done.
template <std::size_t N>
uint64_t frame_bits(const std::array<uint8_t, N>& f) {
  uint64_t v = 0;
  for (uint8_t b : f) v = (v << 8) | b;
  return v;
}

class PyTwin {
 public:
  PyTwin(std::optional<double> load_gcm2, std::optional<std::filesystem::path> load_file, double voltage_V, double ambient_C,
         double master_cycle_ms, bool configure_load, bool record_trace, std::vector<double> hard_stops_deg,
         std::optional<pyb::bytes> nvm, std::optional<std::filesystem::path> model, std::optional<double> mounting_tilt_deg) {
    TwinConfig c;
    if (model) {
      try {
        c.module = load_module_model(model->string()); // issue 25: the model card with the file's overrides
      } catch (const ModelCardError& e) {
        throw input_error(std::string("model: ") + e.what());
      }
    }
    if (load_gcm2 && load_file) throw input_error("Twin: give load_gcm2 or load_file, not both");
    if (load_gcm2) {
      check_finite(*load_gcm2, "load_gcm2");
      c.load = InertiaLoad{*load_gcm2};
    } else if (load_file) {
      const std::string f = load_file->string();
      if (f.size() > 4 && f.compare(f.size() - 4, 4, ".xml") == 0) {
        c.load = MjcfLoad{f}; // an MJCF body file, as `load: {mjcf: ...}`
      } else {
        try {
          // The load and the file's mounting: (issue 28), exactly as `run` and `size --load`.
          LoadFileContents contents = sizing::read_load_file(f, "load_file");
          c.load = std::move(contents.load);
          c.mounting_tilt_deg = contents.mounting_tilt_deg.value_or(0.0);
        } catch (const sizing::SizingInputError& e) {
          throw input_error(e.what());
        }
      }
    }
    if (mounting_tilt_deg) { // given: it wins over the file's mounting:, as size --mounting-tilt-deg
      if (!(*mounting_tilt_deg >= 0.0 && *mounting_tilt_deg <= 180.0)) {
        throw input_error("mounting_tilt_deg " + std::to_string(*mounting_tilt_deg) + ": expected 0 .. 180 deg");
      }
      c.mounting_tilt_deg = *mounting_tilt_deg;
    }
    check_finite(voltage_V, "voltage_V");
    check_finite(ambient_C, "ambient_C");
    // As a scenario's sim.cycle_s: 2 ms .. 1 s, whole physics steps (0.1 ms).
    if (!(master_cycle_ms >= 2.0 && master_cycle_ms <= 1000.0)) {
      throw input_error("master_cycle_ms " + std::to_string(master_cycle_ms) + ": expected 2 .. 1000 ms");
    }
    for (double a : hard_stops_deg) {
      check_finite(a, "hard_stops_deg");
      c.hard_stops.push_back(HardStop{a});
    }
    c.supply.voltage_V = voltage_V;
    c.thermal.ambient_C = ambient_C;
    c.cycle_s = master_cycle_ms * 1e-3;
    c.record_trace = record_trace;
    if (nvm) {
      const std::string b = *nvm;
      c.nvm_image = std::vector<uint8_t>(b.begin(), b.end());
    }
    try {
      twin_ = sizing::make_twin(c); // MJCF compiles serialised (threads may build twins)
    } catch (const std::invalid_argument& e) {
      throw input_error(std::string("Twin: ") + e.what());
    }
    const bool has_load = load_gcm2 || load_file;
    if (has_load && configure_load) {
      // Every parameter set's configured load (64..71 subindex 4, manual 6.2), whole g cm^2.
      const double j = load_gcm2 ? *load_gcm2 : twin_->load_inertia_gcm2();
      const auto raw = encode_number(ParamType::UInt16, static_cast<int64_t>(std::llround(j)));
      for (uint16_t index = 64; index <= 71; ++index) {
        const IsduResult r = twin_->isdu_write(index, 4, raw);
        if (!r.ok()) raise_isdu(r.error, index, 4);
      }
    }
  }

  pyb::bytes exchange(const pyb::handle& pd_out) {
    set_pd_out(pd_out);
    {
      pyb::gil_scoped_release release;
      twin_->run_cycle();
    }
    return pd_in_bytes();
  }

  pyb::bytes run_cycles(int64_t n, const pyb::handle& pd_out) {
    if (n < 0) throw input_error("run_cycles: n must be >= 0");
    if (!pd_out.is_none()) set_pd_out(pd_out);
    constexpr int64_t kChunk = 5000; // Ctrl-C is honoured between chunks
    for (int64_t done = 0; done < n;) {
      const int64_t k = std::min(kChunk, n - done);
      {
        pyb::gil_scoped_release release;
        for (int64_t i = 0; i < k; ++i) twin_->run_cycle();
      }
      done += k;
      if (PyErr_CheckSignals() != 0) throw pyb::error_already_set();
    }
    return pd_in_bytes();
  }

  void set_pd_out(const pyb::handle& pd_out) {
    const std::string b = bytes_of(pd_out, "pd_out");
    try {
      twin_->set_pd_out(decode_out(std::span(reinterpret_cast<const uint8_t*>(b.data()), b.size())));
    } catch (const std::invalid_argument& e) {
      throw input_error(std::string("pd_out: ") + e.what());
    }
  }

  pyb::bytes pd_out_frame() const {
    const PdOutFrame f = encode(twin_->pd_out());
    return pyb::bytes(reinterpret_cast<const char*>(f.data()), f.size());
  }

  pyb::bytes pd_in_bytes() const {
    const PdInFrame f = encode(twin_->pd_in());
    return pyb::bytes(reinterpret_cast<const char*>(f.data()), f.size());
  }

  pyb::object isdu_read(int index, int subindex, bool raw) {
    const auto [i, s] = address(index, subindex);
    const IsduResult r = twin_->isdu_read(i, s);
    if (!r.ok()) raise_isdu(r.error, i, s);
    return decode_value(r, i, s, raw);
  }

  void isdu_write(int index, int subindex, const pyb::handle& value) {
    const auto [i, s] = address(index, subindex);
    const std::vector<uint8_t> data = encode_value(value, i, s);
    const IsduResult r = twin_->isdu_write(i, s, data);
    if (!r.ok()) raise_isdu(r.error, i, s);
  }

  void system_command(int code) {
    if (code < 0 || code > 255) throw input_error("system_command " + std::to_string(code) + ": one octet, 0 .. 255");
    const uint8_t data[1] = {static_cast<uint8_t>(code)};
    const IsduResult r = twin_->isdu_write(kIndexSystemCommand, 0, data);
    if (!r.ok()) raise_isdu(r.error, kIndexSystemCommand, 0);
  }

  void firmware_update(const pyb::handle& image) {
    const std::string b = bytes_of(image, "firmware_update image");
    const uint16_t code = twin_->firmware_update(std::span(reinterpret_cast<const uint8_t*>(b.data()), b.size()));
    if (code != 0) raise_isdu(code, 0, 0);
  }

  pyb::dict state() const {
    const Telemetry t = twin_->telemetry();
    const Plant& p = twin_->plant();
    pyb::dict d;
    d["time_s"] = twin_->time_s();
    d["cycles"] = twin_->cycles();
    d["position_deg"] = t.position_deg;
    d["setpoint_deg"] = t.setpoint_deg;
    d["tracking_error_deg"] = t.tracking_error_deg;
    d["velocity_dps"] = t.velocity_dps;
    d["torque_Nm"] = p.applied_torque_Nm();
    d["external_torque_Nm"] = p.external_torque_Nm();
    d["supply_V"] = p.sensors().supply_V;
    d["temperature_C"] = p.sensors().temperature_C;
    d["state"] = std::string(state_name(t.state));
    d["error_code"] = t.error_code;
    d["warning_code"] = t.warning_code;
    d["led"] = std::string(led_name(twin_->device().powered() ? t.led : LedColor::Off));
    d["moving"] = t.moving;
    d["settling"] = t.settling;
    d["flange_blocked"] = p.flange_blocked();
    return d;
  }

  pyb::dict trace() const {
    const std::vector<TraceRow>& rows = twin_->trace();
    pyb::dict d;
    d["t_s"] = column<double>(rows, [](const TraceRow& r) { return r.t_s; });
    d["state"] = column<uint8_t>(rows, [](const TraceRow& r) { return r.state; });
    d["setpoint_deg"] = column<double>(rows, [](const TraceRow& r) { return r.setpoint_deg; });
    d["position_deg"] = column<double>(rows, [](const TraceRow& r) { return r.position_deg; });
    d["tracking_error_deg"] = column<double>(rows, [](const TraceRow& r) { return r.tracking_error_deg; });
    d["velocity_dps"] = column<double>(rows, [](const TraceRow& r) { return r.velocity_dps; });
    d["torque_Nm"] = column<double>(rows, [](const TraceRow& r) { return r.torque_Nm; });
    d["supply_V"] = column<double>(rows, [](const TraceRow& r) { return r.supply_V; });
    d["temperature_C"] = column<double>(rows, [](const TraceRow& r) { return r.temperature_C; });
    d["error_code"] = column<uint8_t>(rows, [](const TraceRow& r) { return r.error_code; });
    d["warning_code"] = column<uint8_t>(rows, [](const TraceRow& r) { return r.warning_code; });
    d["pd_out"] = column<uint64_t>(rows, [](const TraceRow& r) { return frame_bits(r.pd_out); });
    d["pd_in"] = column<uint64_t>(rows, [](const TraceRow& r) { return frame_bits(r.pd_in); });
    d["led"] = column<uint8_t>(rows, [](const TraceRow& r) { return r.led; });
    d["torque_limit_Nm"] = column<double>(rows, [](const TraceRow& r) { return r.torque_limit_Nm; });
    d["external_torque_Nm"] = column<double>(rows, [](const TraceRow& r) { return r.external_torque_Nm; });
    return d;
  }

  std::string trace_csv(const std::optional<std::filesystem::path>& path) const {
    std::ostringstream out;
    write_trace_csv(out, twin_->trace());
    if (path) {
      try {
        io::write_file_atomic(path->string(), [&](std::ostream& o) { o << out.str(); });
      } catch (const std::runtime_error& e) {
        throw input_error(e.what());
      }
    }
    return out.str();
  }

  // The device's move records, exactly as `run --json` shows them (issue 13).
  pyb::list moves() const {
    pyb::list out;
    for (const MoveRecord& m : twin_->moves()) out.append(to_python(move_json(m)));
    return out;
  }

  pyb::bytes save_nvm() const {
    const std::vector<uint8_t> image = twin_->save_nvm();
    return pyb::bytes(reinterpret_cast<const char*>(image.data()), image.size());
  }

  Twin& twin() { return *twin_; }
  const Twin& twin() const { return *twin_; }
  pyb::object render(int width, int height, bool overlay) { return render_twin(*twin_, renderer_, width, height, overlay); }

 private:
  static std::pair<uint16_t, uint8_t> address(int index, int subindex) {
    if (index < 0 || index > 0xFFFF) throw input_error("ISDU index " + std::to_string(index) + ": expected 0 .. 65535");
    if (subindex < 0 || subindex > 0xFF) throw input_error("ISDU subindex " + std::to_string(subindex) + ": expected 0 .. 255");
    return {static_cast<uint16_t>(index), static_cast<uint8_t>(subindex)};
  }

  std::unique_ptr<Twin> twin_;
  std::unique_ptr<TwinRenderer, TwinRendererDeleter> renderer_; // made by the first render()
};

} // namespace

void bind_twin(pyb::module_& m) {
  using pyb::arg;
  // Opaque: what a Twin was at one cycle (A-TWIN-34..36). Immutable, so
  // copies share it; kept in Python as long as it is referenced.
  pyb::class_<TwinSnapshot>(m, "TwinSnapshot", R"(A running Twin at one cycle (Twin.snapshot()).

Opaque and immutable; give it to Twin.restore() (of the same Twin, or of one
made with the same arguments) to continue from there bit for bit.)")
      .def_property_readonly("cycles", [](const TwinSnapshot& s) { return s.run.cycles; },
                             "IO-Link cycles the twin had run.")
      .def_property_readonly("time_s", [](const TwinSnapshot& s) { return static_cast<double>(s.run.time_ns) * 1e-9; },
                             "Simulated time then, s.")
      .def("__repr__", [](const TwinSnapshot& s) {
        return "<sreh_twin.TwinSnapshot at cycle " + std::to_string(s.run.cycles) + ">";
      });
  pyb::class_<PyTwin>(m, "Twin", R"(One SREH-50-IOL on a simulated IO-Link master.

The device is reached as from a PLC: exchange() / run_cycles() send the
6-byte output process data and return the 7-byte input frame (manual 2.2,
2.3); isdu_read() / isdu_write() are the acyclic parameters (manual 6).
A load given here is mounted and, unless configure_load=False, written
into every parameter set's configured load (index 64..71 subindex 4).
Not thread-safe: one Twin per thread.)")
      .def(pyb::init<std::optional<double>, std::optional<std::filesystem::path>, double, double, double, bool, bool,
                     std::vector<double>, std::optional<pyb::bytes>, std::optional<std::filesystem::path>,
                     std::optional<double>>(),
           pyb::kw_only(), arg("load_gcm2") = pyb::none(), arg("load_file") = pyb::none(), arg("voltage_V") = 24.0,
           arg("ambient_C") = 25.0, arg("master_cycle_ms") = 2.0, arg("configure_load") = true,
           arg("record_trace") = true, arg("hard_stops_deg") = std::vector<double>{}, arg("nvm") = pyb::none(),
           arg("model") = pyb::none(), arg("mounting_tilt_deg") = pyb::none(),
           R"(load_gcm2: a load of this inertia about the axis (g cm^2, 0 .. 15000).
load_file: a YAML file with a scenario's 'load:' key (its 'mounting:' too), or an MJCF body file (.xml).
mounting_tilt_deg: the axis tilted from vertical, 0 .. 180 (90: horizontal); default: the file's mounting:, else 0.
voltage_V: supply; ambient_C: air temperature; master_cycle_ms: IO-Link cycle 2 .. 1000 ms.
record_trace: keep one trace row per cycle (trace()); hard_stops_deg: obstacles the load hits.
nvm: a saved memory image (save_nvm()); factory-new otherwise.
model: a model file overriding constants of the module's model card
(YAML as `sreh-twin model show` prints; model_card() gives the card).)")
      .def("exchange", &PyTwin::exchange, arg("pd_out"),
           "One IO-Link cycle: send the 6-byte output frame, run the cycle, return the 7-byte input frame.")
      .def("run_cycles", &PyTwin::run_cycles, arg("n"), arg("pd_out") = pyb::none(),
           "Run n IO-Link cycles with this output frame (or the last one) without returning to Python; "
           "returns the last input frame.")
      .def("set_pd_out", &PyTwin::set_pd_out, arg("pd_out"), "Set the output frame for the next cycles.")
      .def_property_readonly("pd_out", &PyTwin::pd_out_frame, "The output frame in use (6 bytes).")
      .def_property_readonly("pd_in", &PyTwin::pd_in_bytes, "The last input frame the master received (7 bytes).")
      .def("set_outputs_valid", [](PyTwin& t, bool valid) { t.twin().set_outputs_valid(valid); }, arg("valid"),
           "The master marks the output data valid / invalid (manual 5: PD invalid).")
      .def("isdu_read", &PyTwin::isdu_read, arg("index"), arg("subindex") = 0, pyb::kw_only(), arg("raw") = false,
           "Read a parameter: an int for numbers, a str for texts, a list of ints for a whole record "
           "(subindex 0), bytes otherwise or with raw=True. Raises IsduError with the IO-Link code.")
      .def("isdu_write", &PyTwin::isdu_write, arg("index"), arg("subindex"), arg("value"),
           "Write a parameter: an int (raw wire value), a str, bytes, or a list of ints for a whole record. "
           "Raises IsduError with the IO-Link code; the device is unchanged then.")
      .def("system_command", &PyTwin::system_command, arg("code"),
           "A system command (index 2, manual 6.6), e.g. 129 application reset, 130 restore factory settings.")
      .def("power_cycle", [](PyTwin& t) { t.twin().power_cycle(); },
           "Switch the module off and on again; its non-volatile memory is kept.")
      .def("firmware_update", &PyTwin::firmware_update, arg("image"),
           "Hand a firmware image to the device in boot mode (manual 9). Raises IsduError when refused.")
      .def("link_down", [](PyTwin& t, bool down) { t.twin().set_link_up(!down); }, arg("down") = true,
           "Interrupt the IO-Link communication (down=False restores it). Cycles stop reaching the device (manual 5).")
      .def("set_voltage", [](PyTwin& t, double v) { check_finite(v, "voltage"); t.twin().set_supply_voltage(v); },
           arg("voltage_V"), "Set the supply's source voltage (V).")
      .def("external_torque", [](PyTwin& t, double nm) { check_finite(nm, "torque"); t.twin().set_external_torque(nm); },
           arg("torque_Nm"), "An external torque on the flange (N m, physical frame: positive clockwise from above); 0 removes it.")
      .def("block_flange", [](PyTwin& t, bool b) { t.twin().set_flange_blocked(b); }, arg("blocked") = true,
           "Hold the flange rigidly where it is (a clamp, a jam); blocked=False releases it.")
      .def("set_ambient", [](PyTwin& t, double c) { check_finite(c, "ambient"); t.twin().set_ambient_C(c); },
           arg("ambient_C"), "Set the ambient temperature (degC); the module follows with its thermal time constants.")
      .def("state", &PyTwin::state,
           "The module now: time_s, position_deg, velocity_dps, torque_Nm, temperature_C, state, error_code, "
           "warning_code, led and more.")
      .def("trace", &PyTwin::trace,
           "The trace so far, one row per cycle: column name -> 1-D numpy array (columns of `run --trace`; "
           "state / led are indices into STATES / LEDS, pd_out / pd_in the frames as integers in the manual's bit "
           "numbering).")
      .def("trace_csv", &PyTwin::trace_csv, arg("path") = pyb::none(),
           "The trace as the CSV of `sreh-twin run --trace` (returned, and written to path if given).")
      .def("render", &PyTwin::render, arg("width") = 640, arg("height") = 480, pyb::kw_only(), arg("overlay") = true,
           "The module as it stands now, rendered off-screen as a video frame shows it (the overlay with time, state, "
           "positions and codes unless overlay=False): a numpy uint8 array of shape (height, width, 3), RGB.")
      .def("moves", &PyTwin::moves, "One dict per accepted Move (as `run --json` moves).")
      .def("save_nvm", &PyTwin::save_nvm, "The non-volatile memory image (for Twin(nvm=...)).")
      .def("snapshot", [](const PyTwin& t) { return t.twin().snapshot(); },
           "The whole running twin now (device, physics, drive, supply, thermal, clocks, link, load) as an opaque "
           "TwinSnapshot for restore().")
      .def("restore", [](PyTwin& t, const TwinSnapshot& s) {
             try {
               t.twin().restore(s);
             } catch (const std::invalid_argument& e) {
               throw input_error(e.what());
             }
           },
           arg("snapshot"),
           "Go back to a snapshot(): the twin then continues exactly as it did after the snapshot, bit for bit. "
           "The kept trace is cut back to the snapshot's rows. Raises InputError (nothing changes) for a snapshot "
           "of a twin with other hard stops.")
      .def_property_readonly("time_s", [](const PyTwin& t) { return t.twin().time_s(); }, "Simulated time, s.")
      .def_property_readonly("cycles", [](const PyTwin& t) { return t.twin().cycles(); }, "IO-Link cycles run.")
      .def_property_readonly("load_inertia_gcm2", [](const PyTwin& t) { return t.twin().load_inertia_gcm2(); },
                             "The mounted load's inertia about the axis as MuJoCo computes it (g cm^2).");
}

} // namespace sreh::py
