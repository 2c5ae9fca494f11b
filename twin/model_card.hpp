// The model card (issue 25): every physical constant of the module in one
// data file, models/sreh50-model.yaml, each with its value, unit, source and
// the range a production module plausibly lies in. Read at run time; a
// user's file (`--model FILE`, scenario key `model: FILE`, Python
// `Twin(model=...)`) overrides any subset of it:
//
//   constants:
//     coulomb_friction: 0.012                  # just the value, or
//     torsional_stiffness: {value: 420, source: "measured on our module", range: [300, 500]}
//
// The names, units and what each constant sets in the twin are declared
// once, in model_card.cpp's schema; the card file gives the numbers.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include "twin/module_model.hpp"

namespace sreh {

// Bad card or model file (exit code 2): "FILE:LINE:COL: what is wrong".
class ModelCardError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ModelConstant {
  std::string name;
  double value = 0;
  std::string unit;
  std::string source;
  double range_lo = 0;
  double range_hi = 0;
  // A calibration's 95 % interval, where one was written (`interval: [lo, hi]`,
  // issue 36): uncertainty sizing samples it instead of the range.
  bool has_interval = false;
  double interval_lo = 0;
  double interval_hi = 0;
  double sampling_lo() const { return has_interval ? interval_lo : range_lo; }
  double sampling_hi() const { return has_interval ? interval_hi : range_hi; }
  bool operator==(const ModelConstant&) const = default;
};

struct ModelCard {
  std::vector<ModelConstant> constants; // in the card file's order, every schema name once

  const ModelConstant* find(const std::string& name) const;
  ModuleModel module_model() const; // the values as the twin's structs
  bool operator==(const ModelCard&) const = default;
};

// models/sreh50-model.yaml from the models folder, read once (thread-safe).
const ModelCard& default_model_card();

// A complete card (every constant with value, unit, source and range).
ModelCard read_model_card(const std::string& path);

// `base` with the entries of the model file at `path` applied: unknown names,
// a unit that differs from the card's, a value outside its range, a range
// with lo > hi: ModelCardError naming file:line:col and the constant.
ModelCard apply_model_file(const ModelCard& base, const std::string& path);

// The default card with the model file applied; an empty path: the default.
ModuleModel load_module_model(const std::string& path);

// The card as YAML, in the format read_model_card / apply_model_file read.
std::string model_card_yaml(const ModelCard& card);

// Whether the constant takes whole numbers only (loop_delay,
// cogging_periods): sampling and fitting round it. False for unknown names.
bool model_constant_is_whole(const std::string& name);

// Shortest text that reads back as the same double ("0.004", "1e-05").
std::string shortest_number(double value);

} // namespace sreh
