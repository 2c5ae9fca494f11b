// `sreh-twin codes [CODE] [--markdown]` (issue 39): every code the module
// answers with its name, cause and remedy, from the one table
// (device_logic/faults.hpp, isdu.cpp); one code looked up (0x8CA3, 0x8030,
// 114.5); --markdown prints docs/errors.md.
#include <iostream>
#include <memory>
#include <regex>
#include <string>

#include <fmt/format.h>

#include "device_logic/fault_names.hpp"
#include "device_logic/isdu.hpp"
#include "tools/codes_doc.hpp"
#include "tools/command.hpp"

namespace sreh::tools {
namespace {

struct CodesArgs {
  std::string code;
  bool markdown = false;
};

void print_cause(std::ostream& out, const CauseDefinition& c) {
  out << fmt::format("{} {} code {}: {}\n  {}\n", c.type == EventType::Error ? "error" : "warning",
                     cause_index(c.type, c.subindex), c.code, c.name, c.remedy);
}

void print_event(std::ostream& out, const EventDefinition& e) {
  out << fmt::format("event 0x{:04X}: {}, manual {}\n", e.code, e.name, e.section);
}

void print_all(std::ostream& out) {
  for (const CauseDefinition& c : kCauses) print_cause(out, c);
  for (const EventDefinition& e : kErrorEvents) print_event(out, e);
  for (const EventDefinition& e : kWarningEvents) print_event(out, e);
  for (const IsduErrorDefinition& e : isdu_errors())
    out << fmt::format("ISDU 0x{:04X}: {}: {}\n  {}\n", e.code, e.name, e.when, e.remedy);
}

int lookup(std::ostream& out, const std::string& code) {
  std::smatch m;
  if (std::regex_match(code, m, std::regex(R"(11([45])\.([1-8]))"))) {
    const EventType type = m[1] == "4" ? EventType::Error : EventType::Warning;
    const auto sub = static_cast<uint8_t>(std::stoi(m[2]));
    const auto causes = causes_of_bit(type, static_cast<uint8_t>(8 - sub));
    if (causes.empty()) throw InputError(fmt::format("codes {}: no such cause index (115.1 .. 115.3 for warnings)", code));
    for (const CauseDefinition* c : causes) print_cause(out, *c);
    return 0;
  }
  if (std::regex_match(code, m, std::regex(R"(0[xX]([0-9A-Fa-f]{4}))"))) {
    const auto value = static_cast<uint16_t>(std::stoul(m[1], nullptr, 16));
    if (const EventDefinition* e = find_event(value)) {
      print_event(out, *e);
      for (const CauseDefinition* c : causes_of_bit(e->type, e->bit))
        if (e->cause_code == 0 || e->cause_code == c->code) print_cause(out, *c);
      return 0;
    }
    if (const IsduErrorDefinition* e = find_isdu_error(value)) {
      out << fmt::format("ISDU 0x{:04X}: {}: {}\n  {}\n", e->code, e->name, e->when, e->remedy);
      return 0;
    }
    throw InputError(fmt::format("codes {}: not a code of this module (sreh-twin codes lists them)", code));
  }
  throw InputError(fmt::format("codes {}: expected an event or ISDU code (0x8CA3, 0x8030) or a cause index (114.5)",
                               code));
}

} // namespace

SREH_REGISTER_COMMAND(52, [](CLI::App& app, int& exit_code) {
  auto a = std::make_shared<CodesArgs>();
  CLI::App* cmd = app.add_subcommand("codes", "Every error, warning, event and ISDU code with its name and remedy "
                                              "(manual chapter 7, IO-Link)");
  cmd->add_option("CODE", a->code, "One code: an event or ISDU code (0x8CA3, 0x8030) or a cause index (114.5)");
  cmd->add_flag("--markdown", a->markdown, "Print the whole table as docs/errors.md");
  cmd->callback([a, &exit_code] {
    if (a->markdown) std::cout << codes_markdown();
    else if (!a->code.empty()) exit_code = lookup(std::cout, a->code);
    else print_all(std::cout);
  });
});

} // namespace sreh::tools
