// hypotheses.json and hypotheses.md: every number of the checks, and per check a table of strings
// that the markdown and the HTML report print as they are (one place decides the formatting).
#include <fmt/core.h>

#include "comparison/compare/hypotheses.hpp"

namespace iwb::comparison {

namespace {

using nlohmann::json;

json scatter_json(const Scatter& s) {
  return {{"n", s.n}, {"mean", s.mean}, {"sd", s.sd}};
}

std::string pm_cell(const Scatter& s, int digits) {
  return s.n > 1 ? fmt::format("{:.{}f} ± {:.{}f}", s.mean, digits, s.sd, digits)
                 : fmt::format("{:.{}f}", s.mean, digits);
}

std::string opt_cell(const std::optional<double>& x, const char* unit) {
  return x ? fmt::format("{:+.1f}{}", *x, unit) : std::string("-");
}

json kappa_json(const KappaCheck& c) {
  json groups = json::array(), rows = json::array();
  for (const auto& g : c.groups) {
    json bases = json::array();
    for (const auto& b : g.bases)
      bases.push_back({{"log_base", b.base},
                       {"formula", b.formula},
                       {"difference", b.difference},
                       {"in_scatter", b.in_scatter ? json(*b.in_scatter) : json(nullptr)},
                       {"follows", b.follows}});
    groups.push_back({{"R_n", g.R_n},
                      {"runs", g.runs},
                      {"fit", scatter_json(g.fit)},
                      {"scatter", g.scatter},
                      {"bases", bases}});
    std::vector<std::string> row = {fmt::format("{:.3g}", g.R_n), std::to_string(g.fit.n),
                                    pm_cell(g.fit, 3)};
    for (const auto& b : g.bases)
      row.insert(row.end(), {fmt::format("{:.3f}", b.formula), fmt::format("{:+.3f}", b.difference),
                             opt_cell(b.in_scatter, " SD"), b.follows ? "follows" : "misses"});
    rows.push_back(row);
  }
  return {
      {"id", "kappa_r_vs_gutjahr"},
      {"title", "Fitted kappa_r against Gutjahr's kappa_r(R_n), eq. 5.35"},
      {"assumption",
       "kappa_r = min(1, 0.25 log(R_n) + 1.05), floor 0.05; log base 10 (our reading) and e"},
      {"outcome", {{"log_base_10", c.outcome[0]}, {"log_base_e", c.outcome[1]}}},
      {"verdict", c.verdict[0] + ". " + c.verdict[1] + ". " + c.verdict_overall + "."},
      {"groups", groups},
      {"table",
       {{"columns",
         {"R_n", "runs", "fitted kappa_r", "lg: formula", "lg: fit - formula", "lg: in scatter",
          "lg", "ln: formula", "ln: fit - formula", "ln: in scatter", "ln"}},
        {"rows", rows}}},
      {"notes",
       fmt::format(
           "Scatter = sqrt(SD over seeds^2 + mean fit sigma^2); within scatter means |difference| "
           "<= {:g} of it, or |difference| <= {:g} (below the DEM's friction resolution). A single "
           "run "
           "at an R_n has no seed scatter: it follows when within {:g} in absolute terms.",
           kWithinScatter, kKappaResolution, kKappaSingleRunTolerance)}};
}

json band_json(const BandCheck& c, const std::vector<RunRecord>& runs) {
  json rows = json::array();
  for (const auto& r : runs)
    rows.push_back(
        {r.name, fmt::format("{:.3g}", r.R_n), fmt::format("{:g}", r.d50_mm), r.shear_mode,
         r.band_d50 && r.shear_mode != "distributed shear" ? fmt::format("{:.2f}", *r.band_d50)
                                                           : "-",
         fmt::format("{:.1f}", r.d_s_fit_d50)});
  json bands = json::array();
  for (const auto& [name, b] : c.bands) bands.push_back({{"run", name}, {"band_d50", b}});
  json groups = json::array(), group_rows = json::array();
  for (const auto& g : c.groups) {
    groups.push_back({{"R_n", g.R_n},
                      {"d50_mm", g.d50_mm},
                      {"runs", g.runs},
                      {"band", scatter_json(g.band)},
                      {"inside", g.inside},
                      {"without_band", g.without_band}});
    group_rows.push_back({fmt::format("{:.3g}", g.R_n), fmt::format("{:g}", g.d50_mm),
                          std::to_string(g.runs.size()), g.band.n > 0 ? pm_cell(g.band, 2) : "-",
                          fmt::format("{} of {}", g.inside, g.band.n),
                          std::to_string(g.without_band)});
  }
  return {{"id", "band_thickness"},
          {"title", "Band thickness against d_s = k d50, k in [5, 10]"},
          {"assumption",
           fmt::format("the DEM's wall band (summary.json wall_band_d50) lies in [{:g}, {:g}] d50",
                       kBandMinD50, kBandMaxD50)},
          {"outcome", c.outcome},
          {"verdict", c.verdict + "."},
          {"bands", bands},
          {"band", scatter_json(c.band)},
          {"inside", c.inside},
          {"distributed", c.distributed},
          {"without_wall_band", c.without_wall_band},
          {"d_s_fit_d50", scatter_json(c.d_s_fit_d50)},
          {"groups", groups},
          {"group_table",
           {{"columns",
             {"R_n", "d50 (mm)", "runs", "wall band (d50): mean ± SD over seeds",
              fmt::format("inside [{:g}, {:g}]", kBandMinD50, kBandMaxD50),
              "distributed or no wall band"}},
            {"rows", group_rows}}},
          {"table",
           {{"columns",
             {"run", "R_n", "d50 (mm)", "shear mode", "wall band (d50)", "fitted d_s (d50)"}},
            {"rows", rows}}}};
}

json collapse_json(const CollapseCheck& c) {
  json groups = json::array(), rows = json::array();
  for (const auto& g : c.groups) {
    json qs = json::array();
    for (const auto& q : g.quantities) {
      json sets = json::array();
      std::string cells;
      for (const auto& s : q.sets) {
        sets.push_back({{"d50_mm", s.d50_mm}, {"value", scatter_json(s.value)}});
        cells +=
            fmt::format("{}{:g} mm: {}", cells.empty() ? "" : "; ", s.d50_mm, pm_cell(s.value, 3));
      }
      qs.push_back({{"quantity", q.quantity},
                    {"sets", sets},
                    {"difference", q.difference},
                    {"pooled_sd", q.pooled_sd},
                    {"dof", q.dof},
                    {"in_scatter", q.in_scatter ? json(*q.in_scatter) : json(nullptr)},
                    {"resolution", q.resolution},
                    {"collapses", q.collapses}});
      rows.push_back(
          {fmt::format("{:.3g}", g.R_n), q.quantity, cells, fmt::format("{:.3f}", q.difference),
           q.in_scatter ? fmt::format("{:.1f} SE (pooled SD {:.3f})", *q.in_scatter, q.pooled_sd)
                        : fmt::format("no seed scatter (resolution {:g})", q.resolution),
           q.collapses ? "collapses" : "does not collapse"});
    }
    if (g.quantities.empty())
      rows.push_back({fmt::format("{:.3g}", g.R_n), "-",
                      fmt::format("one d50 ({:g} mm)", g.d50s_mm.front()), "-", "-",
                      "not testable"});
    groups.push_back(
        {{"R_n", g.R_n}, {"d50s_mm", g.d50s_mm}, {"quantities", qs}, {"collapses", g.collapses}});
  }
  return {
      {"id", "d50_collapse"},
      {"title", "Same R_n at different d50: same friction and dilation"},
      {"assumption", "normalising roughness by d50 collapses results (DEM.md)"},
      {"outcome", c.outcome},
      {"verdict", c.verdict},
      {"groups", groups},
      {"table",
       {{"columns",
         {"R_n", "quantity", "per d50: mean ± SD over seeds", "largest difference",
          "against scatter", "verdict"}},
        {"rows", rows}}},
      {"notes",
       fmt::format(
           "Dilation as u_n at the end over d50: if the band scales with d50 and reaches the same "
           "critical void ratio, u_n/d50 is equal for every d50 and independent of how far each "
           "run "
           "was sheared; the dilatancy rate is ~0 at the critical state for every run and cannot "
           "tell. Collapses when the largest difference of set means is within {:g} standard "
           "errors "
           "of the pooled seed scatter, or below the resolution ({:g} in friction, {:g} in "
           "u_n/d50).",
           kWithinScatter, kFrictionResolution, kDilationResolutionD50)}};
}

json record_json(const RunRecord& r) {
  return {{"name", r.name},
          {"R_n", r.R_n},
          {"d50_mm", r.d50_mm},
          {"kappa_r_fit", r.kappa_r_fit},
          {"sigma_kappa_r_fit", r.sigma_kappa_r_fit},
          {"d_s_fit_d50", r.d_s_fit_d50},
          {"peak_friction", r.peak_friction},
          {"residual_friction", r.residual_friction},
          {"dilation_mm", r.dilation_mm},
          {"shear_mode", r.shear_mode},
          {"band_d50", r.band_d50 ? json(*r.band_d50) : json(nullptr)}};
}

std::string markdown_table(const json& t) {
  // fmt rather than string operator+: GCC 12 warns falsely (-Wrestrict) on " " + s + " |"
  std::string s = "|", rule = "|";
  for (const auto& c : t["columns"])
    s += fmt::format(" {} |", c.get<std::string>()), rule += "---|";
  s += fmt::format("\n{}\n", rule);
  for (const auto& row : t["rows"]) {
    s += "|";
    for (const auto& cell : row) s += fmt::format(" {} |", cell.get<std::string>());
    s += "\n";
  }
  return s;
}

}  // namespace

json to_json(const Hypotheses& h, const std::vector<RunRecord>& runs) {
  json records = json::array();
  for (const auto& r : runs) records.push_back(record_json(r));
  return {{"runs", records},
          {"checks", {kappa_json(h.kappa), band_json(h.band, runs), collapse_json(h.collapse)}}};
}

std::string to_markdown(const json& h) {
  std::string s = fmt::format("# Hypothesis checks over {} DEM run(s)\n", h["runs"].size());
  int k = 0;
  for (const auto& c : h["checks"]) {
    s += fmt::format("\n## {}. {}\n\nAssumption: {}.\n\n**Verdict:** {}\n\n", ++k,
                     c["title"].get<std::string>(), c["assumption"].get<std::string>(),
                     c["verdict"].get<std::string>());
    if (c.contains("group_table")) s += markdown_table(c["group_table"]) + "\n";
    s += markdown_table(c["table"]);
    if (c.contains("notes")) s += fmt::format("\n{}\n", c["notes"].get<std::string>());
  }
  return s;
}

}  // namespace iwb::comparison
