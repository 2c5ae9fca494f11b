// Strict typed access to yaml-cpp nodes: every failure is a ScenarioError
// naming file:line:col and the dotted key path (docs/style.md 13). Internal to
// the scenario parser.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "device_logic/parameter_ids.hpp"
#include "scenarios/pd_out_fields.hpp"
#include "scenarios/scenario.hpp"

namespace sreh::detail {

// Plain-scalar number syntax: decimal integers, 0x hex integers, decimals
// with optional exponent. No inf / nan.
std::optional<int64_t> parse_integer(std::string_view text);
std::optional<double> parse_number(std::string_view text);

class YamlReader {
 public:
  explicit YamlReader(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  SourceLoc loc(const YAML::Node& node) const;
  [[noreturn]] void fail(const YAML::Node& node, const std::string& message) const;
  [[noreturn]] void fail(const SourceLoc& loc, const std::string& message) const;

  // A mapping whose keys are all in `allowed`, none twice.
  void check_map(const YAML::Node& node, std::string_view what,
                 const std::vector<std::string_view>& allowed) const;
  // A required key of a checked mapping.
  YAML::Node require(const YAML::Node& map, std::string_view key, std::string_view what) const;

  double number(const YAML::Node& node, std::string_view what, double min, double max) const;
  // A value a parameter-table row holds, in its display unit, within the
  // row's range (manual 6.2): the range is the table's, never retyped.
  double row_number(const YAML::Node& node, std::string_view what, ParamId row) const {
    return number(node, what, display_min(row), display_max(row));
  }
  int64_t integer(const YAML::Node& node, std::string_view what, int64_t min, int64_t max) const;
  bool boolean(const YAML::Node& node, std::string_view what) const;
  std::string text(const YAML::Node& node, std::string_view what) const; // any scalar
  // A number or [min, max]; a plain number x becomes [x - tol, x + tol].
  Range range(const YAML::Node& node, std::string_view what, double min, double max,
              bool integers, double tol = 0.0) const;
  // Quoted, or tagged !!str: a text, never a number or a boolean (issue 12).
  bool is_quoted(const YAML::Node& node) const {
    return node.Tag() == "!" || node.Tag() == "tag:yaml.org,2002:str";
  }

 private:
  std::string file_;
};

std::string join_path(std::string_view parent, std::string_view key); // "pd" + "move" -> "pd.move"

// The keys of one mapping read through a reader (messages name `what.key`
// and the line): the YAML side of the process-data reader (pd_out_fields.hpp).
class YamlFieldSource final : public PdFieldSource {
 public:
  YamlFieldSource(const YamlReader& r, const YAML::Node& map, const std::string& what) : r_(r), map_(map), what_(what) {}
  bool has(std::string_view key) const override;
  double number(std::string_view key, double lo, double hi) const override;
  int64_t integer(std::string_view key, int64_t lo, int64_t hi) const override;
  bool boolean(std::string_view key) const override;
  [[noreturn]] void fail(std::string_view key, const std::string& message) const override;

 private:
  std::string path(std::string_view key) const { return what_ + "." + std::string(key); }
  const YamlReader& r_;
  const YAML::Node& map_;
  const std::string& what_;
};

} // namespace sreh::detail
