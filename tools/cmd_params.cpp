// `sreh-twin params [list | show INDEX[.SUB]] [--json]`: the device's
// parameter table (manual chapter 6) as an aligned table or JSON
// (interfaces.md). Reads device_logic/parameter_table only; exit 2 for an
// unknown or malformed index.
#include <algorithm>
#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "device_logic/parameter_table.hpp"
#include "io/atomic_file.hpp"
#include "io/output_path.hpp"
#include "tools/command.hpp"
#include "tools/iodd_export.hpp"

namespace sreh::tools {
namespace {

using Json = nlohmann::ordered_json;

struct ParamsArgs {
  bool json = false;
  bool wide = false; // every column; the default view fits 100 columns
  std::string which; // INDEX[.SUB] for `show`
  std::string iodd_path; // FILE.xml for `export --iodd`
};

std::string hex_octets(std::string_view bytes) {
  std::string out;
  for (unsigned char c : bytes) out += fmt::format("{}{:02X}", out.empty() ? "" : " ", c);
  return out;
}

// A string default prints as text, octet strings / records as hex octets.
std::string text_default(const ParameterEntry& row) {
  return row.type == ParamType::String ? std::string(row.default_text) : hex_octets(row.default_text);
}

std::string display_value(const ParameterEntry& row, int64_t raw) {
  const std::string v = fmt::format("{:.8g}", static_cast<double>(raw) * row.display_scale);
  return row.display_unit.empty() ? v : v + " " + std::string(row.display_unit);
}

bool non_volatile(const ParameterEntry& row) {
  return row.storage == Storage::Config || row.storage == Storage::PersistentDiag ||
         (row.storage == Storage::Identification && row.access == Access::RW);
}

Json row_json(const ParameterEntry& row) {
  Json j;
  j["index"] = row.index;
  j["subindex"] = row.subindex;
  j["name"] = row.name;
  if (!row.record_name.empty()) j["record"] = row.record_name;
  j["type"] = row_type_text(row);
  j["access"] = access_name(row.access);
  j["storage"] = storage_name(row.storage);
  j["non_volatile"] = non_volatile(row);
  j["raw_unit"] = row.raw_unit;
  j["display_unit"] = row.display_unit;
  if (is_numeric(row.type)) {
    j["display_scale"] = row.display_scale;
    j["min"] = row.min;
    j["max"] = row.max;
    j["default"] = row.default_value;
  } else {
    j["max_length"] = row.max_length;
    j["min"] = nullptr;
    j["max"] = nullptr;
    j["default"] = text_default(row);
  }
  j["section"] = row.section;
  if (!row.notes.empty()) j["notes"] = row.notes;
  return j;
}

// ------------------------------------------------------------------- list

std::string clip(std::string s, std::size_t n) {
  return s.size() <= n ? s : s.substr(0, n - 3) + "...";
}

// Columns padded to their widest cell, two spaces apart, no trailing blanks;
// the columns in `right_aligned` (numbers) flush right.
void print_table(std::ostream& os, const std::vector<std::vector<std::string>>& rows,
                 std::initializer_list<std::size_t> right_aligned = {}) {
  std::vector<std::size_t> width;
  for (const auto& r : rows) {
    width.resize(std::max(width.size(), r.size()), 0);
    for (std::size_t c = 0; c < r.size(); ++c) width[c] = std::max(width[c], r[c].size());
  }
  for (const auto& r : rows) {
    std::string line;
    for (std::size_t c = 0; c < r.size(); ++c) {
      const bool right = std::find(right_aligned.begin(), right_aligned.end(), c) != right_aligned.end();
      line += right ? fmt::format("{:>{}}", r[c], width[c]) : fmt::format("{:<{}}", r[c], width[c]);
      if (c + 1 < r.size()) line += "  ";
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    os << line << "\n";
  }
}

std::string default_cell(const ParameterEntry& row) {
  if (row.access == Access::W) return "-"; // commands have no default
  if (is_numeric(row.type)) return std::to_string(row.default_value);
  if (row.default_text.empty()) return "-"; // computed by the device
  return clip('"' + text_default(row) + '"', 34);
}

std::vector<std::string> row_cells(const ParameterEntry& row) {
  const bool num = is_numeric(row.type);
  const std::string name = row.record_name.empty() ? std::string(row.name)
                                                   : fmt::format("{}: {}", row.record_name, row.name);
  return {std::to_string(row.index),
          std::to_string(row.subindex),
          clip(name, 60),
          std::string(row_type_text(row)),
          std::string(access_name(row.access)),
          std::string(row.raw_unit.empty() ? "-" : row.raw_unit),
          std::string(row.display_unit.empty() ? "-" : row.display_unit),
          num ? std::to_string(row.min) : "-",
          num ? std::to_string(row.max) : "-",
          default_cell(row),
          std::string(row.section)};
}

// The narrow view (fits 100 columns): one "index.sub" cell, the range as
// "min..max" ("full" for the type's whole range), the raw unit, a short default.
bool full_range(const ParameterEntry& row) {
  switch (row.type) {
    case ParamType::UInt8: return row.min == 0 && row.max == 0xFF;
    case ParamType::UInt16: return row.min == 0 && row.max == 0xFFFF;
    case ParamType::UInt32: return row.min == 0 && row.max == 0xFFFFFFFF;
    case ParamType::Int32: return row.min == INT32_MIN && row.max == INT32_MAX;
    default: return false;
  }
}

std::vector<std::string> narrow_cells(const ParameterEntry& row) {
  const bool num = is_numeric(row.type);
  std::string record(row.record_name);
  if (record.rfind("Motion parameter set ", 0) == 0) record = "Set " + record.substr(21); // "Set 1: ..."
  const std::string name = record.empty() ? std::string(row.name) : fmt::format("{}: {}", record, row.name);
  std::string range = "-";
  if (num) range = full_range(row) ? "full" : fmt::format("{}..{}", row.min, row.max);
  return {fmt::format("{}.{}", row.index, row.subindex),
          clip(name, 32),
          clip(std::string(row_type_text(row)), 8),
          std::string(access_name(row.access)),
          clip(range, 16),
          clip(std::string(row.raw_unit.empty() ? "-" : row.raw_unit), 13),
          clip(default_cell(row), 10)};
}

int list_command(const ParamsArgs& a) {
  if (a.json) {
    Json out = Json::array();
    for (const auto& row : parameter_table()) out.push_back(row_json(row));
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  if (!a.wide) {
    std::vector<std::vector<std::string>> rows{{"param", "name", "type", "acc", "raw range", "raw unit", "default"}};
    for (const auto& row : parameter_table()) rows.push_back(narrow_cells(row));
    print_table(std::cout, rows);
    std::cout << "Raw wire values. Units, sections: 'params show INDEX.SUB'; all columns: --wide\n";
    return 0;
  }
  std::vector<std::vector<std::string>> rows{
      {"index", "sub", "name", "type", "access", "raw unit", "display unit", "min", "max", "default", "section"}};
  for (const auto& row : parameter_table()) rows.push_back(row_cells(row));
  print_table(std::cout, rows, {0, 1, 7, 8}); // index, sub, min, max
  return 0;
}

// ------------------------------------------------------------------- show

struct Selector {
  uint16_t index;
  std::optional<uint8_t> subindex;
};

Selector parse_selector(const std::string& text) {
  static const std::regex pattern(R"(^(\d{1,5})(?:\.(\d{1,3}))?$)");
  std::smatch m;
  if (!std::regex_match(text, m, pattern) || std::stoul(m[1].str()) > 0xFFFF ||
      (m[2].matched && std::stoul(m[2].str()) > 0xFF)) {
    throw InputError(fmt::format("malformed parameter '{}': expected INDEX or INDEX.SUB, e.g. 64.1 "
                                 "(see 'sreh-twin params list')",
                                 text));
  }
  Selector s{static_cast<uint16_t>(std::stoul(m[1].str())), std::nullopt};
  if (m[2].matched) s.subindex = static_cast<uint8_t>(std::stoul(m[2].str()));
  if (!index_exists(s.index))
    throw InputError(fmt::format("unknown parameter index {} (see 'sreh-twin params list')", s.index));
  return s;
}

void print_row_details(std::ostream& os, const ParameterEntry& row) {
  os << fmt::format("{}.{}  {}", row.index, row.subindex, row.name);
  if (!row.record_name.empty()) os << fmt::format("  ({})", row.record_name);
  os << "\n";
  const auto line = [&](std::string_view key, const std::string& value) {
    os << fmt::format("  {:<13}{}\n", key, value);
  };
  line("type", std::string(row_type_text(row)));
  line("access", fmt::format("{} ({}{})", access_name(row.access), storage_name(row.storage),
                             non_volatile(row) ? ", non-volatile" : ""));
  if (is_numeric(row.type)) {
    line("raw unit", std::string(row.raw_unit));
    if (!row.display_unit.empty())
      line("display unit", fmt::format("{} (display = raw * {})", row.display_unit, row.display_scale));
    const bool scaled = !row.display_unit.empty();
    line("range", scaled ? fmt::format("{} .. {}   ({} .. {})", row.min, row.max, display_value(row, row.min),
                                       display_value(row, row.max))
                         : fmt::format("{} .. {}", row.min, row.max));
    if (row.access != Access::W)
      line("default", scaled ? fmt::format("{}   ({})", row.default_value, display_value(row, row.default_value))
                             : std::to_string(row.default_value));
  } else {
    line("max length", fmt::format("{} octets", row.max_length));
    if (!row.default_text.empty()) line("default", '"' + text_default(row) + '"');
  }
  line("section", fmt::format("manual {}", row.section));
  if (!row.notes.empty()) line("notes", std::string(row.notes));
}

int show_command(const ParamsArgs& a) {
  const Selector sel = parse_selector(a.which);
  const bool whole_record = is_record(sel.index) && sel.subindex.value_or(0) == 0;
  if (whole_record) {
    const auto members = record_members(sel.index);
    if (a.json) {
      Json j;
      j["index"] = sel.index;
      j["subindex"] = 0;
      j["name"] = members.front()->record_name;
      j["type"] = "record";
      j["members"] = Json::array();
      for (const auto* m : members) j["members"].push_back(row_json(*m));
      std::cout << j.dump(2) << "\n";
    } else {
      std::cout << fmt::format("{}  {} (record, subindex 0 = all members concatenated)\n\n", sel.index,
                               members.front()->record_name);
      for (const auto* m : members) {
        print_row_details(std::cout, *m);
        std::cout << "\n";
      }
    }
    return 0;
  }
  const ParameterEntry* row = find_parameter(sel.index, sel.subindex.value_or(0));
  if (row == nullptr) {
    throw InputError(fmt::format("unknown parameter subindex {}.{} (see 'sreh-twin params show {}')", sel.index,
                                 *sel.subindex, sel.index));
  }
  if (a.json) {
    std::cout << row_json(*row).dump(2) << "\n";
  } else {
    print_row_details(std::cout, *row);
  }
  return 0;
}

// ----------------------------------------------------------------- export

int export_command(const ParamsArgs& a) {
  io::check_outputs({{"--iodd", a.iodd_path, io::OutputKind::File}}, {});
  io::write_file_atomic(a.iodd_path, [](std::ostream& os) { os << iodd_document(SREH_VERSION); });
  std::cout << "wrote " << a.iodd_path << " (the parameter table as an IODD-like XML document)\n"; // issue 39
  return 0;
}

} // namespace

SREH_REGISTER_COMMAND(50, [](CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ParamsArgs>();
  CLI::App* params = app.add_subcommand("params", "The device's parameter table (manual chapter 6)");
  params->add_flag("--json", args->json, "Print JSON (with no subcommand: the list)");
  params->require_subcommand(0, 1);

  CLI::App* list = params->add_subcommand("list", "Every index/subindex: type, access, units, range, default");
  list->add_flag("--json", args->json, "Print a JSON array, one object per index/subindex");
  list->add_flag("--wide", args->wide, "All columns (display unit, min, max, section); over 100 columns wide");
  list->callback([args, &exit_code] { exit_code = list_command(*args); });

  CLI::App* show = params->add_subcommand("show", "One parameter, or all members of a record");
  show->add_option("INDEX[.SUB]", args->which, "Index, or index.subindex, e.g. 64 or 64.1")->required();
  show->add_flag("--json", args->json, "Print one JSON object");
  show->callback([args, &exit_code] { exit_code = show_command(*args); });

  CLI::App* exp = params->add_subcommand("export", "Write a device description generated from the table");
  exp->add_option("--iodd", args->iodd_path,
                  "IODD-like XML (IODD vocabulary; schema docs/iodd/sreh-iodd.xsd)")
      ->required();
  exp->callback([args, &exit_code] { exit_code = export_command(*args); });

  params->callback([params, args, &exit_code] {
    if (params->get_subcommands().empty()) exit_code = list_command(*args);
  });
});

} // namespace sreh::tools
