#include "tools/run_folder.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <tuple>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "io/interrupt.hpp"
#include "io/output_path.hpp"
#include "io/shard.hpp"
#include "io/text.hpp"
#include "scenarios/runner.hpp"
#include "scenarios/scenario_parser.hpp"
#include "tools/command.hpp"
#include "tools/junit_report.hpp"
#include "tools/run_output.hpp"

namespace sreh::tools {
namespace {

namespace fs = std::filesystem;

const char* getenv_ptr(const char* name) { return std::getenv(name); }

std::string shard_note(std::size_t shard, std::size_t shards, std::size_t begin, std::size_t end, std::size_t total) {
  if (shards == 1) return "";
  if (begin == end) return fmt::format(" (shard {}/{}: no file, the folder has {})", shard, shards, total);
  return fmt::format(" (shard {}/{}: files {}..{} of {})", shard, shards, begin + 1, end, total);
}

} // namespace

std::vector<std::string> scenario_files(const std::string& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path p = it->path();
    std::error_code file_ec;
    // Regular files (or links to them) named *.yaml; not recursive.
    if (p.extension() == ".yaml" && fs::is_regular_file(p, file_ec)) names.push_back(p.filename().string());
  }
  if (ec) throw InputError(fmt::format("{}: cannot read the folder: {}", io::escape_control(dir), ec.message()));
  if (names.empty()) throw InputError(fmt::format("{}: no *.yaml scenario files in this folder", io::escape_control(dir)));
  std::sort(names.begin(), names.end()); // bytewise: the same order on every machine and locale
  std::vector<std::string> files;
  for (const std::string& n : names) files.push_back((fs::path(dir) / n).string());
  return files;
}

int run_folder(const FolderArgs& a) {
  const std::vector<std::string> all = scenario_files(a.dir);
  std::size_t shard = 1, shards = 1;
  if (!a.shard.empty()) {
    try {
      std::tie(shard, shards) = io::parse_shard(a.shard, getenv_ptr);
    } catch (const std::invalid_argument& e) {
      throw InputError(e.what());
    }
  }
  const auto [begin, end] = io::shard_range(shard, shards, all.size());
  const std::vector<std::string> files(all.begin() + static_cast<std::ptrdiff_t>(begin),
                                       all.begin() + static_cast<std::ptrdiff_t>(end));

  // Bad input in any file of the shard: nothing runs (issue 12: before any long work).
  // One line per bad file on stderr, the last one as the error (exit 2).
  std::vector<Scenario> scenarios;
  std::optional<std::string> last_error;
  for (const std::string& f : files) {
    try {
      scenarios.push_back(parse_scenario_file(f, a.limits));
      apply_command_line_model(scenarios.back(), a.model);
      check_setup(scenarios.back(), a.limits);
    } catch (const ScenarioError& e) {
      if (last_error) std::cerr << "sreh-twin: " << io::escape_control(*last_error) << "\n";
      last_error = e.what();
    }
  }
  if (last_error) throw InputError(*last_error);

  io::check_outputs({{"--junit", a.junit, io::OutputKind::File}}, files);
  JunitReport junit;
  std::size_t held = 0, failed = 0, errors = 0;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const auto start = std::chrono::steady_clock::now();
    std::optional<RunOutput> output;
    try {
      output.emplace(a.json, true);
    } catch (const std::runtime_error& e) {
      throw InputError(e.what());
    }
    RunOptions options;
    options.limits = a.limits;
    output->attach(options);
    if (!a.junit.empty()) {
      junit.begin_case(files[i], scenarios[i].name);
      junit.chain(options);
    }
    RunResult result;
    try {
      result = run_scenario(scenarios[i], options);
    } catch (const ScenarioError& e) {
      // Found only while running (e.g. a load the twin rejects): this file is
      // bad input; the others still run.
      ++errors;
      const std::string what = io::escape_control(e.what());
      if (!a.junit.empty()) junit.end_case_with_error(what);
      if (a.json) {
        std::cout << nlohmann::json{{"file", files[i]}, {"passed", false}, {"error", what}}.dump(
                         -1, ' ', false, nlohmann::json::error_handler_t::replace)
                  << "\n";
      } else {
        std::cout << "ERROR  " << io::escape_control(files[i]) << "  " << what << "\n";
      }
      std::cout.flush();
      continue;
    }
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    (result.passed ? held : failed) += 1;
    if (!a.junit.empty()) junit.end_case(result, wall_s);
    output->print_file_line(std::cout, result, files[i], wall_s);
    std::cout.flush(); // a line per file as it finishes (a batch log shows progress)
    std::vector<Step>().swap(scenarios[i].steps); // done: its steps' memory goes
  }
  if (!a.json) {
    std::cout << fmt::format("{} of {} scenarios held, {} failed{}{}\n", held, files.size(), failed,
                             errors ? fmt::format(", {} bad input", errors) : "",
                             shard_note(shard, shards, begin, end, all.size()));
  }
  if (!a.junit.empty()) {
    for_option("--junit", a.junit, [&] { junit.write(a.junit); });
  }
  // After the runs: bad input found before them stays one line on stderr.
  const std::string note = io::one_task_array_note(a.shard, getenv_ptr);
  if (!note.empty()) std::cerr << "sreh-twin: " << note << "\n";
  return errors > 0 ? 2 : failed > 0 ? 1 : 0;
}

} // namespace sreh::tools
