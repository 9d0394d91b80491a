// `iwb plan SCENE`: the cheapest DEM setting and the simplest continuum model that meet a scene's
// requirements (tradeoff/plan.hpp, tradeoff/plan_parameters.hpp).
#include <fmt/core.h>
#include <fmt/ranges.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "tradeoff/plan_parameters.hpp"

namespace iwb::app {

namespace fs = std::filesystem;

namespace {

struct PlanCommand {
  std::string scene, tradeoff, out, parameter_uncertainty = "fit";
  std::vector<std::string> params, params_for;
  int samples = 200;
};

CLI::App* add_plan_options(CLI::App& app, PlanCommand& c) {
  auto* plan = app.add_subcommand(
      "plan",
      "Choose from a scene's [requirements] (data/scenes/README.md: a relative tolerance per "
      "quantity of "
      "interest, or \"not needed\") and its tradeoff (run `iwb tradeoff` first): the cheapest DEM "
      "setting whose "
      "errors plus the seed noise floor meet every tolerance, and the simplest interface model (" +
          std::string(kInterfaceModelLadder) +
          ") whose "
          "global uncertainty meets them: each model calibrated to the scene's own runs (the base "
          "seeds: kappa_r and "
          "d_s, and the material of models without a soil-test calibration), replayed along their "
          "path, its miss of "
          "their seed mean and the spread its parameters' uncertainty gives "
          "(--parameter-uncertainty) "
          "in quadrature, "
          "per quantity (seed eq. 4.4, ERRATA 16). Prints the decision and which setting or model "
          "failed which "
          "tolerance by how much; writes plan.json.\n"
          "It needs the tradeoff's run directories (the base runs are replayed), not only its "
          "tables.\n"
          "Example: iwb plan data/scenes/default.toml --tradeoff runs/tradeoff-default");
  plan->add_option("scene", c.scene, "scene TOML file with a [requirements] table")
      ->required()
      ->check(input_file());
  plan->add_option(
      "--tradeoff", c.tradeoff,
      "tradeoff directory (default runs/tradeoff-<scene stem>)");  // run_plan says what to run
  plan->add_option(
          "--params", c.params,
          "parameter files of the continuum models: the first for every model (default: "
          "the set iwb validate chooses from those built into iwb: dem_default_grains.toml "
          "for the default scene's grains, else phi_c closest to the reference's residual "
          "friction); further files are other calibrations of the same grains (a point of "
          "`iwb calibrate --pareto` that weights the dilatancy, say), tried after the "
          "first for each model calibrated from soil tests, so that the plan can "
          "recommend a model with the calibration that meets the tolerances, or say by "
          "how much the closest misses")
      ->check(input_file());
  plan->add_option("--params-for", c.params_for,
                   "MODEL=FILE: that model's own parameter set, tried instead of --params (repeat; "
                   "for the candidates whose parameters are fitted to DEM walls, e.g. hvwe-rd="
                   "data/models_beyond/hvwe_rd_held_walls/form_limit.toml)");
  plan->add_option("--parameter-uncertainty", c.parameter_uncertainty,
                   "fit (default): each calibrated quantity spread by its own sigma from the fit "
                   "to these runs (the "
                   "parameters as this scene pins them down); seed: the COVs of the seed's Table "
                   "4.8 and Appendix A "
                   "about the calibrated values (parameters as a laboratory would know them)")
      ->check(CLI::IsMember({"fit", "seed"}));
  plan->add_option("--samples", c.samples, "Latin hypercube parameter samples per candidate model")
      ->check(whole_in(10, 100000));
  plan->add_option("--out,-o", c.out, "where plan.json goes (default: the tradeoff directory)")
      ->check(output_directory());
  return plan;
}

int run_plan_command(const PlanCommand& c, const std::string& cl) {
  tradeoff::PlanOptions opt{c.scene, c.tradeoff, {}, "", c.out, cl};
  opt.spread = c.parameter_uncertainty == "seed" ? assessment::ParameterSpread::kSeedCovs
                                                 : assessment::ParameterSpread::kFitSigmas;
  opt.samples = c.samples;
  opt.params_for = c.params_for;
  const auto plan = tradeoff::run_plan_from_files(opt, c.params);
  const fs::path written =
      opt.out.empty() ? fs::path(plan["tradeoff"].get<std::string>()).parent_path() : opt.out;
  fmt::print(
      "{}parameters: {} ({}){}\n-> {}\n", tradeoff::plan_text(plan),
      plan["params"].get<std::string>(), plan["params_why"].get<std::string>(),
      c.params_for.empty() ? "" : fmt::format("; own sets: {}", fmt::join(c.params_for, ", ")),
      (written / "plan.json").string());
  return 0;
}

}  // namespace

void add_plan_command(CLI::App& app, CommandList& commands) {
  auto c = std::make_shared<PlanCommand>();
  auto* plan = add_plan_options(app, *c);
  commands.add(plan, [c](const CommandContext& context) {
    return run_plan_command(*c, context.command_line);
  });
}

}  // namespace iwb::app
