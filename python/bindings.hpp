// The pieces of the sreh_twin._core extension (issue 19), one file each:
// twin_binding.cpp (Twin), tools_binding.cpp (run_scenario, size, sweep),
// process_data_binding.cpp (frame codec), py_json.cpp (JSON -> Python).
#pragma once
#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "device_logic/process_data.hpp"
#include "twin/twin.hpp"

namespace sreh::py {

namespace pyb = pybind11;

// A JSON value as plain Python objects (dict, list, str, int, float, bool,
// None); floats keep every bit.
pyb::object to_python(const nlohmann::json& value);

// Bytes from bytes / bytearray / memoryview / a 1-D uint8 array; TypeError otherwise.
std::string bytes_of(const pyb::handle& value, const char* what);

// Python exceptions defined in module.cpp.
pyb::object& isdu_error_type(); // sreh_twin.IsduError(code, index, subindex)
pyb::object& input_error_type(); // sreh_twin.InputError (ValueError): bad input, the CLI's exit 2

// Sets sreh_twin.InputError with the message; `throw input_error(...)`.
pyb::error_already_set input_error(const std::string& message);

pyb::dict pd_in_dict(const sreh::ProcessDataIn& in); // decode_pd_in's dict

// Twin.render() (render_binding.cpp): an off-screen renderer kept per Twin,
// made on the first call; an RGB numpy array (height, width, 3) uint8.
struct TwinRenderer;
struct TwinRendererDeleter {
  void operator()(TwinRenderer* r) const;
};
pyb::object render_twin(const Twin& twin, std::unique_ptr<TwinRenderer, TwinRendererDeleter>& cache, int width, int height,
                        bool overlay);

void bind_process_data(pyb::module_& m);
void bind_render(pyb::module_& m);
void bind_twin(pyb::module_& m);
void bind_tools(pyb::module_& m);

} // namespace sreh::py
