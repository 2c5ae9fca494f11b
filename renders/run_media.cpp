#include "renders/run_media.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <regex>

#include <fmt/format.h>

#include "renders/report.hpp"
#include "renders/report_recorder.hpp"
#include "renders/run_recording.hpp"
#include "twin/load_builder.hpp"
#include "twin/plant.hpp"
#include "twin/twin.hpp"

namespace sreh {

namespace fs = std::filesystem;

namespace {
constexpr std::size_t kCardFailures = 4; // failed checks a closing card lists; the rest are counted

std::string code_text(const char* what, uint8_t code) {
  return code == 0 ? fmt::format("no {}", what) : fmt::format("{} 0x{:02X}", what, code);
}

ReportCheck report_check(const CheckRecord& c) { return {c.description, c.passed, c.step, c.line, c.t_s, c.actual}; }

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec);
}
} // namespace

TitleCard make_closing_card(const RunResult& r, const std::vector<std::string>& failures, std::size_t failures_total) {
  TitleCard card;
  const uint64_t failed = r.checks_recorded - std::min(r.checks_held, r.checks_recorded);
  if (r.passed) {
    card.heading = r.checks_recorded == 0 ? std::string("PASS (no checks)") : fmt::format("PASS: all {} checks held", r.checks_recorded);
    card.heading_rgb = {0.45f, 0.9f, 0.45f};
  } else {
    card.heading = failed > 0 ? fmt::format("FAIL: {} of {} checks failed", failed, r.checks_recorded) : std::string("FAIL");
    if (r.stopped_early) card.heading += " (run stopped early)";
    card.heading_rgb = {1.0f, 0.42f, 0.36f};
  }
  const std::size_t shown = std::min(failures.size(), kCardFailures);
  for (std::size_t i = 0; i < shown; ++i) card.lines.emplace_back(i == 0 ? "failed" : "", failures[i]);
  if (failures_total > shown) {
    card.lines.emplace_back(shown == 0 ? "failed" : "", fmt::format("{}{} more (the run's output lists them)", shown == 0 ? "" : "... and ",
                                                                   failures_total - shown));
  }
  const FinalState& f = r.final_state;
  card.lines.emplace_back("final state", fmt::format("{} at {:.2f} deg, LED {}", state_name(f.state), f.position_deg, led_name(f.led)));
  card.lines.emplace_back("codes", code_text("error", f.error_code) + ", " + code_text("warning", f.warning_code));
  card.lines.emplace_back("moves", fmt::format("{}", r.moves_recorded));
  card.lines.emplace_back("tracking error", fmt::format("{:.3f} deg at most", r.max_tracking_error_deg));
  card.lines.emplace_back("simulated", fmt::format("{:.3f} s", r.sim_time_s));
  return card;
}

std::string load_title(const LoadSpec& load, const std::string& scenario_file) {
  if (const auto* m = std::get_if<MjcfLoad>(&load)) return fs::path(m->path).filename().string();
  const auto* a = std::get_if<AssemblyLoad>(&load);
  if (a == nullptr) return describe_load(load);
  // origin: "FILE:LINE:COL" where the parts are written.
  std::smatch at;
  const std::string origin = a->origin;
  const bool located = std::regex_match(origin, at, std::regex("(.*):[0-9]+:[0-9]+"));
  const std::string file = located ? at[1].str() : origin;
  if (!file.empty() && !same_file(file, scenario_file)) {
    std::string name;
    try {
      const YAML::Node root = YAML::LoadFile(file); // read once already: the run parsed it
      if (root["name"] && root["name"].IsScalar()) name = root["name"].Scalar();
    } catch (const YAML::Exception&) {
    }
    const std::string base = fs::path(file).filename().string();
    return name.empty() ? base : fmt::format("{} ({})", name, base);
  }
  std::string parts;
  for (const LoadPart& p : a->parts) {
    if (!p.name.empty()) parts += (parts.empty() ? "" : ", ") + p.name;
  }
  const std::string n = fmt::format("assembly of {} part{}", a->parts.size(), a->parts.size() == 1 ? "" : "s");
  return parts.empty() ? n : n + ": " + parts;
}

struct RunMedia::Impl {
  RunMediaOptions options;
  TitleFacts title;
  uint32_t last_move = 0;
  std::string step, caption;
  std::unique_ptr<RunRecording> recording;
  std::optional<ReportRecorder> report;
  std::vector<std::string> failures; // the first few, for the closing card
  std::size_t failures_seen = 0;
  bool failures_streamed = false, checks_streamed = false, moves_streamed = false;

  void on_cycle(const Twin& twin) {
    const Plant& plant = twin.plant();
    if (!recording) {
      recording = std::make_unique<RunRecording>(plant.model());
      title.load_inertia_gcm2 = twin.load_inertia_gcm2();
    }
    // The title card lists each parameter set a move latched, as it was then (issue 29).
    if (const std::optional<MoveRecord> move = twin.device().pending_move(); move && move->number != last_move) {
      last_move = move->number;
      if (!title.sets.contains(move->parameter_set)) {
        title.sets.emplace(move->parameter_set, twin.device().snapshot().configuration.store.motion_set(move->parameter_set));
      }
    }
    FrameInfo info;
    info.row = twin.last_row();
    info.ghost_joint_rad = plant.ghost_angle_rad();
    info.step = step;
    info.caption = caption;
    recording->add(plant.data(), info);
  }
};

RunMedia::RunMedia(const Scenario& s, RunMediaOptions options) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.options = std::move(options);
  m.title.scenario_name = s.name;
  m.title.scenario_file = s.file;
  m.title.load = load_title(s.world.load, s.file);
  m.title.mounting_tilt_deg = s.world.mounting_tilt_deg;
  m.title.supply_V = s.world.supply.voltage_V;
  if (!m.options.report_dir.empty()) m.report.emplace();
}

RunMedia::~RunMedia() = default;

void RunMedia::attach(RunOptions& o) {
  Impl& m = *impl_;
  if (m.options.video) {
    o.on_cycle = [prev = std::move(o.on_cycle), &m](const Twin& twin) {
      m.on_cycle(twin);
      if (prev) prev(twin);
    };
    o.on_step = [prev = std::move(o.on_step), &m](const Step& step) {
      if (prev) prev(step);
      m.step = step.number + " " + step.kind;
      // A `comment:` step is the caption until the next one (issue 39).
      if (const auto* c = std::get_if<CommentStep>(&step.action)) m.caption = c->text;
    };
  }
  // Records the caller streams (the CLI's output) are taken on the way;
  // otherwise they stay in the RunResult (Python's dict) and are read from
  // it after the run.
  if (o.failure_sink) {
    m.failures_streamed = true;
    o.failure_sink = [prev = std::move(o.failure_sink), &m](const std::string& f) {
      prev(f);
      if (m.failures.size() < kCardFailures) m.failures.push_back(f);
      ++m.failures_seen;
    };
  }
  if (!m.report) return;
  ReportRecorder& report = *m.report;
  o.trace_sink = [prev = std::move(o.trace_sink), &report](const TraceRow& row) {
    if (prev) prev(row);
    report.add_row(row);
  };
  if (o.check_sink) {
    m.checks_streamed = true;
    o.check_sink = [prev = std::move(o.check_sink), &report](const CheckRecord& c) {
      prev(c);
      report.add_check(report_check(c));
    };
  }
  if (o.move_sink) {
    m.moves_streamed = true;
    o.move_sink = [prev = std::move(o.move_sink), &report](const MoveRecord& mv) {
      prev(mv);
      report.add_move(mv);
    };
  }
}

void RunMedia::render_video(const RunResult& result, const std::function<void(double)>& progress) {
  Impl& m = *impl_;
  if (m.options.video) {
    if (!m.recording) throw std::runtime_error("video: the run has no cycle to show");
    VideoOptions vo = *m.options.video;
    vo.progress = progress;
    const TimeScaleOptions scale;
    if (!vo.time_map) {
      vo.time_map = m.options.fixed_slowmo ? TimeMap::constant(vo.slowmo, m.recording->duration_s())
                                           : TimeMap::automatic(m.recording->motion(), m.recording->duration_s(), scale);
    }
    m.title.time_scale = vo.time_map->describe(scale);
    vo.title = make_title_card(m.title);
    const TitleCard closing = m.failures_streamed ? make_closing_card(result, m.failures, m.failures_seen)
                                                  : make_closing_card(result, result.failures, result.failures.size());
    vo.closing = closing;
    m.recording->render(vo, m.options.fixed_slowmo, scale);
  }
}

void RunMedia::write_report(const RunResult& result) {
  Impl& m = *impl_;
  if (m.report) {
    if (!m.checks_streamed) {
      for (const CheckRecord& c : result.checks) m.report->add_check(report_check(c));
    }
    if (!m.moves_streamed) {
      for (const MoveRecord& mv : result.moves) m.report->add_move(mv);
    }
    ReportSummary summary;
    summary.scenario_name = result.name;
    summary.passed = result.passed;
    summary.tracking_limit_deg = result.tracking_limit_deg;
    summary.command_line = m.options.command_line;
    summary.version = m.options.version;
    summary.sim_time_s = result.sim_time_s;
    summary.max_tracking_error_deg = result.max_tracking_error_deg;
    summary.hints = result.hints;
    if (m.options.video && !m.options.video->path.empty()) summary.video_source = m.options.video->path; // copied in
    sreh::write_report(m.options.report_dir, summary, *m.report);
  }
}


} // namespace sreh
