#include "tools/cli_hints.hpp"

#include <cctype>
#include <cstdlib>
#include <utility>
#include <vector>

#include "io/text.hpp"

namespace sreh::tools {
namespace {

// The subcommand argv[1] names (nullptr for none or an unknown one).
const CLI::App* subcommand_of(const CLI::App& app, int argc, char** argv) {
  if (argc < 2) return nullptr;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (sub->get_name() == argv[1]) return sub;
  }
  return nullptr;
}

// "--load-kgm2 is not an option of size; did you mean --load-gcm2?"
std::string unknown_option(const CLI::App& sub, const std::string& given) {
  std::vector<std::string> names;
  for (const CLI::Option* o : sub.get_options()) {
    for (const std::string& name : o->get_lnames()) names.push_back(name);
  }
  const std::string best = io::closest_name(given.substr(2), names);
  std::string out = given + " is not an option of " + sub.get_name();
  return best.empty() ? out + " (sreh-twin " + sub.get_name() + " --help lists them)" : out + "; did you mean --" + best + "?";
}

// A number followed by letters: "90deg", "5000gcm2", "0.5s".
bool number_with_unit(const std::string& value) {
  char* end = nullptr;
  std::strtod(value.c_str(), &end);
  return end != value.c_str() && *end != '\0' && std::isalpha(static_cast<unsigned char>(*end));
}

// "90", "0,5000,15000": every comma-separated piece a number.
bool all_numbers(const std::string& value) {
  if (value.empty()) return false;
  std::size_t at = 0;
  for (;;) {
    const std::size_t comma = value.find(',', at);
    const std::string piece = value.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    char* end = nullptr;
    std::strtod(piece.c_str(), &end);
    if (piece.empty() || end == piece.c_str() || *end != '\0') return false;
    if (comma == std::string::npos) return true;
    at = comma + 1;
  }
}

// The unit an option's name ends in, in words, and a typical value
// (issue 39): "--angle-deg" -> {"deg", "90"}. Empty: no unit in the name.
std::pair<std::string, std::string> unit_of(const std::string& option) {
  static const std::pair<const char*, std::pair<const char*, const char*>> kUnits[] = {
      {"-deg", {"deg", "90"}},     {"-dps", {"deg/s", "600"}},     {"-pct", {"%", "50"}},
      {"-gcm2", {"g cm^2", "5000"}}, {"-ms", {"ms", "100"}},       {"-s", {"s", "0.5"}},
      {"-V", {"V", "24"}},         {"-C", {"degC", "25"}},         {"-K", {"K", "10"}},
      {"-ohm", {"ohm", "0.5"}},    {"-F", {"F", "0.001"}},         {"-mb", {"MB", "100"}},
      {"-Nm", {"N m", "0.5"}},     {"-hz", {"Hz", "500"}},         {"-Hz", {"Hz", "500"}},
  };
  for (const auto& [suffix, unit] : kUnits) {
    const std::string s = suffix;
    if (option.size() > s.size() && option.compare(option.size() - s.size(), s.size(), s) == 0) return unit;
  }
  return {};
}

// "--angle-deg ninety" -> "--angle-deg ninety: expected a number in deg, e.g. 90".
std::string not_a_number(const CLI::Option& o, const std::string& name, const std::string& value) {
  const std::string type = o.get_type_name();
  const bool whole = type.find("INT") != std::string::npos;
  const bool number = whole || type.find("FLOAT") != std::string::npos || type.find("NUMBER") != std::string::npos;
  if (!number) return {};
  if (number_with_unit(value)) return name + " " + value + ": give the number alone; the option's name says its unit";
  const auto [unit, example] = unit_of(name);
  const std::string kind = whole ? "a whole number" : "a number";
  const std::string list = o.get_expected_max() > 1 ? " (a list: comma separated)" : "";
  std::string e = example;
  if (const std::string d = o.get_default_str(); !d.empty() && d.find_first_not_of("0123456789.-") == std::string::npos) e = d;
  if (e.empty()) e = whole ? "5" : "1.5";
  return name + " " + io::escape_control(value) + ": expected " + kind + (unit.empty() ? "" : " in " + unit) + list + ", e.g. " + e;
}

} // namespace

std::string command_hint(const CLI::App& app, const std::string& given) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
  return io::closest_name(given, names);
}

std::string cli_hint(const CLI::App& app, const CLI::ParseError& error, int argc, char** argv) {
  const CLI::App* sub = subcommand_of(app, argc, argv);
  if (sub == nullptr) return {};
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--", 0) != 0 || arg.size() < 3) continue;
    const std::string name = arg.substr(0, arg.find('='));
    const CLI::Option* option = nullptr;
    for (const CLI::Option* o : sub->get_options()) {
      if (o->check_lname(name.substr(2))) option = o;
    }
    if (option == nullptr && dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr) return unknown_option(*sub, name);
    if (option != nullptr && dynamic_cast<const CLI::ConversionError*>(&error) != nullptr) {
      const std::size_t eq = arg.find('=');
      const std::string value = eq != std::string::npos ? arg.substr(eq + 1) : (i + 1 < argc ? argv[i + 1] : "");
      // The option CLI11 could not convert: the one whose value is not a number (or list of them).
      if (all_numbers(value)) continue;
      if (std::string m = not_a_number(*option, name, value); !m.empty()) return m;
    }
  }
  return {};
}

} // namespace sreh::tools
