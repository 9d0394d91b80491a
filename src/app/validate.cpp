#include "app/validate.hpp"

#include <chrono>
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

// Parameter sets calibrated on soil tests of one scene's grains (`iwb dem soiltest` + `iwb
// calibrate`, data/calibration/<name>/README.md): the set for a scene whose [particles] are those
// grains, and never a stand-in for other grains in the phi_c match below.
struct CalibratedGrains {
  const char* scene;  // embedded scene whose particles were calibrated
  const char* file;   // in the parameter directory
};
constexpr CalibratedGrains kCalibratedGrains[] = {{"default", "dem_default_grains.toml"}};

bool calibrated_set(const fs::path& file) {
  for (const auto& c : kCalibratedGrains)
    if (file.filename() == c.file) return true;
  return false;
}

bool same_grains(const dem::Particles& a, const dem::Particles& b) {
  const auto key = [](const dem::Particles& p) {
    std::vector<double> k{p.d50_m, p.density_kg_m3, p.youngs_modulus_Pa, p.poisson, p.friction, p.rolling_friction,
                          p.restitution};
    for (const auto& c : p.sizes) k.insert(k.end(), {c.diameter_m, c.mass_fraction});
    return k;
  };
  return key(a) == key(b);
}

// The calibrated set for the scene's grains, or empty if there is none.
fs::path calibrated_parameters(const fs::path& dir, const dem::Scene& scene, std::string& why) {
  for (const auto& c : kCalibratedGrains) {
    const auto base = dem::parse_scene(dem::embedded_scenes().at(std::string(c.scene) + ".toml"), c.scene);
    if (!same_grains(base.particles, scene.particles) || !fs::exists(dir / c.file)) continue;
    why = fmt::format("calibrated on DEM soil tests of the {} scene's grains (data/calibration/)", c.scene);
    return dir / c.file;
  }
  return {};
}

// Runs the scene in one engine into out/dem-<engine>; false (and says why) if it did not complete.
bool run_dem(const dem::Scene& scene, const std::string& text, const std::string& source, const std::string& engine_name,
             const ValidateOptions& opt, const fs::path& dem_dir, const std::string& step) {
  const auto engine = dem::make_engine(engine_name);
  fmt::print(stderr, "iwb validate: {} DEM run of {} in {} ({} processes) -> {}\n", step, source, engine_name,
             opt.processes, dem_dir.string());
  auto last = std::chrono::steady_clock::now();
  const auto outcome = dem::run_scene(scene, text, *engine,
                                      {dem_dir, opt.processes, false, opt.force, opt.command_line, nullptr,
                                       [&last](const std::string& l) {
                                         if (std::chrono::steady_clock::now() - last < std::chrono::seconds(3)) return;
                                         last = std::chrono::steady_clock::now();
                                         fmt::print(stderr, "  {}\n", l);
                                       }});
  if (!outcome.complete()) fmt::print(stderr, "iwb validate: the {} run did not complete: {}\n", engine_name, outcome.status);
  return outcome.complete();
}

}  // namespace

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
    if (e.path().extension() == ".toml" && !calibrated_set(e.path())) files.push_back(e.path());
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

fs::path parameters_for(const fs::path& dir, const dem::Scene& scene, double residual_friction, std::string& why) {
  const auto calibrated = calibrated_parameters(dir, scene, why);
  return calibrated.empty() ? matching_parameters(dir, residual_friction, why) : calibrated;
}

int run_validate(const ValidateOptions& opt) {
  if (opt.engines.empty()) throw InputError("--engines: name at least one engine (liggghts, yade)");
  for (const auto& e : opt.engines) dem::make_engine(e);  // refused before anything runs
  const auto [text, source] = scene_source(opt.scene);
  const auto scene = dem::parse_scene(text, source);
  for (const auto& w : scene.warnings) fmt::print(stderr, "warning: {}\n", w);
  fs::create_directories(opt.out);
  const std::size_t steps = 2 * opt.engines.size() + 1;
  std::size_t step = 0;
  std::vector<fs::path> compares;
  fs::path params;
  std::string why;
  for (const auto& engine : opt.engines) {
    const fs::path dem_dir = opt.out / fmt::format("dem-{}", engine);
    if (!run_dem(scene, text, source, engine, opt, dem_dir, fmt::format("{}/{}", ++step, steps))) return 1;
    // One parameter set for every engine, chosen on the first, so that the engines are compared
    // through the same continuum model.
    if (params.empty()) {
      const auto summary = nlohmann::json::parse(io::read_file(dem_dir / "summary.json"));
      params = parameters_for(opt.params_dir, scene, summary["residual_friction"].get<double>(), why);
    }
    fmt::print(stderr, "iwb validate: {}/{} replay of the {} run through hvwe with {} ({})\n", ++step, steps, engine,
               params.string(), why);
    const fs::path out = opt.out / (opt.engines.size() == 1 ? "compare-hvwe" : fmt::format("compare-hvwe-{}", engine));
    comparison::CompareOptions copt{dem_dir, "hvwe", params.string(), out, false, opt.force,
                                    opt.command_line + " [parameters: " + why + "]"};
    comparison::run_comparison(copt);
    compares.push_back(out);
  }
  const fs::path html = opt.out / "report.html";
  fmt::print(stderr, "iwb validate: {}/{} report\n", ++step, steps);
  comparison::write_report(compares, html);
  fmt::print("report: {}\n", fs::absolute(html).string());
  return 0;
}

}  // namespace iwb::app
