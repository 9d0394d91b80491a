// `iwb column PARAMS --e0 X`: the micro-polar hypoplastic column (src/column/README.md).
#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"
#include "column/column_output.hpp"
#include "column/column_scene.hpp"
#include "common/errors.hpp"
#include "io/parameter_file.hpp"

namespace iwb::app {

namespace {

struct ColumnOptions {
  std::string params, out, scene, bc = "CNL", wall_rotation = "free";
  std::vector<std::string> dem;
  double height_d50 = 14.0, d50_mm = 2.0, elements_per_d50 = 4.0, e0 = 0.0, sigma_kPa = 50.0;
  double stiffness = 0.0, wall_friction = std::numeric_limits<double>::infinity();
  double imperfection = 0.0, travel_mm = 10.0;
  int increments = 1000;
  bool plain = false, force = false;
};

// The start: --e0, else the DEM runs' mean void ratio at the start of shear.
double start_e0(const ColumnOptions& o) {
  if (o.e0 > 0.0) return o.e0;
  if (o.dem.empty())
    throw InputError(
        "--e0: the void ratio at the start of shear is needed (or --dem RUN_DIR..., "
        "whose specimens' mean at the start is taken)");
  return column::start_void_ratio({o.dem.begin(), o.dem.end()});
}

column::ColumnSpec column_spec(const ColumnOptions& o, const CLI::App& command) {
  const auto tables = io::load_parameter_file(o.params);
  const auto it = tables.find("hypoplastic");
  if (it == tables.end())
    throw InputError(
        fmt::format("{}: no [hypoplastic] table (the column reads von "
                    "Wolffersdorff's set, e.g. data/params/truth_grains_epsd2.toml)",
                    o.params));
  if (o.bc != "CNS") refuse_given(command, {"--stiffness"}, "applies only to --bc CNS");
  if (o.plain) refuse_given(command, {"--wall-rotation"}, "a plain column has no rotations");
  if (!o.scene.empty())
    refuse_given(command,
                 {"--sigma", "--bc", "--stiffness", "--height-d50", "--d50", "--travel",
                  "--wall-friction", "--wall-rotation"},
                 "--scene gives it (the scene's boundary, geometry, travel and wall)");
  column::ColumnSpec s;
  s.soil = models::HypoplasticParameters::from(it->second, o.params + " [hypoplastic]");
  s.e0 = start_e0(o);
  s.polar = !o.plain;
  s.imperfection = o.imperfection;
  s.increments = o.increments;
  if (!o.scene.empty()) return column::on_scene(s, dem::load_scene(o.scene), o.elements_per_d50);
  s.d50_mm = o.d50_mm;
  s.height_mm = o.height_d50 * o.d50_mm;
  s.elements = std::max(2, int(std::lround(o.height_d50 * o.elements_per_d50)));
  s.sigma_n0_kPa = o.sigma_kPa;
  s.top = o.bc == "CNS" ? column::TopBoundary::kCNS
                        : (o.bc == "CV" ? column::TopBoundary::kCV : column::TopBoundary::kCNL);
  s.stiffness_kPa_per_mm = o.stiffness;
  s.wall_rotation =
      o.wall_rotation == "free" ? column::WallRotation::kFree : column::WallRotation::kFixed;
  s.wall_friction = o.wall_friction;
  s.travel_mm = o.travel_mm;
  return s;
}

int run_column_command(const ColumnOptions& o, const CommandContext& context,
                       const CLI::App& command) {
  auto spec = column_spec(o, command);
  // set beside DEM runs, the column's profiles are taken where theirs are
  if (!o.dem.empty()) spec.profile_at_mm = column::profile_windows(o.dem.front(), spec.travel_mm);
  const auto dir =
      o.out.empty() ? std::filesystem::path("runs") / "column" : std::filesystem::path(o.out);
  nlohmann::json inputs = {{"params", o.params}, {"command_line", context.command_line}};
  // the DEM runs the column is for, relative to its directory so that a committed pair moves
  // together; `iwb report` sets their profiles beside the column's
  nlohmann::json dem = nlohmann::json::array();
  for (const auto& d : o.dem)
    dem.push_back(
        std::filesystem::relative(std::filesystem::absolute(d), std::filesystem::absolute(dir))
            .generic_string());
  const auto r = column::run_column_into(spec, dir, o.force, inputs, dem, increment_progress());
  const auto& end = r.rows.back();
  const auto band = column::band_widths(r.profiles.back());
  fmt::print(
      "{} at u = {:.3g} mm: tau {:.4g} kPa, sigma_n {:.4g} kPa, u_n {:.4g} mm; band {:.3g} "
      "d50 (FWHM of the shear rate) -> {}\n",
      r.status, end.u_mm, end.tau_kPa, end.sigma_n_kPa, end.u_n_mm, band.fwhm_d50, dir.string());
  return r.status == "complete" ? 0 : 1;
}

}  // namespace

void add_column_command(CLI::App& app, CommandList& commands) {
  auto o = std::make_shared<ColumnOptions>();
  auto* column = app.add_subcommand(
      "column",
      "The band resolved: a column of micro-polar hypoplastic soil (von Wolffersdorff's set with "
      "couple stresses and grain rotations, the mean grain diameter d50 as its length) sheared by "
      "a wall below a clamped plate under CNL, CNS or CV, in linear elements over the height, "
      "solved implicitly increment by increment. Writes timeseries.csv (tau, sigma_n, u_n and "
      "slip along the wall's travel), profiles.csv (velocity, grain spin, shear rate, void "
      "ratio, stresses and couple stress over the height at the ends of five windows, or at the "
      "first --dem run's windows, as a DEM run's profiles.csv), band.csv (the band's width along "
      "the travel) and manifest.json "
      "(src/column/README.md).\n\nExample: iwb column data/params/truth_grains_epsd2.toml "
      "--e0 0.64 -o runs/column\n         iwb column data/params/truth_grains_epsd2.toml --scene "
      "data/convergence/truth_clamped/scenes/s1.toml --dem "
      "data/convergence/truth_clamped/runs/s{1,2} -o runs/column");
  column->add_option("params", o->params, "parameter file with a [hypoplastic] table")
      ->required()
      ->check(input_file());
  column
      ->add_option("--e0", o->e0,
                   "void ratio at the start of shear (default with --dem: the mean of the DEM "
                   "runs' specimens at their start)")
      ->check(number_in(positive(10.0)));
  column
      ->add_option("--scene", o->scene,
                   "a DEM scene: the column takes its d50, its height below the plate's clamp, "
                   "the plate's boundary, the travel, and the wall's condition from its R_n (no "
                   "slip from R_n 0.5, else slip at the seed's kappa_r; src/column/README.md)")
      ->check(input_file());
  column->add_option("--sigma", o->sigma_kPa, "sigma_n0 (kPa, default 50)")
      ->check(number_in(positive(1e5), "kPa"));
  column->add_option("--bc", o->bc, "the plate: CNL (default), CNS or CV")
      ->check(CLI::IsMember({"CNL", "CNS", "CV"}));
  column->add_option("--stiffness", o->stiffness, "CNS: d sigma_n / d u_n (kPa/mm)")
      ->check(number_in(positive(1e6), "kPa/mm"));
  column
      ->add_option("--height-d50", o->height_d50,
                   "free soil between the wall and the clamp, in d50 (default 14: the truth "
                   "scene's 20 d50 less its 6 clamped)")
      ->check(number_in(closed(2.0, 1000.0), "d50"));
  column->add_option("--d50", o->d50_mm, "mean grain diameter, the polar length (mm, default 2)")
      ->check(number_in(positive(100.0), "mm"));
  column->add_option("--elements-per-d50", o->elements_per_d50, "mesh density (default 4)")
      ->check(number_in(closed(0.1, 64.0)));
  column
      ->add_option("--wall-rotation", o->wall_rotation,
                   "fixed (default: the grains locked by a rough wall, w = 0) or free (m = 0)")
      ->check(CLI::IsMember({"fixed", "free"}));
  column
      ->add_option("--wall-friction", o->wall_friction,
                   "tan(delta): the wall slips under the soil where |tau| / sigma_n reaches it "
                   "(default: no slip)")
      ->check(number_in(positive(10.0)));
  column
      ->add_option("--imperfection", o->imperfection,
                   "relative raise of e0 in the element at the wall (default 0)")
      ->check(number_in(closed(0.0, 0.2)));
  column->add_option("--travel", o->travel_mm, "the wall's travel (mm, default 10)")
      ->check(number_in(positive(1000.0), "mm"));
  column->add_option("--increments", o->increments, "increments of the travel (default 1000)")
      ->check(whole_in(1, 10000000));
  column
      ->add_option("--dem", o->dem,
                   "DEM run directories of the same cell, for `iwb report` to set their "
                   "profiles and curves beside the column's (the column's profiles are written "
                   "at the first run's windows)")
      ->check(input_directory());
  column->add_flag(
      "--plain", o->plain,
      "without the polar terms (no couple stress, the grains turn with the continuum)");
  column->add_option("--out,-o", o->out, "run directory (default runs/column)")
      ->check(output_directory());
  column->add_flag("--force", o->force, "replace an earlier column run in the same directory");
  commands.add(column,
               [o, column](const CommandContext& c) { return run_column_command(*o, c, *column); });
}

}  // namespace iwb::app
