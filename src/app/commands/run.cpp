// `iwb run [--study sand|clay|chapter8|thermo]`: the continuum studies. sand: hvwe against vw3d on
// seed Table 5.1 (studies/sand_study.hpp); clay: the seed's 6.4 comparisons of the clay models
// (studies/).
#include <fmt/core.h>

#include <memory>
#include <string>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "studies/chapter8_study.hpp"
#include "studies/clay_study.hpp"
#include "studies/sand_study.hpp"
#include "studies/thermo_study.hpp"

namespace iwb::app {

namespace {
struct RunOptions {
  std::string study = "sand", out;
  bool force = false;
};

// The sand study's table, a row per boundary as it is done.
void print_sand_header() {
  fmt::print(
      "iwb run: embedded default, hvwe against vw3d in simple shear (seed Table 5.1, "
      "e0 = 0.80, 100 kPa)\n");
  fmt::print("{:<4} {:>9} {:>9} {:>9} {:>8} | {:^39} |\n", "", "", "hvwe", "", "",
             "max |hvwe - vw3d| along the path");
  fmt::print("{:<4} {:>9} {:>9} {:>9} {:>8} | {:>9} {:>9} {:>9} {:>9} | {}\n", "BC", "peak t/s",
             "end t/s", "end s_n", "end e", "tau kPa", "s_n kPa", "s_p kPa", "e", "status");
}

void print_sand_row(const studies::SandRow& r) {
  const auto& d = r.differences;
  fmt::print(
      "{:<4} {:>9.4f} {:>9.4f} {:>9.2f} {:>8.4f} | {:>9.2e} {:>9.2e} {:>9.2e} {:>9.2e} | {}\n",
      r.boundary, r.peak, r.last, r.sigma_last, r.e_last, d[0], d[1], d[2], d[3],
      r.status == "complete" ? "ok" : "FAILED");
}

int run_sand(const std::filesystem::path& out, bool force, const std::string& command_line) {
  print_sand_header();
  const bool ok = studies::run_sand_study(out, force, command_line, print_sand_row);
  fmt::print("run directories and summary.json in {}\n", out.string());
  return ok ? 0 : 1;
}

int run_study(const RunOptions& o, const CommandContext& c) {
  if (o.study == "clay")
    return studies::run_study(studies::clay_study(), {o.out.empty() ? "runs/clay" : o.out, o.force,
                                                      c.command_line, c.interrupt});
  if (o.study == "chapter8")
    return studies::run_study(studies::chapter8_study(), {o.out.empty() ? "runs/chapter8" : o.out,
                                                          o.force, c.command_line, c.interrupt});
  if (o.study == "thermo")
    return studies::run_study(studies::thermo_study(), {o.out.empty() ? "runs/thermo" : o.out,
                                                        o.force, c.command_line, c.interrupt});
  return run_sand(o.out.empty() ? "runs/default" : o.out, o.force, c.command_line);
}
}  // namespace

void add_run_command(CLI::App& app, CommandList& commands) {
  auto o = std::make_shared<RunOptions>();
  auto* run =
      app.add_subcommand("run",
                         "The continuum studies. sand (default): hvwe against its 3D reference "
                         "vw3d in simple shear under CNL, "
                         "CNS and CV (seed Table 5.1), with a table of their differences. clay: "
                         "the seed's section 6.4 "
                         "comparisons of the clay interface models (HCC against HCE under CV, CNL "
                         "and CNS; roughness kappa_r and "
                         "the two roughness schemes; intergranular strain under cyclic CNL and "
                         "CV). chapter8: the seed's section 8.4, "
                         "constant-volume shear of HCE, Barodesy for clay and modified Cam clay on "
                         "the reduced vectors with Table "
                         "8.1's London and Kaolin sets, and reduced against 3D. thermo: the seed's "
                         "section 6.5, the thermo-hydro-mechanical "
                         "interface model hcthm under CNL and CV at several temperatures, with n_t "
                         "and l_t varied, and at several "
                         "suctions (Table 6.5). Each case is an element run directory, the seed's "
                         "claims are checked in study.md and study.json, and NAME.html holds the "
                         "figures (src/studies/README.md).");
  run->add_option("--study", o->study, "sand, clay, chapter8 or thermo")
      ->check(CLI::IsMember({"sand", "clay", "chapter8", "thermo"}))
      ->capture_default_str();
  run->add_option("--out,-o", o->out,
                  "output directory (default runs/default for sand, runs/<study> otherwise)")
      ->check(output_directory());
  run->add_flag("--force", o->force, "replace earlier runs in the output directory");
  commands.add(run, [o](const CommandContext& c) { return run_study(*o, c); });
}

}  // namespace iwb::app
