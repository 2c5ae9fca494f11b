// `sreh-twin load show FILE [--json] [--picture PNG]` (issue 28): a load as
// the twin builds it, in the figures a machine builder sizes with: mass,
// inertia about the axis, centre of mass, the largest gravity torque for
// each mounting, the ratio to the module's own inertia and each part's
// share; --picture renders it on the module from above and from the side,
// with the axis and the centre of mass marked.
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "device_logic/units.hpp"
#include "io/output_path.hpp"
#include "scenarios/load_file.hpp"
#include "tools/command.hpp"
#include "twin/load_builder.hpp"
#include "twin/load_figures.hpp"
#include "twin/module_model.hpp"

#ifdef SREH_WITH_RENDER
#include "renders/load_picture.hpp"
#endif

namespace sreh::tools {
namespace {

struct LoadArgs {
  std::string file;
  bool json = false;
  std::string picture;
};

struct Shown {
  LoadSpec load;
  std::optional<double> tilt_deg; // the file's mounting:
  LoadFigures figures;
};

Shown read(const std::string& file) {
  Shown s;
  try {
    if (file.size() > 4 && file.compare(file.size() - 4, 4, ".xml") == 0) {
      s.load = MjcfLoad{file}; // an MJCF file alone, as `load: {mjcf: FILE}`
    } else {
      LoadFileContents c = parse_load_file(file);
      s.load = std::move(c.load);
      s.tilt_deg = c.mounting_tilt_deg;
    }
    s.figures = load_figures(s.load);
  } catch (const ScenarioError& e) {
    throw InputError(e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  return s;
}

double ratio(const LoadFigures& f) { return f.inertia_kgm2 / kInternalInertia_kgm2; }

nlohmann::json as_json(const std::string& file, const Shown& s) {
  const LoadFigures& f = s.figures;
  nlohmann::json j;
  j["file"] = file;
  j["mass_kg"] = f.mass_kg;
  j["inertia_gcm2"] = kgm2_to_gcm2(f.inertia_kgm2);
  j["inertia_kgm2"] = f.inertia_kgm2;
  j["com_m"] = f.com_m;
  j["com_radius_m"] = f.com_radius_m;
  j["gravity_torque_max_Nm"] = {{"vertical", gravity_torque_max_Nm(f, 0)}, {"horizontal", gravity_torque_max_Nm(f, 90)}};
  if (s.tilt_deg) {
    j["mounting_tilt_deg"] = *s.tilt_deg;
    j["gravity_torque_max_Nm"]["mounting"] = gravity_torque_max_Nm(f, *s.tilt_deg);
  }
  j["inertia_ratio"] = ratio(f);
  j["j_intern_gcm2"] = kgm2_to_gcm2(kInternalInertia_kgm2);
  j["limit_gcm2"] = max_load_gcm2();
  nlohmann::json parts = nlohmann::json::array();
  for (const PartFigures& p : f.parts) {
    parts.push_back({{"shape", p.shape}, {"name", p.name}, {"mass_kg", p.mass_kg}, {"inertia_gcm2", kgm2_to_gcm2(p.inertia_kgm2)},
                     {"share", f.inertia_kgm2 > 0 ? p.inertia_kgm2 / f.inertia_kgm2 : 0.0}, {"com_m", p.com_m}});
  }
  j["parts"] = parts;
  return j;
}

void print_text(const std::string& file, const Shown& s) {
  const LoadFigures& f = s.figures;
  auto mm = [](double m) { return fmt::format("{:.1f}", m * 1e3); };
  std::cout << "load: " << file << "\n";
  std::cout << fmt::format("  mass            {:.3f} kg\n", f.mass_kg);
  std::cout << fmt::format("  inertia         {} g cm^2 ({:.4g} kg m^2) about the axis; the module carries up to {:.0f}\n",
                           round_gcm2(kgm2_to_gcm2(f.inertia_kgm2)), f.inertia_kgm2, max_load_gcm2());
  std::cout << fmt::format("  ratio           J_load / J_intern = {:.2f} (J_intern {:.0f} g cm^2, manual 3.5.4)\n", ratio(f),
                           kgm2_to_gcm2(kInternalInertia_kgm2));
  std::cout << fmt::format("  centre of mass  [{}, {}, {}] mm, {} mm from the axis\n", mm(f.com_m[0]), mm(f.com_m[1]),
                           mm(f.com_m[2]), mm(f.com_radius_m));
  std::cout << fmt::format("  gravity torque  at most {:.3f} N m vertical, {:.3f} N m horizontal", gravity_torque_max_Nm(f, 0),
                           gravity_torque_max_Nm(f, 90));
  if (s.tilt_deg) std::cout << fmt::format(", {:.3f} N m as mounted (tilt {:g} deg)", gravity_torque_max_Nm(f, *s.tilt_deg), *s.tilt_deg);
  std::cout << "\n  parts:\n";
  for (std::size_t k = 0; k < f.parts.size(); ++k) {
    const PartFigures& p = f.parts[k];
    std::cout << fmt::format("    {:>2} {:<8} {:>7.3f} kg {:>9} g cm^2 {:>5.1f} %  centre [{}, {}, {}] mm{}\n", k + 1, p.shape,
                             p.mass_kg, round_gcm2(kgm2_to_gcm2(p.inertia_kgm2)),
                             f.inertia_kgm2 > 0 ? 100 * p.inertia_kgm2 / f.inertia_kgm2 : 0.0, mm(p.com_m[0]), mm(p.com_m[1]),
                             mm(p.com_m[2]), p.name.empty() ? "" : "  " + p.name);
  }
}

int show_command(const LoadArgs& a) {
  io::check_outputs({{"--picture", a.picture, io::OutputKind::File}}, {a.file});
  const Shown s = read(a.file);
  if (!a.picture.empty()) {
#ifdef SREH_WITH_RENDER
    write_load_picture(s.load, s.figures, a.picture);
#else
    throw InputError("--picture: this sreh-twin was built without rendering (-DSREH_WITH_RENDER=OFF)");
#endif
  }
  if (a.json) std::cout << as_json(a.file, s).dump(2) << "\n";
  else print_text(a.file, s);
  if (!a.json && !a.picture.empty()) std::cout << "wrote " << a.picture << "\n"; // issue 39: a success line per file written
  return 0;
}

} // namespace

SREH_REGISTER_COMMAND(57, [](CLI::App& app, int& exit_code) {
  auto args = std::make_shared<LoadArgs>();
  CLI::App* load = app.add_subcommand("load", "Loads: what the twin builds from a load file (issue 28)");
  load->require_subcommand(1);
  CLI::App* show = load->add_subcommand(
      "show", "Mass, inertia about the axis, centre of mass, gravity torque, inertia ratio and each part's share of a load file");
  show->add_option("FILE", args->file, "A load file (YAML with load:, or a scenario) or an MJCF .xml")->required();
  show->add_flag("--json", args->json, "Print one JSON object: mass_kg, inertia_gcm2, com_m, gravity_torque_max_Nm, parts, ...");
  show->add_option("--picture", args->picture, "Render the load on the module from above and from the side into this PNG");
  show->callback([args, &exit_code] { exit_code = show_command(*args); });
});

} // namespace sreh::tools
