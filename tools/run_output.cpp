#include "tools/run_output.hpp"

#include <ostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "io/text.hpp"
#include "scenarios/result_json.hpp"

namespace sreh::tools {
namespace {

std::string failure_line(const std::string& f) { return "  " + io::escape_control(f) + "\n"; }

} // namespace

RunOutput::RunOutput(bool json, bool in_memory, bool json_line)
    : json_(json), in_memory_(in_memory), json_line_(json_line) {
  if (in_memory_) return;
  if (json_) json_stream_.emplace(json_line_ ? -1 : 2);
  else failure_lines_.emplace();
}

void RunOutput::attach(RunOptions& options) {
  if (in_memory_) return;
  if (json_stream_) {
    json_stream_->attach(options);
    return;
  }
  // The summary needs only the counts (RunResult::checks_recorded ...) and the failures.
  options.check_sink = [](const CheckRecord&) {};
  options.move_sink = [](const MoveRecord&) {};
  options.failure_sink = [this](const std::string& f) { failure_lines_->stream() << failure_line(f); };
}

void RunOutput::print(std::ostream& out, const RunResult& r) {
  if (json_) {
    if (json_stream_) json_stream_->write(out, r);
    else out << to_json(r).dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
    out << "\n";
    return;
  }
  out << (r.passed ? "PASS" : "FAIL") << "  " << io::escape_control(r.name) << "\n";
  print_failures(out, r);
  out << fmt::format("  {} of {} checks held, {} moves, {:.3f} s simulated{}\n", r.checks_held, r.checks_recorded,
                     r.moves_recorded, r.sim_time_s, r.stopped_early ? " (stopped at the first failure)" : "");
  out << fmt::format("  final: {} at {:.3f} deg, error_code {}, warning_code {}\n", state_name(r.final_state.state),
                     r.final_state.position_deg, r.final_state.error_code, r.final_state.warning_code);
}

void RunOutput::print_failures(std::ostream& out, const RunResult& r) {
  if (failure_lines_) failure_lines_->copy_to(out);
  for (const auto& f : r.failures) out << failure_line(f);
}

void RunOutput::print_file_line(std::ostream& out, const RunResult& r, const std::string& file, double wall_s) {
  if (json_) {
    const nlohmann::json extra = {{"file", file}};
    if (json_stream_) {
      json_stream_->write(out, r, extra);
    } else {
      nlohmann::json j = to_json(r);
      j.update(extra);
      out << j.dump(json_line_ ? -1 : 2, ' ', false, nlohmann::json::error_handler_t::replace);
    }
    out << "\n";
    return;
  }
  out << fmt::format("{}  {}  {}  ({:.3f} s simulated, {:.2f} s)\n", r.passed ? "PASS" : "FAIL", io::escape_control(file),
                     io::escape_control(r.name), r.sim_time_s, wall_s);
  print_failures(out, r);
}

} // namespace sreh::tools
