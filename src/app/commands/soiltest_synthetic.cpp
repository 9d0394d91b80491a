// `iwb soiltest synthetic`: a soil test from a continuum model with known parameters, the target a
// calibration must recover (calibration/synthetic.hpp).
#include <fmt/core.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "calibration/synthetic.hpp"

namespace iwb::app {

namespace {

struct SyntheticCommand {
  calibration::SyntheticSpec spec;
  std::string params, test = "oedometer", bc = "CNL", out;
  double e0 = 0.0;
  bool force = false;
};

CLI::App* add_synthetic_options(CLI::App& soiltest, SyntheticCommand& c) {
  auto* s = soiltest.add_subcommand(
      "synthetic",
      "Write a soil-test run directory (contract: src/calibration/README.md) from a continuum "
      "model "
      "with known parameters: the target a calibration must find them again from.\n"
      "  oedometer:   sigma_v from --sigma up to --sigma-max in geometric steps, then down to "
      "--sigma-end\n"
      "  simpleshear: monotonic shear to --gamma under --bc CNL (sigma_n held) or CV (volume "
      "held)\n"
      "  cyclicshear: gamma 0 -> +A -> -A -> 0 (A = --amplitude), --cycles times, under --bc; the "
      "model starts with its intergranular strain (if any) along the vertical compression that "
      "prepared the specimen\n"
      "Example: iwb soiltest synthetic --params data/params/table_5_2_hostun.toml --test "
      "simpleshear "
      "--bc CV --e0 0.70 -o runs/soil/dense-cv\n"
      "Example: iwb soiltest synthetic --model vw3d-igs --params "
      "data/params/table_5_3_toyoura.toml --test cyclicshear --amplitude 0.002 --cycles 3 --bc CV "
      "-o runs/soil/cyclic-cv");
  s->add_option("--model", c.spec.model, "continuum model (iwb models)")->capture_default_str();
  s->add_option("--params", c.params, "parameter file (data/params/)")
      ->required()
      ->check(input_file());
  s->add_option("--test", c.test, "oedometer, simpleshear or cyclicshear")
      ->check(CLI::IsMember({"oedometer", "simpleshear", "cyclicshear"}))
      ->capture_default_str();
  s->add_option("--bc", c.bc, "simple shear boundary: CNL or CV")
      ->check(CLI::IsMember({"CNL", "CV"}))
      ->capture_default_str();
  s->add_option("--e0", c.e0,
                "initial void ratio (default: Bauer's critical e_c at the initial mean stress)")
      ->check(number_in(positive(kMaxVoidRatio)));
  s->add_option("--sigma", c.spec.sigma0_kPa,
                "initial sigma_v (oedometer) or sigma_n (simple shear), kPa")
      ->check(number_in(positive(kMaxStressKPa), "kPa"))
      ->capture_default_str();
  s->add_option("--sigma-max", c.spec.sigma_max_kPa, "oedometer: largest sigma_v, kPa")
      ->check(number_in(positive(kMaxStressKPa), "kPa"))
      ->capture_default_str();
  s->add_option("--sigma-end", c.spec.sigma_end_kPa,
                "oedometer: sigma_v after unloading, kPa (>= --sigma-max: no unloading)")
      ->check(number_in(positive(kMaxStressKPa), "kPa"))
      ->capture_default_str();
  s->add_option("--gamma", c.spec.gamma_max, "simple shear: final engineering shear strain")
      ->check(number_in(positive(kMaxShearStrain)))
      ->capture_default_str();
  s->add_option("--amplitude", c.spec.gamma_amplitude,
                "cyclic shear: amplitude A of the engineering shear strain")
      ->check(number_in(positive(kMaxShearStrain)))
      ->capture_default_str();
  s->add_option("--cycles", c.spec.cycles, "cyclic shear: number of cycles")
      ->check(whole_in(1, 1000))
      ->capture_default_str();
  s->add_option("--rows", c.spec.rows, "data rows per branch (cyclic: per quarter cycle)")
      ->check(whole_in(3, 100000))
      ->capture_default_str();
  s->add_option("--out,-o", c.out, "run directory")->required()->check(output_directory());
  s->add_flag("--force", c.force, "replace an earlier soil test in the same directory");
  return s;
}

int run_synthetic(SyntheticCommand c, const std::string& command_line) {
  c.spec.kind = soil_test::soil_test_kind(c.test, "--test");
  c.spec.boundary = driver::parse_boundary_kind(c.bc, "--bc");
  if (c.e0 > 0.0) c.spec.e0 = c.e0;
  const auto t = calibration::write_synthetic_test(c.spec, c.params, c.out, c.force, command_line);
  fmt::print("{} {}{} from {} (e0 = {:.4f}, sigma0 = {:g} kPa): {} rows -> {}\n", c.test,
             c.test == "oedometer" ? "" : c.bc + " ", c.spec.model, c.params, t.e0, t.sigma0_kPa,
             t.rows(), c.out);
  return 0;
}

}  // namespace

void refuse_cyclic_options(const CLI::App& soiltest, const std::string& test) {
  if (test != "cyclicshear")
    refuse_given(soiltest, {"--amplitude", "--cycles"},
                 "applies only to --test cyclicshear, not to --test " + test);
}

void add_soiltest_synthetic_command(CLI::App& soiltest, CommandList& commands) {
  auto c = std::make_shared<SyntheticCommand>();
  auto* s = add_synthetic_options(soiltest, *c);
  commands.add(s, [c, s](const CommandContext& context) {
    refuse_cyclic_options(*s, c->test);
    return run_synthetic(*c, context.command_line);
  });
}

}  // namespace iwb::app
