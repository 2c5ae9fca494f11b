#include "tools/run_output.hpp"

#include <cmath>
#include <ostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "device_logic/fault_names.hpp"
#include "io/text.hpp"

namespace sreh::tools {
namespace {

std::string failure_line(const std::string& f) { return "  " + io::escape_control(f) + "\n"; }

} // namespace

RunOutput::RunOutput(bool json, bool json_line) : json_(json), json_line_(json_line) {
  if (json_) json_stream_.emplace(json_line_ ? -1 : 2);
  else failure_lines_.emplace();
}

void RunOutput::attach(RunOptions& options) {
  if (json_stream_) {
    json_stream_->attach(options);
    return;
  }
  // The summary needs only the counts (RunResult::checks_recorded ...) and the failures.
  options.check_sink = [](const CheckRecord&) {};
  options.move_sink = [](const MoveRecord&) {};
  options.failure_sink = [this](const std::string& f) { failure_lines_->stream() << failure_line(f); };
}

namespace {
// Wall time and real-time factor: measured, so they differ run to run; they
// come last in the object so that everything before them is the
// deterministic result (tools tests compare that part byte for byte).
nlohmann::json timing(const RunResult& r, double wall_s) {
  const double w = std::round(wall_s * 1e4) / 1e4;
  return {{"wall_s", w}, {"real_time_factor", wall_s > 0 ? std::round(r.sim_time_s / wall_s * 10.0) / 10.0 : 0.0}};
}
} // namespace

void RunOutput::print(std::ostream& out, const RunResult& r, double wall_s) {
  if (json_) {
    json_stream_->write(out, r, timing(r, wall_s));
    out << "\n";
    return;
  }
  out << (r.passed ? "PASS" : "FAIL") << "  " << io::escape_control(r.name) << "\n";
  for (const std::string& h : r.hints) out << "  " << h << "\n"; // issue 28: the commissioning hint
  print_failures(out);
  out << fmt::format("  {} of {} checks held, {} moves, {:.3f} s simulated{}\n", r.checks_held, r.checks_recorded,
                     r.moves_recorded, r.sim_time_s, r.stopped_early ? " (stopped at the first failure)" : "");
  out << fmt::format("  final: {} at {:.3f} deg, error_code {}, warning_code {}\n", state_name(r.final_state.state),
                     r.final_state.position_deg, error_byte_text(r.final_state.error_code),
                     warning_byte_text(r.final_state.warning_code));
}

// The runner handed every failure to the sink: RunResult::failures is empty.
void RunOutput::print_failures(std::ostream& out) { failure_lines_->copy_to(out); }

void RunOutput::print_file_line(std::ostream& out, const RunResult& r, const std::string& file, double wall_s) {
  if (json_) {
    // No wall time here: the lines of shards 1..N concatenated are byte for
    // byte those of the unsharded run (interfaces.md, issue 17).
    json_stream_->write(out, r, {{"file", file}});
    out << "\n";
    return;
  }
  out << fmt::format("{}  {}  {}  ({:.3f} s simulated, {:.2f} s)\n", r.passed ? "PASS" : "FAIL", io::escape_control(file),
                     io::escape_control(r.name), r.sim_time_s, wall_s);
  for (const std::string& h : r.hints) out << "  " << h << "\n";
  print_failures(out);
}

} // namespace sreh::tools
