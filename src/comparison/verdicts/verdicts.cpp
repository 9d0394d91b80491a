#include "comparison/verdicts/verdicts.hpp"

#include <fmt/core.h>

#include <cmath>

#include "comparison/replay/quantities.hpp"
#include "io/toml_reader.hpp"
#include "statistics/t_interval.hpp"

namespace iwb::comparison {

namespace {

// The seeds a verdict needs: a t-interval of the mean at most this share of the tolerance wide
// (half-width), so that its detection limit lies within 1.5 times the tolerance.
constexpr double kResolvedShareOfTolerance = 0.5;
constexpr int kMostSeedsWorthSaying = 1000;

// The quantities read over the last fifth of the travel or at its end: a residual that still
// drifts there makes them depend on where the run stopped.
bool needs_steady_end(const std::string& key) {
  return key == "residual_friction" || key == "dilation_rate" || key == "total_dilation" ||
         key == "wall_zone_dilation";
}

// The quantities that need the DEM's last rows: a model that stopped early has no value for them.
bool needs_end(const std::string& key) {
  return key != "peak_friction" && key != "u_x_at_peak";
}

double floor_of(const QuantityInfo& q, double d50_mm) {
  return q.floor_in_d50 ? q.floor * d50_mm : q.floor;
}

// What the verdict rests on: the t-interval, the detection limit, the seeds the tolerance needs.
void add_statistics(Verdict& v, double scale, std::optional<int> dof) {
  const SeedInterval i = seed_interval(v.dem_sd, v.seeds, v.tolerance, scale, dof);
  v.dem_ci = i.ci, v.detection_limit = i.detection_limit, v.seeds_needed = i.seeds_needed;
}

std::vector<std::string> notes_for(const std::string& key, const SeedScatter& scatter) {
  std::vector<std::string> notes;
  const std::size_t n = scatter.runs.size();
  if (!scatter.left_out.empty())
    notes.push_back(fmt::format("{} of {} runs left out: localised at the plate",
                                scatter.left_out.size(), n + scatter.left_out.size()));
  if (scatter.only_plate_runs)
    notes.push_back("every run localised at the plate: the DEM measured the plate");
  if (!scatter.split.empty())
    notes.push_back(
        fmt::format("{} of {} runs split between wall and plate", scatter.split.size(), n));
  if (needs_steady_end(key) && !scatter.not_steady.empty())
    notes.push_back(fmt::format(
        "{} of {} runs not steady at the end (friction not settled over the last fifth)",
        scatter.not_steady.size(), n));
  return notes;
}

// A residual is judged only where every run it rests on has settled, an extrapolation only where
// every run and the model resolve it (issue 59): anything else would judge a number that is not
// the state the model is meant to reach.
void unjudged(Verdict& v, const SeedScatter& scatter) {
  if (v.key == "residual_friction" && !scatter.not_steady.empty()) {
    v.verdict = "not steady";
    v.notes.push_back(
        fmt::format("not judged: the friction of {} of {} runs had not settled over the last fifth "
                    "(statistics/steady_state.hpp); shear further, or read critical_state_friction",
                    scatter.not_steady.size(), std::max<std::size_t>(1, scatter.runs.size())));
  }
  if (!is_extrapolated(v.key)) return;
  v.notes.push_back("extrapolated: the decay fitted after the peak, beyond the run's end");
  const auto values = scatter.quantity_values.find(v.key);
  const std::size_t resolved = values == scatter.quantity_values.end() ? 0 : values->second.size();
  const std::size_t runs = std::max<std::size_t>(1, scatter.runs.size());
  if (!v.dem || !v.model || (scatter.from_seeds() && resolved < runs)) {
    v.verdict = "not resolved";
    v.notes.push_back(fmt::format("the decay is resolved in {} of {} runs{}", resolved, runs,
                                  v.model ? "" : " and not in the model's replay"));
  }
}

}  // namespace

Tolerances scene_tolerances(const DemRun& dem, Tolerances defaults) {
  if (dem.scene_text.empty()) return defaults;
  const auto where = (dem.dir / "manifest.json").string() + " /scene/text";
  const auto scene = io::parse_toml_text(dem.scene_text, where);
  const auto* req = scene["requirements"].as_table();
  if (req == nullptr) return defaults;
  io::TableReader reader(*req, where, "requirements");
  Tolerances t = defaults;
  for (const auto& [k, tolerance] : defaults)
    if (const auto tol = io::read_tolerance(reader, k)) {
      if (*tol)
        t[k] = **tol;
      else
        t.erase(k);  // "not needed"
    }
  return t;
}

Tolerances tolerances_for(const DemRun& dem) {
  Tolerances t;
  for (const auto& k : judged_quantities(dem.boundary, dem.cyclic())) t[k] = quantity(k).tolerance;
  return scene_tolerances(dem, t);
}

std::vector<Verdict> judge(const DemRun& dem, const SeedScatter& scatter, const Replay& r,
                           const Tolerances& tolerances) {
  std::vector<std::string> keys;
  for (const auto& [k, tol] : tolerances) keys.push_back(k);
  const auto d = evaluate_quantities(
      {dem.u_x_mm, dem.tau_kPa, dem.sigma_n_kPa, dem.u_n_mm, &dem.e_band, dem.wall_zone_mm}, keys);
  const auto m = evaluate_quantities(
      {r.u_x_mm, r.tau_kPa, r.sigma_n_kPa, r.u_n_mm, &r.e_band, dem.wall_zone_mm}, keys);
  const bool reached_end = r.u_x_mm.size() == dem.u_x_mm.size();
  std::vector<Verdict> out;
  for (const auto& q : quantity_table()) {
    if (!tolerances.count(q.key)) continue;
    Verdict v{q.key,
              d.at(q.key),
              std::nullopt,
              scatter.runs.empty() ? 1 : scatter.runs.size(),
              m.at(q.key),
              std::nullopt,
              tolerances.at(q.key),
              "",
              std::nullopt,
              std::nullopt,
              std::nullopt,
              {}};
    if (scatter.from_seeds() &&
        scatter.quantity_sd.count(q.key)) {  // the seed mean is the DEM's value
      v.dem = scatter.quantity_mean.at(q.key);
      v.dem_sd = scatter.quantity_sd.at(q.key);
    }
    if (needs_end(q.key) && !reached_end) v.model = std::nullopt;
    const double scale = v.dem ? std::max(std::abs(*v.dem), floor_of(q, dem.d50_mm)) : 1.0;
    if (v.model && v.dem) v.error = (*v.model - *v.dem) / scale;
    const auto dof = scatter.quantity_dof.find(q.key);
    add_statistics(v, scale,
                   dof == scatter.quantity_dof.end() ? std::nullopt : std::optional(dof->second));
    v.notes = notes_for(q.key, scatter);
    if (const auto note = scatter.quantity_note.find(q.key); note != scatter.quantity_note.end())
      v.notes.push_back(note->second);
    v.verdict = verdict_word(v.model ? v.error : std::nullopt, v.tolerance, scale, v.dem_ci);
    unjudged(v, scatter);
    out.push_back(v);
  }
  return out;
}

SeedInterval seed_interval(std::optional<double> sd, std::size_t seeds, double tolerance,
                           double scale, std::optional<int> dof) {
  SeedInterval i{std::nullopt, tolerance, std::nullopt};
  if (!sd) return i;
  const double target = kResolvedShareOfTolerance * tolerance * scale;
  if (dof) {  // a pooled SD: t with its own degrees of freedom, whatever the cell's seeds
    const double t = statistics::t_quantile(*dof);
    if (seeds >= 2) i.ci = t * *sd / std::sqrt(double(seeds));
    for (int n = 2; n <= kMostSeedsWorthSaying && !i.seeds_needed && *sd > 0.0; ++n)
      if (t * *sd / std::sqrt(double(n)) <= target) i.seeds_needed = n;
  } else {
    i.ci = statistics::t_half_width(*sd, int(seeds));
    i.seeds_needed = statistics::values_needed(*sd, target, kMostSeedsWorthSaying);
  }
  if (i.ci) i.detection_limit = tolerance + *i.ci / scale;
  return i;
}

std::string verdict_word(std::optional<double> error, double tolerance, double scale,
                         std::optional<double> ci) {
  if (!error) return "not reached";
  const double miss = std::abs(*error) - tolerance;  // relative to `scale`
  if (miss <= 0.0) return "holds";
  if (miss * scale <= ci.value_or(0.0)) return "within DEM scatter";
  return "breaks";
}

bool all_hold(const std::vector<Verdict>& verdicts) {
  return failing(verdicts).empty();
}

std::vector<std::string> failing(const std::vector<Verdict>& verdicts) {
  std::vector<std::string> f;
  for (const auto& v : verdicts)
    if (v.verdict != "holds") f.push_back(v.key);
  return f;
}

nlohmann::json to_json(const std::vector<Verdict>& verdicts) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& v : verdicts) {
    const auto& q = quantity(v.key);
    auto j = shared_verdict_json(v);
    j["quantity"] = v.key;
    j["name"] = q.name;
    j["unit"] = q.unit;
    j["notes"] = v.notes;
    out.push_back(j);
  }
  return out;
}

}  // namespace iwb::comparison
