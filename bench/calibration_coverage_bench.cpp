// Coverage of the calibration's 95 % intervals (issue 36): truths drawn
// from the card's ranges, the identification plan run on each at several
// loads, with and without +-1 count of noise on the logged position, the
// log fitted from the card as `calibrate` does, and per constant: does its
// interval contain the truth, is it flagged identified, how far off is it.
// One CSV row per constant and fit, flushed as it goes (a partial run keeps
// what it measured); bench/calibration_coverage.py summarises a CSV.
// docs/calibration.md "Coverage". Run it with bench/calibration_coverage.sh.
//
//   calibration_coverage_bench [--truths N] [--first K] [--loads 0,5000,15000]
//     [--noise 0,1] [--moves I,J,...] [--starts S] [--bootstrap B] [--threads T] [--csv FILE]
// --moves: the plan's moves to keep, by index (0..17, in the plan's order;
// default all), with the plan's parameter sets and first hold.
#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "calibration/fit.hpp"
#include "tests/calibration/calibration_rig.hpp"

namespace {

using namespace sreh;

constexpr const char* kUsage =
    "usage: calibration_coverage_bench [--truths N] [--first K] [--loads 0,5000,15000] [--noise 0,1]\n"
    "  [--moves I,J,...] [--starts S] [--bootstrap B] [--threads T] [--csv FILE]\n";

std::vector<double> numbers(const char* text) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) v.push_back(std::stod(item));
  return v;
}

double cpu_s() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// Truth k: every fitted constant uniform over its card range, from a seed
// of k alone (the same truths at every load and noise).
ModelCard truth_card(int k, const std::vector<std::string>& names) {
  ModelCard card = default_model_card();
  std::mt19937_64 rng(0x36c0ffeeULL + static_cast<unsigned>(k));
  for (const std::string& name : names) {
    for (ModelConstant& c : card.constants) {
      if (c.name == name) c.value = std::uniform_real_distribution<double>(c.range_lo, c.range_hi)(rng);
    }
  }
  return card;
}

} // namespace

int main(int argc, char** argv) {
  int truths = 20, first = 0, starts = 3, threads = 2, bootstrap = kDefaultBootstrap;
  std::vector<double> moves;
  std::string moves_text = "all";
  std::vector<double> loads{0, 5000, 15000}, noises{0, 1};
  std::vector<std::string> names = default_fit_names();
  const char* csv_path = nullptr;
  for (int i = 1; i < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h" || i + 1 == argc) {
      // Every option takes a value; a lone one (or --help) must not start a two-hour run.
      const bool help = a == "--help" || a == "-h";
      if (!help) std::fprintf(stderr, "calibration_coverage_bench: %s needs a value\n", a.c_str());
      std::fputs(kUsage, help ? stdout : stderr);
      return help ? 0 : 2;
    }
    if (a == "--truths") truths = std::atoi(argv[i + 1]);
    else if (a == "--first") first = std::atoi(argv[i + 1]);
    else if (a == "--loads") loads = numbers(argv[i + 1]);
    else if (a == "--noise") noises = numbers(argv[i + 1]);
    else if (a == "--moves") {
      moves = numbers(argv[i + 1]);
      moves_text = argv[i + 1];
      for (char& ch : moves_text) {
        if (ch == ',') ch = ' ';
      }
    }
    else if (a == "--starts") starts = std::atoi(argv[i + 1]);
    else if (a == "--threads") threads = std::atoi(argv[i + 1]);
    else if (a == "--bootstrap") bootstrap = std::atoi(argv[i + 1]);
    else if (a == "--csv") csv_path = argv[i + 1];
    else {
      std::fprintf(stderr, "calibration_coverage_bench: unknown option %s\n", argv[i]);
      return 2;
    }
  }
  FILE* csv = csv_path ? std::fopen(csv_path, "a") : stdout;
  if (!csv) {
    std::fprintf(stderr, "calibration_coverage_bench: cannot write %s\n", csv_path);
    return 2;
  }
  if (!csv_path || std::ftell(csv) == 0) {
    std::fprintf(csv, "load_gcm2,noise_counts,truth,moves,constant,truth_value,fitted,ci95_lo,ci95_hi,covered,identified,"
                      "error_pct,note,likelihood_lo,likelihood_hi,likelihood_covered,bootstrap_lo,bootstrap_hi,bootstrap_covered,"
                      "refits,rms_deg,floor_deg,adequate,iterations,replays,cpu_s\n");
  }
  // Truth by truth, each at every load and noise: a run stopped early has
  // its truths complete.
  for (int k = first; k < first + truths; ++k) {
    for (const double load : loads) {
      const Scenario plan =
          moves.empty() ? test::plan_scenario(load) : test::plan_moves(load, std::vector<int>(moves.begin(), moves.end()));
      for (const double noise : noises) {
        const ModelCard truth = truth_card(k, names);
        const double cpu0 = cpu_s();
        FitCase c;
        c.log = test::record_log(plan, truth, noise > 0 ? std::optional<unsigned>(1000u + static_cast<unsigned>(k))
                                                        : std::nullopt);
        c.setup = replay_setup(c.log, InertiaLoad{load}, &plan);
        FitOptions options;
        options.names = names;
        options.starts = starts;
        options.threads = threads;
        options.bootstrap = bootstrap;
        const FitResult fit = fit_model({c}, default_model_card(), options);
        const double cpu = cpu_s() - cpu0;
        for (const FittedConstant& f : fit.constants) {
          const double t = truth.find(f.name)->value;
          std::string note = f.note;
          for (char& ch : note) {
            if (ch == ',') ch = ';';
          }
          std::string refits; // space-separated: one CSV field
          for (const double r : f.refits) refits += (refits.empty() ? "" : " ") + fmt::format("{:.6g}", r);
          std::fprintf(csv,
                       "%g,%g,%d,%s,%s,%.6g,%.6g,%.6g,%.6g,%d,%d,%.2f,%s,%.6g,%.6g,%d,%.6g,%.6g,%d,%s,%.6f,%.6f,%d,%d,%zu,%.1f\n",
                       load, noise, k, moves_text.c_str(), f.name.c_str(), t, f.value, f.ci95_lo, f.ci95_hi,
                       f.ci95_lo <= t && t <= f.ci95_hi ? 1 : 0, f.identified ? 1 : 0, 100 * (f.value / t - 1),
                       note.c_str(), f.likelihood_lo, f.likelihood_hi, f.likelihood_lo <= t && t <= f.likelihood_hi ? 1 : 0,
                       f.bootstrap_lo, f.bootstrap_hi, f.bootstrap_lo <= t && t <= f.bootstrap_hi ? 1 : 0, refits.c_str(),
                       fit.rms_residual_deg, fit.floor_rms_deg, fit.adequate ? 1 : 0, fit.iterations,
                       fit.replays, cpu);
        }
        std::fflush(csv);
        std::fprintf(stderr, "load %g noise %g truth %d: %d iterations, %zu replays, %.1f s CPU\n", load, noise, k,
                     fit.iterations, fit.replays, cpu);
      }
    }
  }
  if (csv_path) std::fclose(csv);
  return 0;
}
