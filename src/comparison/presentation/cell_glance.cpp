#include "comparison/presentation/cell_glance.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <regex>

#include "comparison/presentation/html.hpp"
#include "comparison/replay/quantities.hpp"

namespace iwb::comparison {

namespace {

namespace fs = std::filesystem;

std::string normal(const std::string& path) {
  return fs::path(path).lexically_normal().string();
}

// The runs whose statistics judged this comparison, sorted, and the model: equal for the runs of
// one cell. A comparison without seeds is a cell of its own run.
std::string cell_key(const nlohmann::json& cmp) {
  std::vector<std::string> runs;
  if (cmp.contains("seeds") && cmp["seeds"].contains("runs"))
    for (const auto& r : cmp["seeds"]["runs"]) runs.push_back(normal(r.get<std::string>()));
  if (runs.empty()) runs.push_back(normal(cmp["dem"]["dir"].get<std::string>()));
  std::sort(runs.begin(), runs.end());
  std::string key = cmp.value("model", std::string("?"));
  for (const auto& r : runs) key += "\n" + r;
  return key;
}

int seed_count(const nlohmann::json& cmp) {
  if (cmp.contains("seeds") && cmp["seeds"].contains("runs"))
    return int(cmp["seeds"]["runs"].size());
  return 1;
}

const nlohmann::json* predicted_verdict(const nlohmann::json& cmp, const std::string& key) {
  const auto& variant = cmp["variants"][cmp["verdicts"]["predicted_variant"].get<std::size_t>()];
  for (const auto& v : variant["verdicts"])
    if (v["quantity"] == key) return &v;
  return nullptr;
}

std::string verdict_text(const nlohmann::json& v) {
  std::string text = v["verdict"].get<std::string>();
  if (text == "breaks" && v.contains("cause_if_breaks") && v["cause_if_breaks"].is_string())
    text += " (" + v["cause_if_breaks"].get<std::string>() + ")";
  return text;
}

// The cell's verdict on one quantity from its runs' (empty: judged on none of them).
std::string cell_verdict(const std::vector<const nlohmann::json*>& verdicts) {
  std::map<std::string, int> count;
  std::optional<int> seeds_needed;
  for (const auto* v : verdicts) {
    ++count[verdict_text(*v)];
    if ((*v)["verdict"] == "within DEM scatter" && v->contains("seeds_needed") &&
        (*v)["seeds_needed"].is_number())
      seeds_needed = std::max(seeds_needed.value_or(0), (*v)["seeds_needed"].get<int>());
  }
  if (count.empty()) return {};
  if (count.size() == 1) {
    std::string text = count.begin()->first;
    if (text == "within DEM scatter" && seeds_needed)
      text += fmt::format(" ({} seeds)", *seeds_needed);
    return text;
  }
  std::string text;
  for (const auto& [verdict, n] : count)
    text += fmt::format("{}{} {}", text.empty() ? "" : " · ", verdict, n);
  return text;
}

std::string seedless_label(const nlohmann::json& cmp) {
  const std::string name =
      fs::path(normal(cmp["dem"]["dir"].get<std::string>())).filename().string();
  return std::regex_replace(name, std::regex("(^|_)s[0-9]+(?=_|$)"), "$1s*");
}

CellRow start_row(const nlohmann::json& cmp) {
  CellRow row;
  row.label = seedless_label(cmp);
  row.model = cmp.value("model", std::string("?"));
  row.boundary = cmp["dem"].value("boundary", std::string("?"));
  row.R_n = cmp["dem"].value("R_n", 0.0);
  row.d50_mm = cmp["dem"].value("d50_mm", 0.0);
  return row;
}

std::string verdict_class(const std::string& text) {
  if (text.rfind("holds", 0) == 0 && text.find(" · ") == std::string::npos) return "holds";
  if (text.rfind("breaks", 0) == 0 && text.find(" · ") == std::string::npos) return "breaks";
  if (text.rfind("within DEM scatter", 0) == 0) return "scatter";
  return "";
}

}  // namespace

std::vector<CellRow> cell_rows(const std::vector<nlohmann::json>& comparisons) {
  std::vector<std::string> keys;
  std::vector<CellRow> rows;
  for (std::size_t k = 0; k < comparisons.size(); ++k) {
    const auto& cmp = comparisons[k];
    const std::string key = cell_key(cmp);
    auto it = std::find(keys.begin(), keys.end(), key);
    if (it == keys.end()) keys.push_back(key), rows.push_back(start_row(cmp)), it = keys.end() - 1;
    auto& row = rows[std::size_t(it - keys.begin())];
    row.runs.push_back(k);
    row.seeds = std::max(row.seeds, seed_count(cmp));
  }
  for (auto& row : rows) {
    double sigma = 0.0;
    for (std::size_t k : row.runs) sigma += comparisons[k]["dem"].value("sigma_n0_kPa", 0.0);
    row.sigma_n0_kPa = sigma / double(row.runs.size());
    for (const auto& q : quantity_table()) {
      std::vector<const nlohmann::json*> verdicts;
      for (std::size_t k : row.runs)
        if (const auto* v = predicted_verdict(comparisons[k], q.key)) verdicts.push_back(v);
      const std::string text = cell_verdict(verdicts);
      if (!text.empty()) row.verdicts.emplace_back(q.key, text);
    }
  }
  return rows;
}

std::string cell_glance_html(const std::vector<CellRow>& rows) {
  std::string h =
      "<table><tr><th>cell (runs)</th><th>model</th><th>boundary</th><th>R_n</th><th>d50 "
      "(mm)</th><th>sigma_n0 (kPa)</th><th>seeds</th>";
  for (const auto& q : quantity_table()) h += fmt::format("<th>{}</th>", escape_html(q.name));
  h += "</tr>\n";
  for (const auto& row : rows) {
    std::string links;
    for (std::size_t k : row.runs) links += fmt::format(" <a href=\"#run-{}\">{}</a>", k, k + 1);
    h += fmt::format(
        "<tr><td>{}<br><small>runs{}</small></td><td>{}</td><td>{}</td><td>{:g}</td><td>{:g}</td>"
        "<td>{:.0f}</td><td>{}</td>",
        escape_html(row.label), links, escape_html(row.model), escape_html(row.boundary), row.R_n,
        row.d50_mm, row.sigma_n0_kPa, row.seeds);
    for (const auto& q : quantity_table()) {
      const auto it = std::find_if(row.verdicts.begin(), row.verdicts.end(),
                                   [&](const auto& v) { return v.first == q.key; });
      if (it == row.verdicts.end()) {
        h += "<td></td>";
        continue;
      }
      const std::string cls = verdict_class(it->second);
      h += fmt::format("<td{}>{}</td>", cls.empty() ? "" : " class=\"" + cls + "\"",
                       escape_html(it->second));
    }
    h += "</tr>\n";
  }
  return h +
         "</table>\n<p>One row per cell: the runs one model was judged on with the same seed "
         "statistics (each run against the mean and scatter of its cell's seeds). Each entry is "
         "the predicted model's verdict on the cell; where its runs differ (each replays its own "
         "specimen), how many runs give each verdict. A break names its cause where a form limit "
         "judged it (form, calibration); \"within DEM scatter\" is undecided, never equal: the "
         "seeds the cell would need to decide it follow. Blank: not judged under this boundary "
         "condition. The runs, with the fitted model, follow below.</p>\n";
}

}  // namespace iwb::comparison
