// The CLI's commands from Python (issue 19), on the same code paths:
// size = `size --json` (run_scenario = `run --json`: render_binding.cpp), sweep = `sweep` with the
// CSV's columns as numpy arrays. Keywords are the long options with '-' as '_'.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <type_traits>

#include "python/bindings.hpp"
#include "scenarios/model_card_json.hpp"
#include "sizing/size_options.hpp"
#include "calibration/calibrate.hpp"
#include "calibration/fit_output.hpp"
#include "calibration/report.hpp"
#include "io/atomic_file.hpp"
#include "io/cpus.hpp"
#include "io/output_path.hpp"
#include "sizing/sweep_options.hpp"

namespace sreh::py {
namespace {

// kwargs -> the options struct, through the option table the CLI uses.
template <class Options, class Table>
Options options_from(const char* function, const Table& table, const pyb::kwargs& kwargs) {
  Options options;
  std::vector<std::string> given;
  for (const auto& [key, value] : kwargs) {
    const std::string name = pyb::str(key);
    const auto* spec = sizing::find_option<Options>(table, name);
    if (spec == nullptr) {
      std::string known;
      for (const auto& s : table) known += (known.empty() ? "" : ", ") + sizing::keyword_of(s.name);
      throw pyb::type_error(std::string(function) + "() got an unexpected keyword argument '" + name +
                            "' (options: " + known + ")");
    }
    given.push_back(name);
    try {
      std::visit(
          [&](auto member) {
            auto& field = options.*member;
            using T = std::decay_t<decltype(field)>;
            if constexpr (std::is_same_v<T, std::optional<double>>) {
              field = value.is_none() ? std::nullopt : std::optional<double>(value.template cast<double>());
            } else if constexpr (std::is_same_v<T, std::string>) {
              field = value.is_none() ? std::string() : pyb::module_::import("os").attr("fspath")(value).template cast<std::string>();
            } else if constexpr (std::is_same_v<T, std::vector<double>>) {
              if (PyFloat_Check(value.ptr()) || PyLong_Check(value.ptr())) field = {value.template cast<double>()};
              else field = pyb::cast<std::vector<double>>(pyb::module_::import("numpy").attr("asarray")(value, "float64").attr("ravel")().attr("tolist")());
            } else if constexpr (std::is_same_v<T, bool>) {
              if (!PyBool_Check(value.ptr())) throw pyb::cast_error("bool");
              field = value.template cast<bool>();
            } else {
              if (PyBool_Check(value.ptr())) throw pyb::cast_error("bool");
              field = value.template cast<T>();
            }
          },
          spec->field);
    } catch (const pyb::cast_error&) {
      throw pyb::type_error(std::string(function) + "(): " + name + "=" + std::string(pyb::str(pyb::repr(value))) +
                            " has the wrong type");
    }
  }
  for (const auto& s : table) {
    const std::string k = sizing::keyword_of(s.name);
    if (s.required && std::find(given.begin(), given.end(), k) == given.end()) {
      throw pyb::type_error(std::string(function) + "() missing required keyword argument '" + k + "'");
    }
  }
  return options;
}

template <class Table>
pyb::list option_names(const Table& table) {
  pyb::list out;
  for (const auto& s : table) out.append(sizing::keyword_of(s.name));
  return out;
}

pyb::dict sweep_arrays(const sizing::SweepResult& result) {
  namespace sz = sizing;
  pyb::dict d;
  const auto columns = sz::sweep_columns(result.uncertainty);
  const auto n = static_cast<pyb::ssize_t>(result.points.size());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const std::string name(columns[c].name);
    switch (columns[c].kind) {
      case sz::SweepColumnKind::Number: {
        pyb::array_t<double> a(n);
        for (pyb::ssize_t i = 0; i < n; ++i) {
          const sz::SweepCell cell = sz::sweep_cell(result.points[static_cast<std::size_t>(i)], c);
          const double* v = std::get_if<double>(&cell);
          a.mutable_data()[i] = v ? *v : std::numeric_limits<double>::quiet_NaN(); // missing: NaN
        }
        d[name.c_str()] = a;
        break;
      }
      case sz::SweepColumnKind::Flag: {
        pyb::array_t<bool> a(n);
        for (pyb::ssize_t i = 0; i < n; ++i) {
          const sz::SweepCell cell = sz::sweep_cell(result.points[static_cast<std::size_t>(i)], c);
          a.mutable_data()[i] = std::get<bool>(cell);
        }
        d[name.c_str()] = a;
        break;
      }
      case sz::SweepColumnKind::Count: {
        pyb::array_t<int64_t> a(n);
        for (pyb::ssize_t i = 0; i < n; ++i) {
          const sz::SweepCell cell = sz::sweep_cell(result.points[static_cast<std::size_t>(i)], c);
          a.mutable_data()[i] = std::get<int64_t>(cell);
        }
        d[name.c_str()] = a;
        break;
      }
      case sz::SweepColumnKind::Word:
      case sz::SweepColumnKind::Text: {
        pyb::list texts;
        for (const auto& p : result.points) texts.append(std::get<std::string>(sz::sweep_cell(p, c)));
        d[name.c_str()] = pyb::module_::import("numpy").attr("array")(texts, "str");
        break;
      }
    }
  }
  return d;
}

// `sreh_twin.calibrate(...)`: `sreh-twin calibrate` on the CLI's code
// (calibration/calibrate.hpp), outputs checked by the output rule first.
pyb::object calibrate_py(std::vector<std::filesystem::path> logs, std::optional<double> load_gcm2,
                         std::optional<std::filesystem::path> load, std::optional<std::filesystem::path> setup,
                         std::optional<std::filesystem::path> model, std::vector<std::string> fit,
                         std::optional<std::filesystem::path> out, std::optional<std::filesystem::path> report,
                         std::optional<int> threads, int max_iterations) {
  if (report && !calibration_reports_available()) throw input_error("report: this build has no renders");
  CalibrateRequest r;
  for (const auto& p : logs) r.logs.push_back(p.string());
  r.load_gcm2 = load_gcm2;
  if (load) r.load_file = load->string();
  if (setup) r.setup = setup->string();
  if (model) r.model = model->string();
  r.fit = std::move(fit);
  r.options.threads = threads.value_or(io::usable_cpus());
  r.options.max_iterations = max_iterations;
  try { // the output rule before the fit, as the CLI (issue 12)
    std::vector<std::string> inputs = r.logs;
    for (const std::string* f : {&r.load_file, &r.setup, &r.model}) {
      if (!f->empty()) inputs.push_back(*f);
    }
    io::check_outputs({{"out", out ? out->string() : "", io::OutputKind::File},
                       {"report", report ? report->string() : "", io::OutputKind::Folder}},
                      inputs);
  } catch (const io::PathError& e) {
    throw input_error(e.what());
  }
  CalibrateOutcome outcome;
  try {
    pyb::gil_scoped_release release;
    outcome = calibrate(r);
  } catch (const CalibrationInputError& e) {
    throw input_error(e.what());
  } catch (const std::invalid_argument& e) {
    throw input_error(e.what());
  }
  if (out) io::write_file_atomic(out->string(), [&](std::ostream& o) { o << outcome.model_yaml; });
  if (report) write_calibration_report(*report, outcome.cases, outcome.start, outcome.fit);
  nlohmann::json j = fit_json(outcome.fit);
  j["model_yaml"] = outcome.model_yaml;
  return to_python(j);
}

} // namespace

void bind_tools(pyb::module_& m) {
  using pyb::arg;
  m.def(
      "model_card",
      [](const std::optional<std::filesystem::path>& model) {
        try {
          const ModelCard card = model ? apply_model_file(default_model_card(), model->string()) : default_model_card();
          return to_python(nlohmann::json(model_card_json(card)));
        } catch (const ModelCardError& e) {
          throw input_error(std::string("model: ") + e.what());
        }
      },
      pyb::arg("model") = pyb::none(),
      "The module's model card (issue 25): {'constants': {NAME: {'value', 'unit', 'source', 'range'}}}, with a "
      "model file's overrides applied when given.");
  m.def(
      "size",
      [](const pyb::kwargs& kwargs) {
        const auto options = options_from<sizing::SizeOptions>("size", sizing::size_option_table(), kwargs);
        try {
          return to_python(sizing::run_size(options).json);
        } catch (const sizing::SizingInputError& e) {
          throw input_error(e.what());
        }
      },
      "PerfectCycle-style sizing (`sreh-twin size --json`); keywords are the CLI's options with '-' as '_'.");
  m.def(
      "sweep",
      [](const pyb::kwargs& kwargs) {
        const auto options = options_from<sizing::SweepOptions>("sweep", sizing::sweep_option_table(), kwargs);
        try {
          const sizing::SweepRequest rq = sizing::make_sweep_request(options);
          return sweep_arrays(sizing::run_sweep_command(options, rq));
        } catch (const sizing::SizingInputError& e) {
          throw input_error(e.what());
        }
      },
      "Sizing over a grid (`sreh-twin sweep`); returns the CSV's columns as numpy arrays (missing times NaN).");
  m.def(
      "calibrate",
      &calibrate_py,
      arg("logs"), pyb::kw_only(), arg("load_gcm2") = pyb::none(), arg("load") = pyb::none(), arg("setup") = pyb::none(),
      arg("model") = pyb::none(), arg("fit") = std::vector<std::string>{}, arg("out") = pyb::none(),
      arg("report") = pyb::none(), arg("threads") = pyb::none(), arg("max_iterations") = 25,
      "`sreh-twin calibrate --json` as a dict (constants, rms_residual_deg, iterations, converged, ...) plus "
      "model_yaml, the fitted model file (also written to `out` when given); `report`: a folder for the HTML "
      "report (`calibrate --report`). Raises InputError for a bad log.");
  m.attr("SIZE_OPTIONS") = pyb::tuple(option_names(sizing::size_option_table()));
  m.attr("SWEEP_OPTIONS") = pyb::tuple(option_names(sizing::sweep_option_table()));
}

} // namespace sreh::py
