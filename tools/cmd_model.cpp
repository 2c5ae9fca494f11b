// `sreh-twin model show [--json] [--model FILE]` (issue 25): the model card
// in force, every physical constant of the module with its value, unit,
// source and production range. The YAML is the format `--model` reads, so
// a user copies it, keeps the lines they change and passes it back.
#include <iostream>
#include <memory>

#include "scenarios/model_card_json.hpp"
#include "tools/command.hpp"
#include "twin/model_card.hpp"

namespace sreh::tools {
namespace {

struct ModelArgs {
  bool json = false;
  std::string model;
};

int show_command(const ModelArgs& a) {
  ModelCard card = default_model_card();
  if (!a.model.empty()) {
    try {
      card = apply_model_file(card, a.model);
    } catch (const ModelCardError& e) {
      throw InputError(std::string("--model: ") + e.what());
    }
  }
  if (a.json) std::cout << model_card_json(card).dump(2) << "\n";
  else std::cout << model_card_yaml(card);
  return 0;
}

} // namespace

SREH_REGISTER_COMMAND(55, [](CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ModelArgs>();
  CLI::App* model = app.add_subcommand("model", "The module's model card: its physical constants (models/sreh50-model.yaml)");
  model->require_subcommand(1);
  CLI::App* show = model->add_subcommand(
      "show", "Print the model card in force as YAML (the format --model reads) or JSON: value, unit, source, range");
  show->add_flag("--json", args->json, "Print {\"constants\": {NAME: {value, unit, source, range}}}");
  show->add_option("--model", args->model, "Apply this model file's overrides first (as run/size/sweep/serve do)");
  show->callback([args, &exit_code] { exit_code = show_command(*args); });
});

} // namespace sreh::tools
