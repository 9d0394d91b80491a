#include "app/validate.hpp"

#include <cmath>
#include <fmt/core.h>

#include "common/errors.hpp"
#include "comparison/compare.hpp"
#include "comparison/report.hpp"
#include "dem/engines.hpp"
#include "dem/run.hpp"
#include "io/parameter_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::app {

namespace fs = std::filesystem;

namespace {

// The scene text and its name: an embedded scene by name, or a file.
std::pair<std::string, std::string> scene_source(const std::string& scene) {
  const auto& embedded = dem::embedded_scenes();
  if (const auto it = embedded.find(scene + ".toml"); it != embedded.end())
    return {it->second, "<embedded:" + scene + ">"};
  if (fs::is_regular_file(scene)) return {io::read_file(scene), scene};
  std::string names;
  for (const auto& [n, t] : embedded) names += (names.empty() ? "" : ", ") + n.substr(0, n.size() - 5);
  throw InputError(fmt::format("--scene {}: neither an embedded scene ({}) nor a file", scene, names));
}

// The shipped parameter set whose critical friction angle is closest to the DEM's residual
// interface friction angle atan(tau/sigma_n): the only property of the grains a DEM run tells
// without calibration (issue 7 calibrates properly).
fs::path matching_parameters(const fs::path& dir, double residual_friction, std::string& why) {
  if (!fs::is_directory(dir))
    throw InputError(fmt::format("{}: no parameter sets here (run from the repository, or pass --params-dir)", dir.string()));
  const double phi_dem = std::atan(residual_friction) * 180.0 / M_PI;
  fs::path best;
  double best_gap = INFINITY;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    const auto tables = io::load_parameter_file(f.string());
    const auto it = tables.find("hypoplastic");
    if (it == tables.end() || !it->second.count("phi_c_deg")) continue;
    const double gap = std::abs(it->second.at("phi_c_deg") - phi_dem);
    if (gap < best_gap) best_gap = gap, best = f;
  }
  if (best.empty()) throw InputError(fmt::format("{}: no [hypoplastic] parameter set", dir.string()));
  why = fmt::format("phi_c closest to the DEM's residual friction angle atan({:.3f}) = {:.1f} deg", residual_friction, phi_dem);
  return best;
}

}  // namespace

int run_validate(const ValidateOptions& opt) {
  const auto engine = dem::make_engine(opt.engine);
  const auto [text, source] = scene_source(opt.scene);
  const auto scene = dem::parse_scene(text, source);
  for (const auto& w : scene.warnings) fmt::print(stderr, "warning: {}\n", w);
  fs::create_directories(opt.out);
  const fs::path dem_dir = opt.out / fmt::format("dem-{}", opt.engine);
  fmt::print(stderr, "iwb validate: 1/3 DEM run of {} in {} ({} ranks) -> {}\n", source, opt.engine, opt.processes, dem_dir.string());
  auto last = std::chrono::steady_clock::now();
  const auto outcome = dem::run_scene(scene, text, *engine,
                                      {dem_dir, opt.processes, false, opt.force, opt.command_line, nullptr,
                                       [&last](const std::string& l) {
                                         if (std::chrono::steady_clock::now() - last < std::chrono::seconds(3)) return;
                                         last = std::chrono::steady_clock::now();
                                         fmt::print(stderr, "  {}\n", l);
                                       }});
  if (!outcome.complete()) {
    fmt::print(stderr, "iwb validate: the DEM run did not complete: {}\n", outcome.status);
    return 1;
  }
  const auto summary = nlohmann::json::parse(io::read_file(dem_dir / "summary.json"));
  std::string why;
  const fs::path params = matching_parameters(opt.params_dir, summary["residual_friction"].get<double>(), why);
  fmt::print(stderr, "iwb validate: 2/3 replay through hvwe with {} ({})\n", params.string(), why);
  comparison::CompareOptions copt{dem_dir, "hvwe", params.string(), opt.out / "compare-hvwe", false, opt.force,
                                  opt.command_line + " [parameters: " + why + "]"};
  comparison::run_comparison(copt);
  const fs::path html = opt.out / "report.html";
  fmt::print(stderr, "iwb validate: 3/3 report\n");
  comparison::write_report({copt.out}, html);
  fmt::print("report: {}\n", fs::absolute(html).string());
  return 0;
}

}  // namespace iwb::app
