#include "tools/cli_hints.hpp"

#include <cctype>
#include <cstdlib>

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
  std::string best;
  std::size_t best_distance = 5; // more edits than this: no guess
  for (const CLI::Option* o : sub.get_options()) {
    for (const std::string& name : o->get_lnames()) {
      const std::size_t d = io::edit_distance(given.substr(2), name);
      if (d < best_distance) best_distance = d, best = "--" + name;
    }
  }
  std::string out = given + " is not an option of " + sub.get_name();
  return best.empty() ? out + " (sreh-twin " + sub.get_name() + " --help lists them)" : out + "; did you mean " + best + "?";
}

// A number followed by letters: "90deg", "5000gcm2", "0.5s".
bool number_with_unit(const std::string& value) {
  char* end = nullptr;
  std::strtod(value.c_str(), &end);
  return end != value.c_str() && *end != '\0' && std::isalpha(static_cast<unsigned char>(*end));
}

} // namespace

std::string cli_hint(const CLI::App& app, const CLI::ParseError& error, int argc, char** argv) {
  const CLI::App* sub = subcommand_of(app, argc, argv);
  if (sub == nullptr) return {};
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--", 0) != 0 || arg.size() < 3) continue;
    const std::string name = arg.substr(0, arg.find('='));
    bool known = false;
    for (const CLI::Option* o : sub->get_options()) known = known || o->check_lname(name.substr(2));
    if (!known && dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr) return unknown_option(*sub, name);
    if (known && dynamic_cast<const CLI::ConversionError*>(&error) != nullptr) {
      const std::size_t eq = arg.find('=');
      const std::string value = eq != std::string::npos ? arg.substr(eq + 1) : (i + 1 < argc ? argv[i + 1] : "");
      if (number_with_unit(value)) {
        return name + " " + value + ": give the number alone; the option's name says its unit";
      }
    }
  }
  return {};
}

} // namespace sreh::tools
