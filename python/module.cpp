// sreh_twin._core: the compiled core of the Python package (issue 19).
// The package's __init__.py re-exports it with the pure-Python parts.
#include "python/bindings.hpp"

#include <pybind11/eval.h>
#include <pybind11/stl.h>

#include "device_logic/device_types.hpp"
#include "twin/models_dir.hpp"

namespace sreh::py {

pyb::object& isdu_error_type() {
  static pyb::object type;
  return type;
}
pyb::object& input_error_type() {
  static pyb::object type;
  return type;
}

pyb::object to_python(const nlohmann::json& v) {
  switch (v.type()) {
    case nlohmann::json::value_t::null: return pyb::none();
    case nlohmann::json::value_t::boolean: return pyb::bool_(v.get<bool>());
    case nlohmann::json::value_t::number_integer: return pyb::int_(v.get<int64_t>());
    case nlohmann::json::value_t::number_unsigned: return pyb::int_(v.get<uint64_t>());
    case nlohmann::json::value_t::number_float: return pyb::float_(v.get<double>());
    case nlohmann::json::value_t::string: return pyb::str(v.get_ref<const std::string&>());
    case nlohmann::json::value_t::array: {
      pyb::list out;
      for (const auto& item : v) out.append(to_python(item));
      return out;
    }
    case nlohmann::json::value_t::object: {
      pyb::dict out;
      for (const auto& [key, item] : v.items()) out[pyb::str(key)] = to_python(item);
      return out;
    }
    default: return pyb::none(); // binary / discarded: never produced here
  }
}

std::string bytes_of(const pyb::handle& value, const char* what) {
  if (PyBytes_Check(value.ptr())) {
    char* data = nullptr;
    Py_ssize_t size = 0;
    PyBytes_AsStringAndSize(value.ptr(), &data, &size);
    return std::string(data, static_cast<std::size_t>(size));
  }
  if (PyByteArray_Check(value.ptr()) || PyMemoryView_Check(value.ptr()) || pyb::hasattr(value, "__array_interface__")) {
    return pyb::bytes(pyb::module_::import("builtins").attr("bytes")(value)).cast<std::string>();
  }
  throw pyb::type_error(std::string(what) + ": expected bytes, got " +
                        pyb::str(pyb::type::handle_of(value).attr("__name__")).cast<std::string>());
}

} // namespace sreh::py

PYBIND11_MODULE(_core, m) {
  using namespace sreh::py;
  m.doc() = "Compiled core of sreh_twin: the SREH-50-IOL digital twin (use the sreh_twin package).";
  m.attr("__version__") = SREH_VERSION; // the release `sreh-twin --version` prints
  input_error_type() = pyb::reinterpret_borrow<pyb::object>(
      PyErr_NewExceptionWithDoc("sreh_twin.InputError",
                                "Bad input (a file, an option, a value): what and where. The CLI exits 2 for it.",
                                PyExc_ValueError, nullptr));
  m.attr("InputError") = input_error_type();
  pyb::object isdu_base = pyb::reinterpret_borrow<pyb::object>(PyExc_RuntimeError);
  pyb::dict ns;
  ns["base"] = isdu_base;
  // A small Python class: the IO-Link ISDU error code (manual 6, e.g. 0x8030) as .code.
  pyb::exec(R"PY(
class IsduError(base):
    """An ISDU request refused by the device. ``code`` is the IO-Link error
    code (e.g. 0x8030 value out of range, 0x8011 index not available),
    ``name`` its IO-Link name ("Parameter value out of range"),
    ``remedy`` what to do (docs/errors.md), ``index`` / ``subindex`` the
    request."""
    def __init__(self, code, index, subindex, message=None, name=None, remedy=None):
        self.code = int(code)
        self.index = int(index)
        self.subindex = int(subindex)
        self.name = name or "ISDU error"
        self.remedy = remedy
        super().__init__(message or f"ISDU {index}.{subindex}: error 0x{self.code:04X} ({self.name})")
)PY", ns);
  isdu_error_type() = ns["IsduError"];
  isdu_error_type().attr("__module__") = "sreh_twin";
  m.attr("IsduError") = isdu_error_type();

  pyb::list states, leds;
  for (int i = 0; i <= static_cast<int>(sreh::State::ErrorOff); ++i) {
    states.append(pyb::str(std::string(sreh::state_name(static_cast<sreh::State>(i)))));
  }
  for (int i = 0; i <= static_cast<int>(sreh::LedColor::Violet); ++i) {
    leds.append(pyb::str(std::string(sreh::led_name(static_cast<sreh::LedColor>(i)))));
  }
  m.attr("STATES") = pyb::tuple(states);
  m.attr("LEDS") = pyb::tuple(leds);
  m.def("models_dir", &sreh::models_dir,
        "The models folder twins are built from (twin/models_dir.hpp: $SREH_TWIN_MODELS_DIR first).");

  bind_process_data(m);
  bind_twin(m);
  bind_tools(m);
  bind_render(m); // after bind_tools: its run_scenario (with video=, report=) is the one kept
}
