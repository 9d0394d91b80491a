// `iwb dem soiltest SCENE.toml --test ...`: a soil element test on a DEM cell
// (dem/soil_cells/soil_cell.hpp).
#include <fmt/core.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"
#include "dem/soil_cells/soil_cell.hpp"
#include "io/run_directory.hpp"

namespace iwb::app {

namespace {

struct DemSoiltestCommand {
  std::string scene, test = "oedometer", bc = "CNL", density = "dense", cell = "plates", out;
  dem::SoilCellSpec spec;
  int np = 1;
  bool resume = false, force = false;
};

int run_dem_soiltest(const DemSoiltestCommand& c, const CommandContext& context) {
  dem::SoilCellSpec spec = c.spec;
  spec.test = soil_test::soil_test_kind(c.test, "--test");
  spec.boundary = driver::parse_boundary_kind(c.bc, "--bc");
  spec.density = dem::parse_soil_density(c.density, "--density");
  spec.cell = dem::parse_cell_kind(c.cell, "--cell");
  const bool oed = spec.test == soil_test::SoilTestKind::kOedometer;
  const std::filesystem::path dir =
      !c.out.empty()
          ? std::filesystem::path(c.out)
          : std::filesystem::path("runs") /
                fmt::format("soil-{}-{}{}-{}{}{}", std::filesystem::path(c.scene).stem().string(),
                            c.test, oed ? "" : "-" + c.bc, c.density,
                            spec.engine == "liggghts" ? "" : "-" + spec.engine,
                            spec.cell == dem::CellKind::kPeriodic ? "-periodic" : "");
  dem::RunOptions opt{
      dir, c.np, c.resume, c.force, context.command_line, context.interrupt, engine_progress(), {}};
  fmt::print(stderr,
             "iwb dem soiltest: {} of {} in {} ({}, {} cell, {:g} kPa, {:g} x {:g} x {:g} d50, {} "
             "rank(s)) "
             "-> {}\n",
             oed ? std::string("oedometer") : c.test + " " + c.bc, c.scene, spec.engine, c.density,
             c.cell, spec.initial_stress_kPa(), spec.length_d50, spec.width_d50, spec.height_d50,
             c.np, dir.string());
  const auto outcome = dem::run_soil_test(io::read_file(c.scene), c.scene, spec, opt);
  fmt::print(outcome.complete() ? stdout : stderr, "{}: {} ({} particles) -> {}\n", c.scene,
             outcome.status, outcome.manifest.value("particle_count", 0), dir.string());
  return outcome.complete() ? 0 : 1;
}

}  // namespace

void add_dem_soiltest_command(CLI::App& dem, CommandList& commands) {
  auto c = std::make_shared<DemSoiltestCommand>();
  auto* s = dem.add_subcommand(
      "soiltest",
      "A soil element test on a DEM cell of a scene's grains (same particles, contact law and "
      "seed; no "
      "wall under test), in LIGGGHTS or YADE (--engine), into the soil-test contract that `iwb "
      "calibrate` reads "
      "(src/calibration/README.md). The cell (--cell plates) is periodic in x and y between two "
      "rough sawtooth plates (ridges 1 d50, pitch 2 d50; plate friction = grain friction); "
      "--cell periodic (simple and cyclic shear) has no plates: periodic in every "
      "direction, consolidated by a servo on the box height and sheared by the box's own tilt, so "
      "that no band forms next to a plate (manifest cell_summary.homogeneous says whether the "
      "shear was). The specimen is prepared at the first stress with friction 0 (dense) or 1 "
      "(loose).\n"
      "  oedometer:   the box never widens (zero lateral strain); the top plate's servo ramps "
      "sigma_v "
      "from --sigma (10 kPa) to --sigma-max in --load-levels geometric steps and back in "
      "--unload-levels, each ramp and hold --level-windows consolidation windows long; rows "
      "sigma_v_kPa, eps_v, e, sigma_h_kPa, K0 (stress tensor), coordination, estimated mean "
      "overlap\n"
      "  simpleshear: the bottom plate moves in +x to --gamma (travel / target height) at "
      "--inertial-number; CNL keeps sigma_n (--sigma, 50 kPa) by the servo, CV holds the plate; "
      "rows "
      "gamma, tau_kPa, sigma_n_kPa, e (+ profiles.csv: is the shear homogeneous?)\n"
      "  cyclicshear: the bottom plate moves 0 -> +A -> -A -> 0, --cycles times, A = --amplitude "
      "x target height; CNL or CV as simple shear; 40 rows a quarter cycle (what `iwb calibrate "
      "--model vw3d-igs --table intergranular_strain` fits)\n"
      "Example: iwb dem soiltest data/scenes/default.toml --test simpleshear --bc CV --density "
      "loose "
      "--out runs/soil/loose-cv");
  s->add_option("scene", c->scene,
                "scene TOML file (its [particles], seed and [consolidation] are used)")
      ->required()
      ->check(input_file());
  s->add_option("--test", c->test, "oedometer, simpleshear or cyclicshear")
      ->check(CLI::IsMember({"oedometer", "simpleshear", "cyclicshear"}))
      ->capture_default_str();
  s->add_option("--engine", c->spec.engine,
                "DEM engine: liggghts or yade (the same cell, stress program and rows; YADE is "
                "~7x slower per particle-step)")
      ->check(CLI::IsMember({"liggghts", "yade"}))
      ->capture_default_str();
  s->add_option(
       "--cell", c->cell,
       "plates (rough sawtooth plates, periodic in x and y) or periodic (no plates: the box "
       "sheared by its tilt; simple and cyclic shear)")
      ->check(CLI::IsMember({"plates", "periodic"}))
      ->capture_default_str();
  s->add_option("--bc", c->bc, "simple shear: CNL or CV")
      ->check(CLI::IsMember({"CNL", "CV"}))
      ->capture_default_str();
  s->add_option("--density", c->density,
                "dense (preparation friction 0), loose (1) or as-scene (the scene's own [specimen] "
                "consolidation_friction: the density of its interface specimen)")
      ->check(CLI::IsMember({"dense", "loose", "as-scene"}))
      ->capture_default_str();
  s->add_option("--sigma", c->spec.sigma0_kPa,
                "first sigma_v (oedometer, default 10) or sigma_n (simple shear, 50), kPa")
      ->check(number_in(positive(kMaxStressKPa), "kPa"));
  s->add_option("--sigma-max", c->spec.sigma_max_kPa, "oedometer: largest sigma_v, kPa")
      ->check(number_in(positive(kMaxStressKPa), "kPa"))
      ->capture_default_str();
  s->add_option("--gamma", c->spec.gamma, "simple shear: final shear strain")
      ->check(number_in(positive(kMaxShearStrain)))
      ->capture_default_str();
  s->add_option("--amplitude", c->spec.gamma_amplitude,
                "cyclic shear: amplitude A of gamma (wall travel / target cell height)")
      ->check(number_in(positive(1.0)))
      ->capture_default_str();
  s->add_option("--cycles", c->spec.cycles, "cyclic shear: number of cycles")
      ->check(whole_in(1, 1000))
      ->capture_default_str();
  s->add_option("--height", c->spec.height_d50, "target cell height (z) in d50")
      ->check(number_in(closed(4.0, 100.0), "d50"))
      ->capture_default_str();
  s->add_option("--length", c->spec.length_d50, "cell length (x) in d50, at least 10 d_max")
      ->check(number_in(positive(kMaxCellSizeD50), "d50"))
      ->capture_default_str();
  s->add_option("--width", c->spec.width_d50, "cell width (y) in d50, at least 3 d_max")
      ->check(number_in(positive(kMaxCellSizeD50), "d50"))
      ->capture_default_str();
  s->add_option("--inertial-number", c->spec.inertial_number,
                "simple shear: gamma_dot d50 sqrt(rho/sigma_n)")
      ->check(number_in(closed(1e-6, 1e-1)))
      ->capture_default_str();
  s->add_option("--load-levels", c->spec.load_levels, "oedometer: loading levels")
      ->check(whole_in(2, 100))
      ->capture_default_str();
  s->add_option("--unload-levels", c->spec.unload_levels, "oedometer: unloading levels (0: none)")
      ->check(whole_in(0, 100))
      ->capture_default_str();
  s->add_option("--level-windows", c->spec.level_windows,
                "oedometer: ramp and hold length in consolidation windows")
      ->check(whole_in(1, 100))
      ->capture_default_str();
  s->add_option("--np", c->np, "MPI ranks (LIGGGHTS) or OpenMP threads (YADE)")
      ->check(whole_in(1, kMaxProcesses))
      ->capture_default_str();
  s->add_option("--out,-o", c->out,
                "run directory (default runs/soil-<scene>-<test>[-<bc>]-<density>[-yade])")
      ->check(output_directory());
  s->add_flag("--resume", c->resume,
              "continue an interrupted run of the same cell from its last finished stage");
  s->add_flag("--force", c->force, "replace an earlier run in the same directory");
  commands.add(s, [c, s](const CommandContext& context) {
    refuse_cyclic_options(*s, c->test);
    return run_dem_soiltest(*c, context);
  });
}

}  // namespace iwb::app
