#include "tradeoff/plan.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "comparison/compare.hpp"
#include "comparison/fit.hpp"
#include "comparison/metrics.hpp"
#include "comparison/seed_scatter.hpp"
#include "dem/scene.hpp"
#include "dem/scene_content.hpp"
#include "io/json_file.hpp"
#include "io/parameter_file.hpp"
#include "io/run_directory.hpp"
#include "tradeoff/tradeoff.hpp"

namespace iwb::tradeoff {

namespace fs = std::filesystem;
using nlohmann::json;

std::vector<std::string> model_ladder(bool cyclic) {
  std::vector<std::string> m = {"hp1d", "ah", "hvwe"};
  if (cyclic) m.push_back("hvwe-igs");  // intergranular strain matters only where the path reverses
  return m;
}

namespace {

bool measured_by_tradeoff(const std::string& key) {
  for (const auto& q : dem::quantities_of_interest())
    if (key == q.key) return true;
  return false;
}

// The stated tolerances a candidate fails: error + noise above the tolerance, or not measured.
// Tolerances of quantities only `iwb compare` judges (dem::compared_only_quantities) are not
// the tradeoff's to meet.
json failures(const std::map<std::string, std::optional<double>>& error,
              const dem::Requirements& req, const json& noise_floor) {
  json out = json::array();
  for (const auto& [q, tol] : req) {
    if (!tol || !measured_by_tradeoff(q)) continue;  // "not needed", or not the tradeoff's
    const auto it = error.find(q);
    const json n = noise_floor.contains(q) ? noise_floor[q].value("relative", json()) : json();
    if (it == error.end() || !it->second || !n.is_number()) {
      out.push_back({{"qoi", q},
                     {"tolerance", *tol},
                     {"error", nullptr},
                     {"why", !n.is_number() ? "no noise floor" : "not measured"}});
      continue;
    }
    const double total = *it->second + n.get<double>();
    if (total > *tol)
      out.push_back({{"qoi", q},
                     {"tolerance", *tol},
                     {"error", *it->second},
                     {"noise", n.get<double>()},
                     {"by", total - *tol}});
  }
  return out;
}

std::map<std::string, std::optional<double>> errors_of(const json& setting) {
  std::map<std::string, std::optional<double>> e;
  const json errors = setting.value("error", json::object());  // named: items() must not outlive it
  for (const auto& [q, v] : errors.items())
    e[q] = v.is_number() ? std::optional<double>(v.get<double>()) : std::nullopt;
  return e;
}

}  // namespace

json choose_dem(const json& tradeoff, const dem::Requirements& req) {
  std::vector<const json*> candidates;
  for (const auto& s : tradeoff.at("settings"))
    if (s.value("status", "") == "complete" && s.contains("error")) candidates.push_back(&s);
  std::stable_sort(candidates.begin(), candidates.end(), [](const json* a, const json* b) {
    return (*a)["particle_steps"].get<double>() < (*b)["particle_steps"].get<double>();
  });
  json out = {{"chosen", nullptr}, {"candidates", json::array()}};
  for (const json* s : candidates) {
    json c = {{"name", (*s)["name"]},
              {"settings", s->value("settings", "")},
              {"particle_steps", (*s)["particle_steps"]},
              {"wall_seconds", (*s)["wall_seconds"]},
              {"error", s->value("error", json::object())},
              {"fails", failures(errors_of(*s), req, tradeoff.at("noise_floor"))}};
    if (out["chosen"].is_null() && c["fails"].empty()) out["chosen"] = c;
    out["candidates"].push_back(c);
  }
  return out;
}

json choose_model(const std::vector<ModelErrors>& models, const dem::Requirements& req,
                  const json& noise_floor) {
  json out = {{"chosen", nullptr}, {"candidates", json::array()}};
  for (const auto& m : models) {
    json c = {{"name", m.model},
              {"note", m.note},
              {"error", json::object()},
              {"fails", failures(m.error, req, noise_floor)}};
    for (const auto& [q, e] : m.error) c["error"][q] = e ? json(*e) : json(nullptr);
    if (out["chosen"].is_null() && c["fails"].empty()) out["chosen"] = c;
    out["candidates"].push_back(c);
  }
  return out;
}

namespace {

// d u_n / d u_x over the last fifth of the displacement (least-squares slope), as the DEM summary
// defines its dilation rate.
double slope_last_fifth(const std::vector<double>& x, const std::vector<double>& y) {
  const double from = x.front() + 0.8 * (x.back() - x.front());
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i] >= from) n += 1, sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  const double d = n * sxx - sx * sx;
  return d > 0 ? (n * sxy - sx * sy) / d : NAN;
}

std::optional<double> relative(double model, double dem) {
  if (!std::isfinite(model) || dem == 0.0) return std::nullopt;
  return std::abs(model - dem) / std::abs(dem);
}

}  // namespace

ModelErrors evaluate_model(const fs::path& reference_run, const std::string& model,
                           const io::ParameterSet& params) {
  ModelErrors r{model, {}, ""};
  try {
    const auto dem = comparison::load_dem_run(reference_run);
    models::ModelInputs inputs;
    inputs.tables = params.tables;
    inputs.source = params.origin;
    auto start = comparison::standard_variants(dem, model, inputs).front();
    const auto fit =
        comparison::fit_kappa_and_ds(dem, start, comparison::joint_targets(dem, comparison::seed_scatter(dem, {})));  // the model at its best kappa_r and d_s, on tau and dilation
    start.inputs.roughness.kappa_r = fit.kappa_r;
    start.d_s_mm = fit.d_s_mm;
    const auto replay = comparison::replay(dem, start);
    const auto m = comparison::compare(dem, replay);
    r.error["peak_friction"] = relative(m.peak_friction_model, m.peak_friction_dem);
    r.error["residual_friction"] = relative(m.residual_friction_model, m.residual_friction_dem);
    const std::size_t n = replay.u_x_mm.size();  // the DEM rows the replay reached
    const std::vector<double> dem_ux(dem.u_x_mm.begin(), dem.u_x_mm.begin() + long(n)),
        dem_un(dem.u_n_mm.begin(), dem.u_n_mm.begin() + long(n));
    r.error["dilation_rate"] =
        relative(slope_last_fifth(replay.u_x_mm, replay.u_n_mm), slope_last_fifth(dem_ux, dem_un));
    r.error["band_thickness"] = std::nullopt;
    r.note = fmt::format(
        "fitted kappa_r = {:.3f}, d_s = {:.2f} mm; replay {}",
        fit.kappa_r, fit.d_s_mm, replay.status);
  } catch (const std::exception& e) {
    r.note = fmt::format("could not be evaluated: {}", e.what());
  }
  return r;
}

namespace {

fs::path tradeoff_dir(const PlanOptions& opt) {
  return opt.tradeoff_dir.empty() ? default_out(opt.scene_file) : opt.tradeoff_dir;
}

// The scene against the one the tradeoff ran, by content: its file's name, comments and layout
// do not count, a value that decides the DEM runs does and is named.
void require_same_scene(const json& t, const fs::path& file, const PlanOptions& opt) {
  const std::string text = io::read_file(opt.scene_file), scene = opt.scene_file.string();
  const std::string ran = t.value("scene", "?");
  const auto refuse = [&](const std::string& what) {
    return InputError(fmt::format("{}: not the scene the tradeoff {} was run on ({}): {}; run `iwb tradeoff {}` "
                                  "for this scene", scene, file.string(), ran, what, scene));
  };
  if (t.contains("dem_scene")) {
    const auto diff = dem::content_differences(dem::scene_content(text, scene), t["dem_scene"]);
    if (!diff.empty()) throw refuse(dem::differences_text(diff));
    return;
  }
  // A tradeoff.json from before the content was recorded: its hash, under the name it ran as.
  if (t.value("dem_scene_sha256", "") != dem_scene_sha256(text, fs::path(ran).filename().string()))
    throw refuse("its DEM settings differ (this tradeoff.json records only their sha256, not which key)");
}

// Plan reads the reference's run directory (its summary chooses the default parameters) and
// replays the complete base seeds: each must be there, not only the tables.
void require_run_directories(const json& t, const fs::path& file, const PlanOptions& opt) {
  std::vector<std::string> names = {t["reference"]["name"].get<std::string>()};
  for (const auto& r : t["runs"])
    if (r["kind"] == "base" && r["status"] == "complete") names.push_back(r["name"].get<std::string>());
  std::string missing;
  for (const auto& n : names)
    if (!fs::is_regular_file(file.parent_path() / "runs" / n / "manifest.json"))
      missing += (missing.empty() ? "" : ", ") + (fs::path("runs") / n).string();
  if (!missing.empty())
    throw InputError(fmt::format("{}: the tradeoff's run directories {} are missing (plan replays its runs; a "
                                 "committed tradeoff holds tables only); run `iwb tradeoff {} -o {}` to make "
                                 "them (complete runs there are reused)", file.string(), missing,
                                 opt.scene_file.string(), file.parent_path().string()));
}

json load_tradeoff(const PlanOptions& opt) {
  const fs::path dir = tradeoff_dir(opt);
  const fs::path file = dir / "tradeoff.json";
  if (!fs::is_regular_file(file))
    throw InputError(fmt::format("{}: no tradeoff data for {}; run `iwb tradeoff {} -o {}` first",
                                 file.string(), opt.scene_file.string(), opt.scene_file.string(),
                                 dir.string()));
  const json t = io::read_json_file(file);  // a truncated file is named, not a raw parse error
  require_same_scene(t, file, opt);
  if (t["reference"].is_null())
    throw InputError(
        fmt::format("{}: the reference run has not completed (status {}); run `iwb tradeoff` again "
                    "to continue it",
                    file.string(), t.value("status", "?")));
  require_run_directories(t, file, opt);
  return t;
}

}  // namespace

// The scene's own runs (base seeds): the grains a parameter set calibrated for the scene
// describes. The refined reference has other grains (kappa x2 is a stiffer E), so a continuum
// model is judged against these, with their seed mean.
std::vector<fs::path> base_runs(const PlanOptions& opt, const json& t) {
  const fs::path dir = tradeoff_dir(opt);
  std::vector<fs::path> out;
  for (const auto& r : t["runs"])
    if (r["kind"] == "base" && r["status"] == "complete")
      out.push_back(dir / "runs" / r["name"].get<std::string>());
  return out;
}

// evaluate_model on every run, each QoI's error averaged over the runs (unknown if one lacks it).
ModelErrors evaluate_model_on(const std::vector<fs::path>& runs, const std::string& model,
                              const io::ParameterSet& params) {
  std::vector<ModelErrors> each;
  ModelErrors mean{model, {}, ""};
  for (const auto& run : runs) {
    each.push_back(evaluate_model(run, model, params));
    mean.note += fmt::format("{}{}: {}", mean.note.empty() ? "" : "; ", run.filename().string(),
                             each.back().note);
  }
  for (const auto& q : dem::quantities_of_interest()) {
    double sum = 0.0;
    bool known = !each.empty();
    for (const auto& e : each) {
      const auto it = e.error.find(q.key);
      known = known && it != e.error.end() && it->second;
      if (known) sum += *it->second;
    }
    mean.error[q.key] = known ? std::optional<double>(sum / double(each.size())) : std::nullopt;
  }
  return mean;
}

fs::path reference_run(const PlanOptions& opt) {
  const json t = load_tradeoff(opt);
  return tradeoff_dir(opt) / "runs" / t["reference"]["name"].get<std::string>();
}

json run_plan(const PlanOptions& opt) {
  const dem::Scene scene = dem::load_scene(opt.scene_file.string());
  if (scene.requirements.empty())
    throw InputError(fmt::format(
        "{}: the scene states no [requirements] (data/scenes/README.md); nothing to plan",
        opt.scene_file.string()));
  const json t = load_tradeoff(opt);
  const fs::path ref = reference_run(opt);
  const auto judged_on = base_runs(opt, t);
  if (judged_on.empty())
    throw InputError(fmt::format("{}: no complete base seed in the tradeoff; run `iwb tradeoff` "
                                 "again to continue it", ref.parent_path().parent_path().string()));
  std::vector<ModelErrors> models;
  for (const auto& m : model_ladder(scene.shear.cyclic()))
    models.push_back(evaluate_model_on(judged_on, m, opt.params));
  json judged = json::array();
  for (const auto& r : judged_on) judged.push_back(r.filename().string());
  json req = json::object();
  for (const auto& [q, tol] : scene.requirements) req[q] = tol ? json(*tol) : json("not needed");
  json plan = {{"kind", "plan"},
               {"scene", opt.scene_file.string()},
               {"requirements", req},
               {"tradeoff", (ref.parent_path().parent_path() / "tradeoff.json").string()},
               {"reference", t["reference"]},
               {"noise_floor", t["noise_floor"]},
               {"dem", choose_dem(t, scene.requirements)},
               {"continuum", choose_model(models, scene.requirements, t["noise_floor"])},
               {"continuum_judged_on", judged},
               {"params", opt.params.origin},
               {"params_why", opt.params_why},
               {"command_line", opt.command_line}};
  const fs::path out = opt.out.empty() ? ref.parent_path().parent_path() : opt.out;
  fs::create_directories(out);
  io::write_atomically(out / "plan.json", plan.dump(2) + "\n");
  return plan;
}

namespace {

std::string fails_text(const json& fails) {
  std::string s;
  for (const auto& f : fails) {
    s += s.empty() ? "" : "; ";
    if (f["error"].is_null())
      s += fmt::format("{}: {}", f["qoi"].get<std::string>(), f["why"].get<std::string>());
    else
      s += fmt::format("{} {:.1f} % + noise {:.1f} % > {:.0f} % by {:.1f} points",
                       f["qoi"].get<std::string>(), 100 * f["error"].get<double>(),
                       100 * f["noise"].get<double>(), 100 * f["tolerance"].get<double>(),
                       100 * f["by"].get<double>());
  }
  return s;
}

// "residual_friction 0.9 %" for the stated QoIs, so that a pass shows its margin too.
std::string stated_errors(const json& c, const json& requirements) {
  std::string s;
  for (const auto& [q, tol] : requirements.items()) {
    if (!tol.is_number()) continue;
    const json e = c.value("error", json::object()).value(q, json());
    s += fmt::format("{}{} {}", s.empty() ? "" : ", ", q,
                     e.is_number() ? fmt::format("{:.1f} %", 100 * e.get<double>()) : "n/a");
  }
  return s;
}

std::string verdict(const json& c, const json& requirements) {
  return c["fails"].empty() ? "meets every tolerance (" + stated_errors(c, requirements) + ")"
                            : "fails: " + fails_text(c["fails"]);
}

}  // namespace

std::string plan_text(const json& p) {
  std::string s = fmt::format("plan for {}: requirements {}\n", p["scene"].get<std::string>(),
                              p["requirements"].dump());
  s += fmt::format("reference: {} ({})\n\nDEM settings, cheapest first:\n",
                   p["reference"]["name"].get<std::string>(),
                   p["reference"]["settings"].get<std::string>());
  for (const auto& c : p["dem"]["candidates"])
    s += fmt::format("  {:<12} {:>10.3g} particle-steps {:>6.0f} s  {}\n",
                     c["name"].get<std::string>(), c["particle_steps"].get<double>(),
                     c["wall_seconds"].get<double>(), verdict(c, p["requirements"]));
  const auto& d = p["dem"]["chosen"];
  s += d.is_null()
           ? "DEM: no setting of the tradeoff meets every tolerance\n"
           : fmt::format("DEM: {} ({}), {:.3g} particle-steps, {:.0f} s\n",
                         d["name"].get<std::string>(), d["settings"].get<std::string>(),
                         d["particle_steps"].get<double>(), d["wall_seconds"].get<double>());
  std::string judged;
  for (const auto& r : p["continuum_judged_on"])
    judged += (judged.empty() ? "" : ", ") + r.get<std::string>();
  s += fmt::format("\ncontinuum models, simplest first (mean error over the scene's own runs {}, "
                   "parameters {}):\n",
                   judged, p["params"].get<std::string>());
  for (const auto& c : p["continuum"]["candidates"])
    s += fmt::format("  {:<9} {}\n            ({})\n", c["name"].get<std::string>(),
                     verdict(c, p["requirements"]), c["note"].get<std::string>());
  const auto& m = p["continuum"]["chosen"];
  s += "  (band thickness: a continuum model takes d_s as input, it does not predict it)\n";
  s += m.is_null() ? "continuum: no model meets every tolerance\n"
                   : fmt::format("continuum: {}\n", m["name"].get<std::string>());
  return s;
}

}  // namespace iwb::tradeoff
