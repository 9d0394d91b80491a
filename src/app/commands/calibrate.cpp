// `iwb calibrate SOILTEST_DIR...`: hypoplastic parameters fitted to soil tests (calibration/).
#include <fmt/core.h>

#include <cmath>
#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "calibration/calibration_run.hpp"

namespace iwb::app {

namespace {

struct CalibrateCommand {
  std::vector<std::string> runs, held_out, weights, fixed;
  std::string model = "vw3d", table, held_params, params_out, pareto;
  int points = 5;
};

constexpr const char* kCalibrateHelp =
    "Calibrate the hypoplastic parameters (phi_c, h_s, n, e_c0, e_d0, e_i0, alpha, beta) from "
    "soil-test run directories, in the order of Herle & Gudehus (1999): phi_c from the critical "
    "state of the simple-shear tests, h_s and n from the oedometric curves, e_c0 from the critical "
    "void ratios, alpha and beta from peak, dilatancy and stiffness, then all jointly (NLopt "
    "BOBYQA "
    "within each parameter's declared calibration box, finished by Levenberg-Marquardt). Prints "
    "per "
    "test the RMSE in its units, per objective group its RMS, and per parameter the estimate and "
    "its one-sigma (Gauss-Newton) uncertainty; parameters the tests cannot identify are flagged, "
    "e_d0 and e_i0 then set from e_c0 by the usual factors.\n"
    "The objective is three groups of residuals, each (model - measured) / scatter: 'oedometer' "
    "(e-paths), 'shear' (simple-shear tau and e, or tau and sigma_n under CV) and 'dilatancy' (per "
    "CNL shear test the peak rate d eps_n/d gamma and the total dilation). The scatter is declared "
    "(0.01 sigma0 for stresses, 0.002 for e, 0.01 for a rate) or, for a test given with several "
    "seeds, measured across them when larger. --weight GROUP=W multiplies a group's squares (1: "
    "each residual one measurement); --pareto A,B traces the front between two groups, each point "
    "a whole calibration (src/calibration/README.md).\n"
    "Writes the parameter file and calibration.json next to it; with --pareto also pareto.csv, "
    "pareto.json, pareto.svg and pareto/point-K.toml. While it fits, a line every 10 s on stderr "
    "says where it is (the recipe's stage or the joint fit, phase k of n, evaluations, RMS, "
    "seconds); with --pareto, a line per point with an ETA. The result goes to stdout.\n"
    "Examples:\n"
    "  iwb calibrate runs/soil/* -o data/params/calibrated_sand.toml\n"
    "  iwb calibrate runs/soil/* --weight dilatancy=10 -o dilatant.toml\n"
    "  iwb calibrate runs/soil/* --pareto oedometer,dilatancy --points 7 -o front/sand.toml\n"
    "The intergranular strain (R, m_R, m_T, beta_r, chi) of vw3d-igs is fitted to cyclic "
    "simple-shear tests with the hypoplastic set held: --model vw3d-igs --table "
    "intergranular_strain --params SET.toml. Its fit starts at the middle of each calibration box "
    "(no staged recipe); the soil-test model starts with delta along the vertical compression "
    "that prepared the specimen, so the first shear is a 90 deg turn (m_T), a reversal 180 deg "
    "(m_R). The parameter file written holds the held tables too:\n"
    "  iwb calibrate runs/cyclic/* --model vw3d-igs --table intergranular_strain --params "
    "data/params/truth_grains_epsd2.toml -o igs.toml";

CLI::App* add_calibrate_options(CLI::App& app, CalibrateCommand& c) {
  auto* calibrate = app.add_subcommand("calibrate", kCalibrateHelp);
  calibrate->add_option("runs", c.runs, "soil-test run directories")
      ->required()
      ->check(input_directory());
  calibrate
      ->add_option(
          "--held-out", c.held_out,
          "soil-test run directories left out of the fit and predicted with the calibrated set "
          "(RMSE and end values printed and in calibration.json)")
      ->check(input_directory());
  calibrate->add_option("--model", c.model, "continuum model whose parameters are fitted")
      ->check(CLI::IsMember({"vw3d", "vw3d-igs"}))
      ->capture_default_str();
  calibrate
      ->add_option("--table", c.table,
                   "the parameter table fitted (default: the model's first table with "
                   "calibration boxes, [hypoplastic]); intergranular_strain for vw3d-igs")
      ->check(CLI::IsMember({"hypoplastic", "intergranular_strain"}));
  calibrate
      ->add_option("--params", c.held_params,
                   "parameter file whose other tables are held while --table is fitted")
      ->needs("--table")
      ->check(input_file());
  calibrate->add_option("--weight", c.weights,
                        "GROUP=W, repeatable: weight of an objective group (oedometer, shear, "
                        "dilatancy; default 1 each, 0 leaves a group out)");
  calibrate->add_option("--fix", c.fixed,
                        "KEY=VALUE, repeatable: hold a parameter at a value instead of fitting "
                        "it (phi_c_deg=30)");
  auto* pareto = calibrate->add_option(
      "--pareto", c.pareto,
      "A,B: trace the Pareto front between two objective groups (each point a "
      "calibration that gives A the share s of the pair's weight)");
  calibrate
      ->add_option("--points", c.points,
                   "points of the front besides the one at the given weights (with --pareto)")
      ->needs(pareto)
      ->check(whole_in(calibration::kMinParetoPoints, calibration::kMaxParetoPoints))
      ->capture_default_str();
  calibrate->add_option("--out,-o", c.params_out, "parameter file to write (data/params format)")
      ->required()
      ->check(output_file());
  return calibrate;
}

void print_test_rows(const std::vector<calibration::TestFit>& fits, bool with_ends,
                     std::FILE* out = stdout) {
  for (const auto& t : fits) {
    fmt::print(out, "{:<40} {:<12}", t.name, t.test + (t.boundary.empty() ? "" : " " + t.boundary));
    for (const auto& ch : t.rmse)
      if (with_ends)
        fmt::print(out, " {} {:.3g} ({:.4g} / {:.4g})", ch.column, ch.rmse, ch.end_model,
                   ch.end_measured);
      else
        fmt::print(out, " {} {:.3g}", ch.column, ch.rmse);
    if (std::isfinite(t.peak_rate_model))
      fmt::print(out, " peak rate {:.3f} ({:.3f})", t.peak_rate_model, t.peak_rate_measured);
    fmt::print(out, "{}\n", t.status == "complete" ? "" : "  (" + t.status + ")");
  }
}

// To stderr when the calibration is refused (stdout stays empty for bad input).
void print_result(const calibration::CalibrationResult& r, std::FILE* out = stdout) {
  for (const auto& n : r.notes) fmt::print(out, "{}\n", n);
  fmt::print(out, "\n{:<40} {:<12} {}\n", "test", "",
             "RMSE (peak dilatancy rate: model (measured))");
  print_test_rows(r.tests, false, out);
  fmt::print(out, "\n{:<10} {:>8} {:>10} {:>12}  {}\n", "objective", "weight", "residuals", "RMS",
             "rows not reached");
  for (const auto& g : r.objectives)
    fmt::print(out, "{:<10} {:>8.4g} {:>10} {:>12.4g}  {}\n", calibration::to_string(g.group),
               g.weight, g.residuals, g.rms, g.unreached);
  // sigma: from this fit's residuals; at scatter: had the residuals the declared scatter (what
  // decides "identified"; the two differ most for noise-free synthetic targets)
  const auto text = [](double v) {
    return std::isfinite(v) ? fmt::format("{:.3g}", v) : std::string("undefined");
  };
  fmt::print(out, "\n{:<10} {:>12} {:>12} {:>12}  {}\n", "parameter", "estimate", "sigma",
             "at scatter", "how");
  for (const auto& p : r.parameters)
    fmt::print(
        out, "{:<10} {:>12.8g} {:>12} {:>12}  {}{}\n", p.key, p.value, text(p.sigma),
        text(p.sigma_at_scatter), p.how,
        p.at_bound.empty() || p.at_bound == "order" ? "" : "; ON ITS " + p.at_bound + " BOUND");
}

void print_front(const calibration::ParetoFront& f) {
  fmt::print("\nPareto front, {} against {} ({} points, {:.0f} s):\n{:>9} {:>10} {:>10}  {}\n",
             calibration::to_string(f.b), calibration::to_string(f.a), f.points.size(), f.seconds,
             "share", calibration::to_string(f.a), calibration::to_string(f.b), "on a bound");
  for (const auto& p : f.points) {
    std::string bounds;
    for (const auto& e : p.result.parameters)
      if (!e.at_bound.empty())
        bounds += fmt::format("{}{} ({})", bounds.empty() ? "" : ", ", e.key, e.at_bound);
    fmt::print("{:>9.6g} {:>10.4g} {:>10.4g}  {}{}\n", p.share, p.rms_a, p.rms_b, bounds,
               p.given ? "  <- the given weights" : "");
  }
  for (const auto& n : f.notes) fmt::print("note: {}\n", n);
}

// The fit is printed before its files are written, so that a refused write follows it.
int run_calibrate(const CalibrateCommand& c, const std::string& command_line) {
  const calibration::CalibrationRequest request{c.runs,   c.held_out,    c.params_out, c.model,
                                                c.table,  c.held_params, c.weights,    c.fixed,
                                                c.pareto, c.points};
  const auto run = [&] {
    try {
      // progress on stderr: stdout is the result (make.sh files keep it as calibrate.txt)
      return calibration::run_calibration(request, [](const std::string& line) {
        fmt::print(stderr, "{}\n", line);
        std::fflush(stderr);  // a front takes minutes
      });
    } catch (const calibration::NothingIdentified& e) {
      print_result(e.fit, stderr);  // what the fit found says why (stdout stays empty)
      throw;
    }
  }();
  const auto& result = run.result;
  const auto& front = run.front;
  print_result(result);
  if (!result.held_out.empty()) fmt::print("\nheld out, predicted: RMSE (end: model / measured)\n");
  print_test_rows(result.held_out, true);
  if (front) print_front(*front);
  calibration::write_calibration(run, c.params_out, command_line);
  fmt::print("\n{} evaluations, {:.1f} s -> {} and {}{}\n",
             front ? front->evaluations : result.evaluations,
             front ? front->seconds : result.seconds, c.params_out,
             (std::filesystem::path(c.params_out).parent_path() / "calibration.json").string(),
             front ? " and the front (pareto.csv, pareto.json, pareto.svg, pareto/)" : "");
  return 0;
}

}  // namespace

void add_calibrate_command(CLI::App& app, CommandList& commands) {
  auto c = std::make_shared<CalibrateCommand>();
  auto* calibrate = add_calibrate_options(app, *c);
  commands.add(calibrate, [c](const CommandContext& context) {
    return run_calibrate(*c, context.command_line);
  });
}

}  // namespace iwb::app
