#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "claims/claims.hpp"
#include "common/errors.hpp"
#include "io/run_directory.hpp"

namespace iwb::claims {

using nlohmann::json;

namespace {

json group_json(const Group& g) {
  json excluded = json::array();
  for (const auto& [run, why] : g.excluded) excluded.push_back({{"run", run}, {"why", why}});
  return {{"runs", g.runs},
          {"values", g.values},
          {"n", g.sample.n},
          {"mean", g.sample.mean},
          {"sd", g.sample.sd},
          {"excluded", excluded},
          {"flagged_included", g.flagged_included}};
}

int resolved_count(const ClaimsReport& report) {
  return int(std::count_if(report.results.begin(), report.results.end(), [](const ClaimResult& r) {
    return r.status == "supported" || r.status == "contradicted";
  }));
}

// What the family's runs cost and what it resolved for it (issue 59 item 4).
std::string cost_line(const ClaimsReport& report) {
  const auto& c = report.cost;
  const int resolved = resolved_count(report);
  std::string line = fmt::format(
      "The family's {} runs cost {:.1f} engine core-hours at least, as their manifests record "
      "(each stage's last attempt, times its ranks){}: ",
      c.runs, c.core_hours,
      c.runs_without_record > 0 ? fmt::format(", {} without a record", c.runs_without_record)
                                : std::string());
  if (resolved == 0) return line + "no claim resolved.\n\n";
  return line + fmt::format("{:.1f} core-hours per resolved claim ({} resolved).\n\n",
                            c.core_hours / resolved, resolved);
}

std::string mean_sd(const Group& g) {
  if (g.sample.n == 1) return fmt::format("{:.4g} (1 run)", g.sample.mean);
  return fmt::format("{:.4g} ± {:.2g} SD", g.sample.mean, g.sample.sd);
}

std::string runs_cell(const Group& g) {
  std::string s = std::to_string(g.sample.n);
  if (!g.excluded.empty()) s += fmt::format(" ({} excluded)", g.excluded.size());
  if (g.flagged_included > 0) s += fmt::format(" ({} flagged, kept)", g.flagged_included);
  return s;
}

}  // namespace

json to_json(const ClaimsReport& report) {
  json claims = json::array();
  for (const auto& r : report.results) {
    json c = {
        {"id", r.claim.id},
        {"says", r.claim.says},
        {"quantity", r.claim.quantity},
        {"relative_to", r.claim.relative_to.empty() ? json() : json(r.claim.relative_to)},
        {"quantity_b", r.claim.quantity_b},
        {"relative_to_b", r.claim.relative_to_b.empty() ? json() : json(r.claim.relative_to_b)},
        {"expect", r.claim.expect},
        {"margin", r.claim.equality() ? json(r.claim.margin) : json()},
        {"flagged", r.claim.flagged},
        {"a", group_json(r.a)},
        {"b", group_json(r.b)},
        {"status", r.status},
        {"p", r.difference ? json(r.p) : json()},
        {"p_adjusted", r.difference ? json(r.p_adjusted) : json()},
        {"seeds_needed", r.seeds_needed ? json(*r.seeds_needed) : json()}};
    if (r.difference)
      c["difference"] = {{"effect", r.difference->effect},
                         {"half_width_95", r.difference->half_width},
                         {"degrees_of_freedom", r.difference->degrees_of_freedom},
                         {"p_welch", r.difference->p_value},
                         {"test", r.difference->prediction_interval
                                      ? "one run against the group's prediction interval"
                                      : "Welch's t-test"}};
    claims.push_back(c);
  }
  return {{"kind", "claims"},
          {"file", report.file.file.string()},
          {"q", report.file.q},
          {"control", "Benjamini-Hochberg over every testable claim of the file"},
          {"claims", claims},
          {"cost",
           {{"runs", report.cost.runs},
            {"runs_without_record", report.cost.runs_without_record},
            {"engine_core_hours", report.cost.core_hours},
            {"resolved_claims", resolved_count(report)}}}};
}

std::string markdown(const ClaimsReport& report) {
  std::map<std::string, int> count;
  std::size_t tested = 0;
  for (const auto& r : report.results) ++count[r.status], tested += r.difference ? 1 : 0;
  std::string tally;
  for (const auto& [status, n] : count)
    tally += fmt::format("{}{} {}", tally.empty() ? "" : ", ", n, status);
  std::string md = fmt::format(
      "{} claims, tested by `iwb claims {}` (Welch's t-test, or one run against a group's 95 % "
      "prediction interval; Benjamini-Hochberg over the {} at q = {:g}; effects b - a with their "
      "95 % interval; runs split between wall and plate or at the plate handled as each claim "
      "says; the seeds a group would need: those at which the measured effect and scatter give p "
      "at most q / {}, which survives the control whatever the others give): {}.\n\n",
      report.results.size(), report.file.file.filename().string(), tested, report.file.q, tested,
      tally);
  if (std::any_of(report.results.begin(), report.results.end(),
                  [](const ClaimResult& r) { return r.claim.equality(); }))
    md +=
        "A claim of equality (\"equal within ...\") is tested by two one-sided tests at its "
        "margin (Schuirmann 1987), the one test whose small p shows the groups equal; its "
        "status \"not resolved\" shows neither equality nor a difference.\n\n";
  md += cost_line(report) +
        "| claim | says | runs a, b | a | b | b - a (95 %) | p | p, BH | status |\n"
        "|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : report.results) {
    const auto& d = r.difference;
    std::string status = r.status;
    if (r.seeds_needed)
      status += fmt::format(" ({} seeds a group would resolve it)", *r.seeds_needed);
    else if (r.status == "not resolved" && d && r.claim.equality() &&
             !(std::abs(d->effect) < r.claim.margin))
      status += " (the measured difference is outside the margin: no count of seeds shows it)";
    else if (r.status == "not resolved" && d && !d->prediction_interval)
      status += " (not within 1000 seeds a group)";
    const std::string says =
        r.claim.says +
        (r.claim.equality() ? fmt::format(" (equal within ±{:g})", r.claim.margin) : std::string());
    md += fmt::format("| {} | {} (flagged runs: {}) | {}, {} | {} | {} | {} | {} | {} | {} |\n",
                      r.claim.id, says, r.claim.flagged, runs_cell(r.a), runs_cell(r.b),
                      mean_sd(r.a), mean_sd(r.b),
                      d ? fmt::format("{:+.3g} ± {:.2g}", d->effect, d->half_width) : "-",
                      d ? fmt::format("{:.2g}", r.p) : "-",
                      d ? fmt::format("{:.2g}", r.p_adjusted) : "-", status);
  }
  return md;
}

std::string readme_with_block(const std::filesystem::path& readme, const std::string& name,
                              const std::string& block) {
  const std::string text = io::read_file(readme);
  const std::string begin = fmt::format("<!-- BEGIN claims: {} -->", name),
                    end = "<!-- END claims -->";
  const auto b = text.find(begin);
  const auto e = b == std::string::npos ? b : text.find(end, b);
  if (e == std::string::npos)
    throw InputError(fmt::format("{}: no claims block ({} ... {})", readme.string(), begin, end));
  return text.substr(0, b + begin.size()) + "\n" + block + text.substr(e);
}

}  // namespace iwb::claims
