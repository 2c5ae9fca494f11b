// The model card's schema and reader (issue 25, twin/model_card.hpp).
#include "twin/model_card.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "io/text.hpp"
#include "twin/models_dir.hpp"

namespace sreh {
namespace {

// What a value may be at all, whatever its range on the card.
enum class Sign { Positive, NonNegative };

// One row per constant: its name, unit and where it goes in ModuleModel.
// The card file must list exactly these names; docs/assumptions/* gives
// each one's reason under the tag its `source` names.
struct SchemaRow {
  const char* name;
  const char* unit;
  Sign sign;
  bool integer;
  void (*set)(ModuleModel&, double);
};

#define SREH_FIELD(path) [](ModuleModel& m, double v) { m.path = v; }
const SchemaRow kSchema[] = {
    {"control_period", "s", Sign::Positive, false,
     [](ModuleModel& m, double v) { m.drive.control_period_ns = std::llround(v * 1e9); }},
    {"loop_delay", "control periods", Sign::NonNegative, true,
     [](ModuleModel& m, double v) { m.drive.gains.delay_periods = static_cast<int>(v); }},
    {"torque_constant", "N m/A", Sign::Positive, false, SREH_FIELD(drive.motor.torque_constant_Nm_per_A)},
    {"winding_resistance", "ohm", Sign::Positive, false, SREH_FIELD(drive.motor.winding_resistance_ohm)},
    {"winding_inductance", "H", Sign::Positive, false, SREH_FIELD(drive.motor.winding_inductance_H)},
    {"current_limit", "A", Sign::Positive, false, SREH_FIELD(drive.motor.current_limit_A)},
    {"current_loop_bandwidth", "rad/s", Sign::Positive, false, SREH_FIELD(drive.motor.current_loop_bandwidth_rad_s)},
    {"velocity_bandwidth", "rad/s", Sign::Positive, false, SREH_FIELD(drive.gains.velocity_bandwidth_rad_s)},
    {"velocity_schedule_exponent", "1", Sign::NonNegative, false, SREH_FIELD(drive.gains.schedule_exponent)},
    {"position_ratio", "1", Sign::Positive, false, SREH_FIELD(drive.gains.position_ratio)},
    {"integral_ratio", "1", Sign::NonNegative, false, SREH_FIELD(drive.gains.integral_ratio)},
    {"velocity_filter", "s", Sign::NonNegative, false, SREH_FIELD(drive.gains.velocity_filter_s)},
    {"speed_filter", "s", Sign::Positive, false, SREH_FIELD(drive.speed_filter_s)},
    {"rotor_inertia", "kg m^2", Sign::Positive, false, SREH_FIELD(mechanics.rotor_inertia_kgm2)},
    {"torsional_stiffness", "N m/rad", Sign::Positive, false, SREH_FIELD(mechanics.torsional_stiffness_Nm_per_rad)},
    {"torsional_damping", "N m s/rad", Sign::NonNegative, false, SREH_FIELD(mechanics.torsional_damping_Nms_per_rad)},
    {"coulomb_friction", "N m", Sign::NonNegative, false, SREH_FIELD(mechanics.coulomb_friction_Nm)},
    {"viscous_friction", "N m s/rad", Sign::NonNegative, false, SREH_FIELD(mechanics.viscous_friction_Nms_per_rad)},
    {"stribeck_excess", "N m", Sign::NonNegative, false, SREH_FIELD(mechanics.stribeck_excess_Nm)},
    {"stribeck_speed", "rad/s", Sign::Positive, false, SREH_FIELD(mechanics.stribeck_speed_rad_s)},
    {"cogging_torque", "N m", Sign::NonNegative, false, SREH_FIELD(mechanics.cogging_torque_Nm)},
    {"cogging_periods", "1/rev", Sign::Positive, true, SREH_FIELD(mechanics.cogging_periods_per_rev)},
    {"gear_efficiency", "1", Sign::Positive, false, SREH_FIELD(mechanics.gear_efficiency)},
    {"gear_backlash", "rad", Sign::NonNegative, false, SREH_FIELD(mechanics.gear_backlash_rad)},
    {"winding_heat_capacity", "J/K", Sign::Positive, false, SREH_FIELD(thermal.winding_capacity_J_per_K)},
    {"housing_heat_capacity", "J/K", Sign::Positive, false, SREH_FIELD(thermal.housing_capacity_J_per_K)},
    {"winding_to_housing_resistance", "K/W", Sign::Positive, false, SREH_FIELD(thermal.winding_to_housing_K_per_W)},
    {"housing_to_ambient_resistance", "K/W", Sign::Positive, false, SREH_FIELD(thermal.housing_to_ambient_K_per_W)},
    {"speed_loss", "W s/rad", Sign::NonNegative, false, SREH_FIELD(thermal.speed_loss_W_per_rad_s)},
    {"bus_bleed_resistance", "ohm", Sign::Positive, false, SREH_FIELD(supply.bleed_resistance_ohm)},
};
#undef SREH_FIELD

constexpr std::size_t kMaxCardBytes = 1 << 20; // a card is a few KB; refuse anything absurd unread

const SchemaRow* schema_row(const std::string& name) {
  for (const SchemaRow& row : kSchema) {
    if (name == row.name) return &row;
  }
  return nullptr;
}

// "unknown constant 'x' (did you mean 'y'? ...)" or the whole list.
std::string unknown_constant(const std::string& name) {
  const SchemaRow* best = nullptr;
  std::size_t best_distance = 4; // more edits than this: no guess
  for (const SchemaRow& row : kSchema) {
    const std::size_t d = io::edit_distance(name, row.name);
    if (d < best_distance) best_distance = d, best = &row;
  }
  std::string out = "unknown constant '" + name + "' (";
  if (best != nullptr) return out + "did you mean '" + best->name + "'? `sreh-twin model show` lists them all)";
  for (const SchemaRow& row : kSchema) out += std::string(row.name) + (&row == std::end(kSchema) - 1 ? ")" : ", ");
  return out;
}

// Reads and parses one YAML document; every error names the file.
class CardFile {
 public:
  explicit CardFile(std::string path) : path_(std::move(path)) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path_, ec)) fail_plain("no such file (a model card or model file)");
    if (std::filesystem::file_size(path_, ec) > kMaxCardBytes) fail_plain("larger than 1 MiB: not a model file");
    std::ifstream in(path_, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) fail_plain("cannot be read");
    std::vector<YAML::Node> docs;
    try {
      docs = YAML::LoadAll(text.str());
    } catch (const YAML::Exception& e) {
      throw ModelCardError(path_ + ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1) +
                           ": not valid YAML: " + e.msg);
    }
    if (docs.size() != 1) fail_plain("must hold exactly one YAML document, holds " + std::to_string(docs.size()));
    root_ = docs.front();
    if (!root_.IsMap()) fail(root_, "must be a mapping with the key 'constants'");
    for (const auto& kv : root_) {
      if (kv.first.Scalar() != "constants") fail(kv.first, "unknown key '" + kv.first.Scalar() + "' (only 'constants')");
    }
    constants_ = root_["constants"];
    if (!constants_ || !constants_.IsMap()) fail(root_, "'constants' must be a mapping NAME: {value, unit, source, range}");
  }

  const YAML::Node& constants() const { return constants_; }

  [[noreturn]] void fail(const YAML::Node& at, const std::string& message) const {
    const YAML::Mark m = at.Mark();
    throw ModelCardError(path_ + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1) + ": " + message);
  }
  [[noreturn]] void fail_plain(const std::string& message) const { throw ModelCardError(path_ + ": " + message); }

  double number(const YAML::Node& node, const std::string& what) const {
    if (!node.IsScalar()) fail(node, what + " must be a number");
    const std::string& s = node.Scalar();
    double v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) {
      fail(node, what + " must be a finite number, got '" + s + "'");
    }
    return v;
  }
  std::string text(const YAML::Node& node, const std::string& what) const {
    if (!node.IsScalar()) fail(node, what + " must be a text");
    return node.Scalar();
  }

 private:
  std::string path_;
  YAML::Node root_;
  YAML::Node constants_;
};

// One entry NAME: VALUE or NAME: {value, unit, source, range}, onto `c`.
// `complete`: the card itself, where all four keys are required.
void read_entry(const CardFile& f, const YAML::Node& key, const YAML::Node& entry, ModelConstant& c, bool complete) {
  const std::string& name = c.name;
  c.has_interval = false; // an entry without one drops a base file's interval
  if (entry.IsScalar()) {
    if (complete) f.fail(entry, name + ": the card gives value, unit, source and range");
    c.value = f.number(entry, name);
  } else if (entry.IsMap()) {
    for (const auto& kv : entry) {
      const std::string k = kv.first.Scalar();
      if (k != "value" && k != "unit" && k != "source" && k != "range" && k != "interval") {
        f.fail(kv.first, name + ": unknown key '" + k + "' (value, unit, source, range, interval)");
      }
    }
    for (const char* k : {"value", "unit", "source", "range"}) {
      if (complete && !entry[k]) f.fail(entry, name + ": missing '" + k + "'");
    }
    if (!entry["value"]) f.fail(entry, name + ": missing 'value'");
    c.value = f.number(entry["value"], name + ".value");
    if (const YAML::Node u = entry["unit"]) {
      const std::string unit = f.text(u, name + ".unit");
      if (!complete && unit != c.unit) f.fail(u, name + ": unit '" + unit + "' differs from the card's '" + c.unit + "'");
      c.unit = unit;
    }
    if (const YAML::Node s = entry["source"]) c.source = f.text(s, name + ".source");
    if (const YAML::Node r = entry["range"]) {
      if (!r.IsSequence() || r.size() != 2) f.fail(r, name + ".range must be [lo, hi]");
      c.range_lo = f.number(r[0], name + ".range[0]");
      c.range_hi = f.number(r[1], name + ".range[1]");
      if (c.range_lo > c.range_hi) f.fail(r, name + ".range: lo " + shortest_number(c.range_lo) + " > hi " + shortest_number(c.range_hi));
    }
    // A calibration's 95 % interval (issue 36): what uncertainty sizing
    // samples instead of the range; it must lie in the range and hold the value.
    if (const YAML::Node r = entry["interval"]) {
      if (!r.IsSequence() || r.size() != 2) f.fail(r, name + ".interval must be [lo, hi]");
      c.interval_lo = f.number(r[0], name + ".interval[0]");
      c.interval_hi = f.number(r[1], name + ".interval[1]");
      if (!(c.interval_lo <= c.value && c.value <= c.interval_hi) || c.interval_lo < c.range_lo || c.interval_hi > c.range_hi) {
        f.fail(r, name + ".interval [" + shortest_number(c.interval_lo) + ", " + shortest_number(c.interval_hi) +
                      "] must hold the value and lie inside the range");
      }
      c.has_interval = true;
    }
  } else {
    f.fail(key, name + " must be a number or {value, unit, source, range}");
  }
  const SchemaRow& row = *schema_row(name);
  const YAML::Node& at = entry.IsMap() ? entry["value"] : entry;
  if (row.integer && c.value != std::floor(c.value)) f.fail(at, name + " must be a whole number, got " + shortest_number(c.value));
  if (row.sign == Sign::Positive ? !(c.value > 0) : !(c.value >= 0)) {
    f.fail(at, name + " must be " + (row.sign == Sign::Positive ? "> 0" : ">= 0") + ", got " + shortest_number(c.value));
  }
  if (name == "loop_delay" && c.value > PositionController::kMaxDelayPeriods) {
    f.fail(at, "loop_delay must be at most " + std::to_string(PositionController::kMaxDelayPeriods) +
                   " control periods (what the controller holds), got " + shortest_number(c.value));
  }
  if (name == "gear_efficiency" && c.value > 1) {
    f.fail(at, "gear_efficiency must be at most 1 (a gear does not add torque), got " + shortest_number(c.value));
  }
  if (c.value < c.range_lo || c.value > c.range_hi) {
    f.fail(at, name + " = " + shortest_number(c.value) + " " + c.unit + " is outside its range [" +
                   shortest_number(c.range_lo) + ", " + shortest_number(c.range_hi) +
                   "] (give a range: [lo, hi] with it if your module really lies outside)");
  }
}

} // namespace

std::string shortest_number(double value) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, r.ptr);
}

const ModelConstant* ModelCard::find(const std::string& name) const {
  for (const ModelConstant& c : constants) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

bool model_constant_is_whole(const std::string& name) {
  const SchemaRow* row = schema_row(name);
  return row && row->integer;
}

ModuleModel ModelCard::module_model() const {
  ModuleModel m;
  for (const ModelConstant& c : constants) {
    if (const SchemaRow* row = schema_row(c.name)) row->set(m, c.value);
  }
  return m;
}

ModelCard read_model_card(const std::string& path) {
  const CardFile f(path);
  ModelCard card;
  for (const auto& kv : f.constants()) {
    const std::string name = kv.first.Scalar();
    const SchemaRow* row = schema_row(name);
    if (row == nullptr) f.fail(kv.first, unknown_constant(name));
    if (card.find(name) != nullptr) f.fail(kv.first, "constant '" + name + "' given twice");
    ModelConstant c{name, 0, "", "", 0, 0};
    read_entry(f, kv.first, kv.second, c, true);
    if (c.unit != row->unit) f.fail(kv.second["unit"], name + ": unit '" + c.unit + "' should be '" + row->unit + "'");
    card.constants.push_back(c);
  }
  for (const SchemaRow& row : kSchema) {
    if (card.find(row.name) == nullptr) f.fail(f.constants(), std::string("the card lacks constant '") + row.name + "'");
  }
  return card;
}

ModelCard apply_model_file(const ModelCard& base, const std::string& path) {
  const CardFile f(path);
  ModelCard card = base;
  std::vector<std::string> seen;
  for (const auto& kv : f.constants()) {
    const std::string name = kv.first.Scalar();
    auto it = std::find_if(card.constants.begin(), card.constants.end(),
                           [&](const ModelConstant& c) { return c.name == name; });
    if (it == card.constants.end()) {
      f.fail(kv.first, unknown_constant(name));
    }
    if (std::find(seen.begin(), seen.end(), name) != seen.end()) f.fail(kv.first, "constant '" + name + "' given twice");
    seen.push_back(name);
    read_entry(f, kv.first, kv.second, *it, false);
  }
  return card;
}

const ModelCard& default_model_card() {
  static std::once_flag once;
  static ModelCard card;
  std::call_once(once, [] { card = read_model_card(models_dir() + "/sreh50-model.yaml"); });
  return card;
}

const ModuleModel& default_module_model() {
  static std::once_flag once;
  static ModuleModel model;
  std::call_once(once, [] { model = default_model_card().module_model(); });
  return model;
}

ModuleModel load_module_model(const std::string& path) {
  return path.empty() ? default_module_model() : apply_model_file(default_model_card(), path).module_model();
}

std::string model_card_yaml(const ModelCard& card) {
  auto quoted = [](const std::string& s) {
    std::string out = "\"";
    for (char ch : s) {
      if (ch == '"' || ch == '\\') out += '\\';
      out += ch;
    }
    return out + "\"";
  };
  std::string out = "# sreh-twin model card (models/sreh50-model.yaml with any --model overrides applied)\nconstants:\n";
  for (const ModelConstant& c : card.constants) {
    out += "  " + c.name + ":\n";
    out += "    value: " + shortest_number(c.value) + "\n";
    out += "    unit: " + quoted(c.unit) + "\n";
    out += "    source: " + quoted(c.source) + "\n";
    out += "    range: [" + shortest_number(c.range_lo) + ", " + shortest_number(c.range_hi) + "]\n";
    if (c.has_interval) out += "    interval: [" + shortest_number(c.interval_lo) + ", " + shortest_number(c.interval_hi) + "]\n";
  }
  return out;
}

} // namespace sreh
