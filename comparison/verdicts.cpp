#include "comparison/verdicts.hpp"

#include <cmath>

#include "comparison/quantities.hpp"
#include "io/toml_reader.hpp"

namespace iwb::comparison {

namespace {

// How many standard errors of the DEM's seed mean a miss must exceed the tolerance by to be a
// "breaks" (about 95 % that the DEM is not the cause).
constexpr double kConvictingSds = 2.0;

// The quantities that need the DEM's last rows: a model that stopped early has no value for them.
bool needs_end(const std::string& key) { return key != "peak_friction" && key != "u_x_at_peak"; }

double floor_of(const QuantityInfo& q, double d50_mm) { return q.floor_in_d50 ? q.floor * d50_mm : q.floor; }

std::string verdict_of(const Verdict& v, double scale) {
  if (!v.model || !v.error) return "not reached";
  const double miss = std::abs(*v.error) - v.tolerance;  // relative to `scale`
  if (miss <= 0.0) return "holds";
  const double standard_error = v.dem_sd ? *v.dem_sd / std::sqrt(double(v.seeds)) : 0.0;
  if (miss * scale <= kConvictingSds * standard_error) return "within DEM scatter";
  return "breaks";
}

}  // namespace

Tolerances tolerances_for(const DemRun& dem) {
  Tolerances t;
  for (const auto& k : judged_quantities(dem.boundary)) t[k] = quantity(k).tolerance;
  if (dem.scene_text.empty()) return t;
  const auto scene = io::parse_toml_text(dem.scene_text, (dem.dir / "manifest.json").string() + " /scene/text");
  const auto* req = scene["requirements"].as_table();
  if (req == nullptr) return t;
  io::TableReader reader(*req, (dem.dir / "manifest.json").string() + " /scene/text", "requirements");
  for (const auto& k : judged_quantities(dem.boundary))
    if (const auto tol = io::read_tolerance(reader, k)) {
      if (*tol)
        t[k] = **tol;
      else
        t.erase(k);  // "not needed"
    }
  return t;
}

std::vector<Verdict> judge(const DemRun& dem, const SeedScatter& scatter, const Replay& r,
                           const Tolerances& tolerances) {
  std::vector<std::string> keys;
  for (const auto& [k, tol] : tolerances) keys.push_back(k);
  const auto d = evaluate_quantities({dem.u_x_mm, dem.tau_kPa, dem.sigma_n_kPa, dem.u_n_mm}, keys);
  const auto m = evaluate_quantities({r.u_x_mm, r.tau_kPa, r.sigma_n_kPa, r.u_n_mm}, keys);
  const bool reached_end = r.u_x_mm.size() == dem.u_x_mm.size();
  std::vector<Verdict> out;
  for (const auto& q : quantity_table()) {
    if (!tolerances.count(q.key)) continue;
    Verdict v{q.key, d.at(q.key), std::nullopt, scatter.runs.empty() ? 1 : scatter.runs.size(),
              m.at(q.key), std::nullopt, tolerances.at(q.key), ""};
    if (scatter.from_seeds() && scatter.quantity_sd.count(q.key)) {  // the seed mean is the DEM's value
      v.dem = scatter.quantity_mean.at(q.key);
      v.dem_sd = scatter.quantity_sd.at(q.key);
    }
    if (needs_end(q.key) && !reached_end) v.model = std::nullopt;
    const double scale = v.dem ? std::max(std::abs(*v.dem), floor_of(q, dem.d50_mm)) : 1.0;
    if (v.model && v.dem) v.error = (*v.model - *v.dem) / scale;
    v.verdict = verdict_of(v, scale);
    out.push_back(v);
  }
  return out;
}

bool all_hold(const std::vector<Verdict>& verdicts) { return failing(verdicts).empty(); }

std::vector<std::string> failing(const std::vector<Verdict>& verdicts) {
  std::vector<std::string> f;
  for (const auto& v : verdicts)
    if (v.verdict != "holds") f.push_back(v.key);
  return f;
}

nlohmann::json to_json(const std::vector<Verdict>& verdicts) {
  auto opt = [](const std::optional<double>& x) { return x ? nlohmann::json(*x) : nlohmann::json(nullptr); };
  nlohmann::json out = nlohmann::json::array();
  for (const auto& v : verdicts) {
    const auto& q = quantity(v.key);
    out.push_back({{"quantity", v.key}, {"name", q.name}, {"unit", q.unit}, {"dem", opt(v.dem)},
                   {"dem_seed_sd", opt(v.dem_sd)}, {"seeds", v.seeds}, {"model", opt(v.model)},
                   {"relative_error", opt(v.error)}, {"tolerance", v.tolerance}, {"verdict", v.verdict}});
  }
  return out;
}

}  // namespace iwb::comparison
