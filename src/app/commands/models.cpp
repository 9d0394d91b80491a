// `iwb models`: every registered model with its parameter tables (keys, units, bounds, meaning).
#include <fmt/core.h>

#include <memory>
#include <nlohmann/json.hpp>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "models/registry.hpp"

namespace iwb::app {

namespace {

int list_models(bool json) {
  nlohmann::json all = nlohmann::json::array();
  for (const auto& spec : models::model_registry()) {
    nlohmann::json m = {{"name", spec.name},
                        {"summary", spec.summary},
                        {"equations", spec.equations},
                        {"roughness", spec.uses_roughness},
                        {"monotonic_only", spec.declaration.monotonic_only}};
    // A monotonic-only model is refused on cyclic runs and cyclic pile loading; say so up front.
    if (!json)
      fmt::print("{:<11} {}\n{:<11} equations: {}; wall roughness: {}; paths: {}\n", spec.name,
                 spec.summary, "", spec.equations, spec.uses_roughness ? "yes" : "no",
                 spec.declaration.monotonic_only ? "monotonic only" : "monotonic and cyclic");
    for (const auto* table : spec.tables) {
      if (!json) fmt::print("{:<11} [{}]\n", "", table->name);
      for (const auto& p : table->entries) {
        m["parameters"][table->name].push_back(
            {{"key", p.key}, {"unit", p.unit}, {"range", p.range()}, {"doc", p.doc}});
        if (!json)
          fmt::print("{:<13} {:<10} {:<5} {:<16} {}\n", "", p.key, p.unit, p.range(), p.doc);
      }
    }
    if (!json) fmt::print("\n");
    all.push_back(m);
  }
  if (json)
    fmt::print("{}\n", all.dump(2));
  else
    fmt::print(
        "Roughness (interface models): [roughness] scheme = the model's own (sand: \"gutjahr\" | "
        "\"arnold-herle\"; hcc, hce: \"arnold-herle\" | \"stutz-masin\"), and one of kappa_r, R_n "
        "(sand, + log_base), delta_deg. See data/tests/README.md.\n");
  return 0;
}

}  // namespace

void add_models_command(CLI::App& app, CommandList& commands) {
  auto as_json = std::make_shared<bool>(false);
  auto* models = app.add_subcommand("models",
                                    "List the constitutive models, their parameters "
                                    "(keys, units, bounds, meaning) and equations.");
  models->add_flag("--json", *as_json, "machine-readable output");
  commands.add(models, [as_json](const CommandContext&) { return list_models(*as_json); });
}

}  // namespace iwb::app
