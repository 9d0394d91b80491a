#include "claims/claims.hpp"

#include <fmt/core.h>
#include <fnmatch.h>

#include <algorithm>
#include <optional>
#include <tuple>

#include "common/errors.hpp"
#include "io/json_file.hpp"

namespace iwb::claims {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The run directories a pattern names, relative to the claims file; a '*' in the last component
// matches names (sorted, so that every machine reads the same order).
std::vector<fs::path> runs_of(const fs::path& base, const std::string& pattern, const Claim& c) {
  const fs::path p = base / pattern;
  std::vector<fs::path> out;
  if (pattern.find('*') == std::string::npos) {
    if (fs::is_directory(p)) out.push_back(p);
  } else if (fs::is_directory(p.parent_path())) {
    for (const auto& e : fs::directory_iterator(p.parent_path()))
      if (e.is_directory() && fnmatch(p.filename().c_str(), e.path().filename().c_str(), 0) == 0)
        out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  if (out.empty())
    throw InputError(fmt::format("claim '{}': \"{}\" names no run directory (under {})", c.id,
                                 pattern, base.string()));
  return out;
}

// A run's summary: summary.json of an interface run, the manifest's cell_summary of a soil cell
// (`iwb dem soiltest`; both written by the run and recomputed by `iwb dem summary`).
struct RunSummary {
  json summary;
  bool soil_cell = false;  // no wall and no plate: where its band sits is not a flag
};

RunSummary summary_of(const fs::path& run) {
  if (fs::exists(run / "summary.json") || !fs::exists(run / "manifest.json"))
    return {io::read_json_file(run / "summary.json"), false};  // its absence named as such
  const auto m = io::read_json_file(run / "manifest.json");
  if (!m.contains("cell_summary") || !m["cell_summary"].is_object())
    throw InputError(
        fmt::format("{}: neither summary.json nor a soil cell's cell_summary in "
                    "manifest.json",
                    run.string()));
  return {m["cell_summary"], true};
}

double number_at(const json& summary, const std::string& pointer, const fs::path& run) {
  const json::json_pointer at(pointer);
  if (!summary.contains(at) || !summary.at(at).is_number())
    throw InputError(fmt::format("{}: its summary has no number at {}", run.string(), pointer));
  return summary.at(at).get<double>();
}

bool flagged(const json& summary, std::string& why) {
  const auto mode = summary.value("shear_mode", std::string());
  if (mode == "split between wall and plate" || mode == "localised at the plate") {
    why = mode;
    return true;
  }
  return false;
}

// A run whose friction has not settled (summary.json's residual_is, the comparison's own rule):
// its "residual" is a point on the way down, and averaging it with settled ones compares
// different states (issue 59); left out of a claim on the residual unless the claim says it is on
// the friction at the runs' stated travel (unsteady = "include").
bool unsettled(const json& summary, const Claim& c, const std::string& quantity) {
  return quantity == "/residual_friction" && c.unsteady == "exclude" &&
         summary.value("residual_is", std::string()) != "steady";
}

// What a group reads from each run: its quantity and, for a relative change, what it is relative
// to.
struct Pointers {
  const std::string& quantity;
  const std::string& relative_to;
};

Group read_group(const fs::path& base, const std::vector<std::string>& patterns, const Claim& c,
                 const Pointers& at) {
  Group g;
  for (const auto& pattern : patterns)
    for (const auto& run : runs_of(base, pattern, c)) {
      const auto [summary, soil_cell] = summary_of(run);
      if (unsettled(summary, c, at.quantity)) {
        g.excluded.emplace_back(run.string(), "residual not steady");
        continue;
      }
      std::string why;
      if (!soil_cell && flagged(summary, why)) {
        if (c.flagged == "exclude") {
          g.excluded.emplace_back(run.string(), why);
          continue;
        }
        ++g.flagged_included;
      }
      double v = number_at(summary, at.quantity, run);
      if (!at.relative_to.empty()) {
        const double r = number_at(summary, at.relative_to, run);
        v = (v - r) / r;
      }
      g.runs.push_back(run.string());
      g.values.push_back(v);
    }
  g.sample = statistics::describe(g.values);
  return g;
}

FamilyCost cost_of(const std::vector<ClaimResult>& results) {
  std::vector<std::string> runs;
  for (const auto& r : results)
    for (const Group* g : {&r.a, &r.b}) {
      for (const auto& run : g->runs) runs.push_back(fs::path(run).lexically_normal().string());
      for (const auto& [run, why] : g->excluded)
        runs.push_back(fs::path(run).lexically_normal().string());
    }
  std::sort(runs.begin(), runs.end());
  runs.erase(std::unique(runs.begin(), runs.end()), runs.end());
  FamilyCost cost;
  cost.runs = int(runs.size());
  for (const auto& run : runs) {
    if (const auto h = engine_core_hours(fs::path(run)))
      cost.core_hours += *h;
    else
      ++cost.runs_without_record;
  }
  return cost;
}

std::string status_of(const ClaimResult& r, double q) {
  if (!r.difference) return "not testable";
  if (r.p_adjusted > q) return "not resolved";
  const double e = r.difference->effect;
  const std::string& x = r.claim.expect;
  const bool agrees =
      x == "b != a" || x == "b = a" || (x == "b > a" && e > 0.0) || (x == "b < a" && e < 0.0);
  return agrees ? "supported" : "contradicted";
}

}  // namespace

std::optional<double> engine_core_hours(const fs::path& run) {
  if (!fs::is_regular_file(run / "manifest.json")) return std::nullopt;
  return engine_core_hours(io::read_json_file(run / "manifest.json"));
}

std::optional<double> engine_core_hours(const json& m) {
  if (!m.contains("stages") || !m["stages"].is_object() || m["stages"].empty()) return std::nullopt;
  double seconds = 0.0;
  for (const auto& [name, stage] : m["stages"].items())
    if (stage.is_object() && stage.contains("wall_seconds") && stage["wall_seconds"].is_number())
      seconds += stage["wall_seconds"].get<double>();
  int processes = 1;
  if (m.contains("engine") && m["engine"].is_object() && m["engine"].contains("processes") &&
      m["engine"]["processes"].is_number_integer())
    processes = m["engine"]["processes"].get<int>();
  return seconds * processes / 3600.0;
}

ClaimsReport test_claims(const ClaimsFile& file) {
  ClaimsReport report{file, {}, {}};
  const fs::path base = file.file.has_parent_path() ? file.file.parent_path() : fs::path(".");
  std::vector<double> p;
  for (const auto& c : file.claims) {
    ClaimResult r;
    r.claim = c;
    r.a = read_group(base, c.a, c, {c.quantity, c.relative_to});
    r.b = read_group(base, c.b, c, {c.quantity_b, c.relative_to_b});
    r.difference = statistics::compare_groups(r.a.sample, r.b.sample);
    if (r.difference)
      r.p = c.equality() ? statistics::equivalence_p_value(*r.difference, c.margin)
                         : r.difference->p_value;
    report.results.push_back(r);
    if (r.difference) p.push_back(r.p);
  }
  // the family: every claim that could be tested; a claim whose p is at most q / m survives the
  // control whatever the others give, the level the seeds a group needs are counted for
  const auto adjusted = statistics::benjamini_hochberg(p);
  const double alpha = file.q / double(std::max<std::size_t>(p.size(), 1));
  std::size_t k = 0;
  for (auto& r : report.results) {
    if (r.difference) r.p_adjusted = adjusted[k++];
    r.status = status_of(r, file.q);
    if (r.status != "not resolved" || r.difference->prediction_interval) continue;
    const auto& [a, b, c] = std::tie(r.a.sample, r.b.sample, r.claim);
    r.seeds_needed =
        c.equality() ? statistics::seeds_to_show_equal(a, b, r.difference->effect, c.margin, alpha)
                     : statistics::seeds_to_resolve(a, b, r.difference->effect, alpha);
  }
  report.cost = cost_of(report.results);
  return report;
}

}  // namespace iwb::claims
