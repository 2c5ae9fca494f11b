#include "tools/junit_report.hpp"

#include <filesystem>
#include <ostream>

#include <fmt/format.h>

#include "io/atomic_file.hpp"
#include "io/html_page.hpp"
#include "io/text.hpp"

namespace sreh::tools {
namespace {

constexpr std::size_t kMaxCheckLines = 2000; // a long run's checks are counted, not all listed
constexpr std::size_t kMaxFailures = 100;

// XML text and attribute values: control characters (not allowed in XML
// 1.0) escaped as the CLI echoes them, then & < > " ' (io/html_page.hpp).
std::string xml(const std::string& raw) { return io::html_escape(io::escape_control(raw)); }

// Element text (<failure>, <system-out>): as xml(), but each line its own
// line (issue 39: CI servers show the log as written, not as one line with
// "\n" in it).
std::string xml_lines(const std::string& raw) {
  std::string out;
  std::size_t from = 0;
  while (from < raw.size()) {
    std::size_t to = raw.find('\n', from);
    if (to == std::string::npos) to = raw.size();
    out += xml(raw.substr(from, to - from));
    if (to < raw.size()) out += '\n';
    from = to + 1;
  }
  return out;
}

} // namespace

void JunitReport::begin_case(const std::string& file, const std::string& scenario_name) {
  const std::filesystem::path p(file);
  Case c;
  c.classname = p.parent_path().empty() ? "." : p.parent_path().string();
  c.name = p.stem().string();
  c.file = file;
  c.scenario_name = scenario_name;
  cases_.push_back(std::move(c));
}

void JunitReport::chain(RunOptions& options) {
  auto checks = options.check_sink;
  options.check_sink = [this, checks](const CheckRecord& r) {
    if (checks) checks(r);
    Case& c = cases_.back();
    if (c.check_lines++ >= kMaxCheckLines) {
      ++c.checks_left_out;
      return;
    }
    c.checks += fmt::format("{}  step {} (line {}) at {:.4f} s: {}: {}\n", r.passed ? "PASS" : "FAIL", r.step, r.line,
                            r.t_s, r.description, r.actual);
  };
  auto failures = options.failure_sink;
  options.failure_sink = [this, failures](const std::string& f) {
    if (failures) failures(f);
    Case& c = cases_.back();
    if (c.failures.size() < kMaxFailures) c.failures.push_back(f);
  };
}

void JunitReport::end_case(const RunResult& result, double wall_s) {
  Case& c = cases_.back();
  c.wall_s = wall_s;
  if (!result.passed && c.failures.empty()) c.failures.push_back("the run did not pass");
}

void JunitReport::end_case_with_error(const std::string& message) {
  Case& c = cases_.back();
  c.error = true;
  c.failures = {message};
}

void JunitReport::write(const std::string& path) const {
  std::size_t failed = 0, errors = 0;
  double total_s = 0;
  for (const Case& c : cases_) {
    if (c.error) ++errors;
    else if (!c.failures.empty()) ++failed;
    total_s += c.wall_s;
  }
  io::write_file_atomic(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out << fmt::format("<testsuites name=\"sreh-twin\" tests=\"{}\" failures=\"{}\" errors=\"{}\" time=\"{:.3f}\">\n",
                       cases_.size(), failed, errors, total_s);
    out << fmt::format("  <testsuite name=\"sreh-twin run\" tests=\"{}\" failures=\"{}\" errors=\"{}\" time=\"{:.3f}\">\n",
                       cases_.size(), failed, errors, total_s);
    for (const Case& c : cases_) {
      out << fmt::format("    <testcase classname=\"{}\" name=\"{}\" time=\"{:.3f}\">\n", xml(c.classname),
                         xml(c.name), c.wall_s);
      if (!c.failures.empty()) {
        std::string text;
        for (const std::string& f : c.failures) text += f + "\n";
        out << fmt::format("      <{} message=\"{}\" type=\"{}\">{}</{}>\n", c.error ? "error" : "failure",
                           xml(c.failures.front()), c.error ? "bad input" : "check failed", xml_lines(text),
                           c.error ? "error" : "failure");
      }
      std::string text = c.file + ": " + c.scenario_name + "\n" + c.checks;
      if (c.checks_left_out > 0) text += fmt::format("... and {} more checks\n", c.checks_left_out);
      out << "      <system-out>" << xml_lines(text) << "</system-out>\n";
      out << "    </testcase>\n";
    }
    out << "  </testsuite>\n</testsuites>\n";
  });
}

} // namespace sreh::tools
