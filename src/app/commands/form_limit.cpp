// `iwb form-limit`: an interface model's best fit of every declared parameter to DEM runs, which
// tells a verdict's form from its calibration (comparison/causes/form_limit.hpp).
#include "comparison/causes/form_limit.hpp"

#include <fmt/core.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "calibration/soil_test_judge.hpp"

namespace iwb::app {

namespace {

constexpr const char* kFormLimitHelp =
    "The form limit of an interface model on DEM runs (issue 38): every material parameter with a "
    "declared calibration box (iwb models) and kappa_r and d_s for each wall (R_n, d50), fitted "
    "jointly to the --runs (tau and the free normal quantity, each in units of the cell's seed "
    "scatter, as compare's joint fit; BOBYQA within the boxes, then Levenberg-Marquardt), from the "
    "soil-test set of --params. The --held-out runs are predicted with the result. Every run is "
    "judged on the quantities of interest three ways: the soil-test set predicted (kappa_r from "
    "the wall, d_s 5 d50), the soil-test set with kappa_r and d_s fitted to the run, and the form "
    "limit. With --soil-tests the same unknowns are fitted again over only the sets the soil "
    "tests accept (every objective group's RMS at most --soil-acceptance times the soil-test "
    "set's; COBYLA from the soil-test set and from the free form limit's set), and a quantity the "
    "prediction breaks is put down to the calibration only where that joint set holds it, else to "
    "the form (the note says whether no set holds it or only sets the soil tests refuse). Without "
    "soil tests a break the free form limit holds is \"calibration (unchecked)\". Writes "
    "form_limit.json, form_limit.md (tables), form_limit.toml (the free set, for compare "
    "--params) and form_limit_joint.toml (the joint set); each parameter's move from the "
    "soil-test set in that set's sigmas when a calibration.json sits beside --params. With --free "
    "or --hold-walls only part is fitted: a fit of a candidate's parameters judged on held-out "
    "runs (data/models_beyond/), whose breaks are given no cause.\n"
    "Example: iwb form-limit --runs data/reference/truth2_seeds45/runs/s4_cnl-50 --held-out "
    "data/reference/truth2_seeds45/runs/s5_cnl-50 --model hvwe --params "
    "data/params/truth_grains_epsd2.toml -o runs/form-limit";

struct FormLimitCommand {
  comparison::FormLimitOptions options;
  std::vector<std::string> runs, held_out, soil_tests;
  std::string out, calibration;
};

}  // namespace

void add_form_limit_command(CLI::App& app, CommandList& commands) {
  auto c = std::make_shared<FormLimitCommand>();
  auto* cmd = app.add_subcommand("form-limit", kFormLimitHelp);
  cmd->add_option("--runs", c->runs, "DEM run directories to fit")
      ->required()
      ->check(input_directory());
  cmd->add_option("--held-out", c->held_out, "DEM run directories to predict with the fitted set")
      ->check(input_directory());
  cmd->add_option("--model", c->options.model, "interface model (iwb models)")
      ->capture_default_str();
  cmd->add_option("--params", c->options.params, "the soil-test parameter file (data/params/)")
      ->required()
      ->check(input_file());
  cmd->add_option("--free", c->options.free,
                  "KEY or TABLE.KEY, repeatable: fit only these material parameters, the others "
                  "held at --params (a candidate's own parameters with the soil held, issue 56); "
                  "the result is a fit, not a form limit, and a break it leaves gets no cause");
  cmd->add_flag("--hold-walls", c->options.hold_walls,
                "hold each wall's kappa_r and d_s at the prediction (eq. 5.35, 5 d50) instead of "
                "fitting them: what a prediction on an unseen wall uses; a fit, not a form limit");
  cmd->add_option("--calibration", c->calibration,
                  "the soil-test set's calibration.json, for its sigmas (default: the one beside "
                  "--params, if any)")
      ->check(input_file());
  auto* soil =
      cmd->add_option(
             "--soil-tests", c->soil_tests,
             "soil-test run directories (the calibration's): the sets they accept bound the "
             "joint fit, and each group's RMS with each set is reported")
          ->check(input_directory());
  cmd->add_option("--soil-acceptance", c->options.soil_acceptance,
                  "a set the soil tests accept: every objective group's RMS at most this times "
                  "the soil-test set's")
      ->capture_default_str()
      ->check(number_in(closed(1.0, 100.0)))
      ->needs(soil);
  cmd->add_option("--joint-evaluations", c->options.joint_evaluations,
                  "COBYLA's budget for each pass of the fit with the soil tests (two starts, "
                  "the soil-test set and the free form limit's set, up to 4 passes each, "
                  "restarted while a pass gains 1 %)")
      ->capture_default_str()
      ->check(whole_in(10, 1000000))
      ->needs(soil);
  cmd->add_option("--out,-o", c->out, "output directory")->required()->check(output_directory());
  cmd->add_option("--max-evaluations", c->options.max_evaluations,
                  "BOBYQA's budget before Levenberg-Marquardt finishes")
      ->capture_default_str()
      ->check(whole_in(10, 1000000));
  cmd->add_flag("--force", c->options.force, "replace an earlier form limit in the same directory");
  commands.add(cmd, [c](const CommandContext& context) {
    auto o = c->options;
    for (const auto& r : c->runs) o.fit_runs.push_back(r);
    for (const auto& r : c->held_out) o.held_out.push_back(r);
    o.out = c->out;
    o.calibration = c->calibration;
    o.soil_tests = calibration::soil_test_judge(
        c->soil_tests);  // read now: a bad test is refused before the fit
    o.soil_tests_about = fmt::format("{} soil tests", c->soil_tests.size());
    o.command_line = context.command_line;
    o.progress = [](const std::string& line) {
      fmt::print("{}\n", line);
      std::fflush(stdout);
    };
    const auto j = comparison::run_form_limit(o);
    fmt::print("{}: RMS {:.4g} scatter units after {} evaluations ({:.0f} s)\n",
               o.restricted() ? "fit" : "form limit", j["rms_scaled"].get<double>(),
               j["evaluations"].get<int>(), j["seconds"].get<double>());
    if (j.contains("joint"))
      fmt::print(
          "with the soil tests: RMS {:.4g} scatter units after {} evaluations ({:.0f} s); the "
          "soil tests {} it\n",
          j["joint"]["rms_scaled"].get<double>(), j["joint"]["evaluations"].get<int>(),
          j["joint"]["seconds"].get<double>(),
          j["joint"]["accepted"].get<bool>() ? "accept" : "refuse");
    fmt::print("-> {}\n", (o.out / "form_limit.md").string());
    return 0;
  });
}

}  // namespace iwb::app
