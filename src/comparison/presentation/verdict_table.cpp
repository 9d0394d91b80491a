#include "comparison/presentation/verdict_table.hpp"

#include <fmt/core.h>

#include <algorithm>

namespace iwb::comparison {

using nlohmann::json;

namespace {

// A value in its unit with digits that suit it: frictions and rates to 3 decimals, lengths to
// 3 significant digits, stresses to 0.1 kPa.
std::string value(const json& v, const std::string& unit) {
  if (!v.is_number()) return "-";
  const double x = v.get<double>();
  if (unit == "kPa") return fmt::format("{:.1f} kPa", x);
  if (unit == "mm") return fmt::format("{:.3g} mm", x);
  return fmt::format("{:.3f}", x);
}

// The DEM's value with the 95 % t-interval of its seed mean, the seeds it rests on and those its
// tolerance needs (comparison/verdicts/verdicts.hpp).
std::string with_interval(const json& verdict) {
  const std::string unit = verdict["unit"];
  if (!verdict["dem_t_interval_95"].is_number()) return value(verdict["dem"], unit) + " (1 run)";
  const std::string ci = value(verdict["dem_t_interval_95"], unit);
  const json& needed = verdict["seeds_needed"];
  const std::string need = needed.is_number() ? fmt::format("; {} needed", needed.get<int>()) : "";
  return fmt::format("{} ± {} (95 % t, {} seeds{})", value(verdict["dem"], unit),
                     ci.substr(0, ci.find(' ')), verdict["seeds"].get<std::size_t>(), need);
}

std::string tolerance_percent(const json& x) {
  return x.is_number() ? fmt::format("{:.0f} %", 100 * x.get<double>()) : "-";
}

std::string model_cell(const json& verdict) {
  if (!verdict["model"].is_number())
    return verdict.value("verdict", "") == "not resolved" ? "not resolved" : "not reached";
  const std::string unit = verdict["unit"];
  if (!verdict["relative_error"].is_number())  // the DEM did not resolve it (an extrapolation)
    return value(verdict["model"], unit);
  return fmt::format("{} ({:+.0f} %)", value(verdict["model"], unit),
                     100 * verdict["relative_error"].get<double>());
}

std::string holds_list(const json& s) {
  std::string out;
  for (const auto& q : s) out += (out.empty() ? "" : ", ") + q.get<std::string>();
  return out.empty() ? "none" : out;
}

// Where the joint fit stops on the box's bound, the data ask for more than the model allows.
std::string bound_note(const json& fit) {
  if (!fit.contains("at_bound") || fit["at_bound"].empty())
    return "The joint fit's optimum is inside the box.";
  std::string which;
  for (const auto& b : fit["at_bound"])
    which += (which.empty() ? "" : " and ") + b.get<std::string>();
  return fmt::format(
      "The joint fit stops on the bound of {}: the DEM asks for more than the model's range allows "
      "(kappa_r <= 1 is fully rough).",
      which);
}

// What the verdicts rest on: the detection limit's meaning and each note once (runs left out,
// residuals still drifting).
std::string statistics_note(const json& verdicts) {
  std::vector<std::string> notes;
  for (const auto& v : verdicts)
    for (const auto& n : v.value("notes", json::array())) {
      const std::string text = v["name"].get<std::string>() + ": " + n.get<std::string>();
      if (std::find(notes.begin(), notes.end(), text) == notes.end()) notes.push_back(text);
    }
  std::string out =
      "'detects': the smallest relative error the DEM can call 'breaks' (the tolerance plus the "
      "95 % t-interval of its seed mean).";
  for (const auto& n : notes) out += " " + n + ".";
  return out;
}

}  // namespace

// "breaks (form)", "breaks (calibration)" where a form-limit record said which (issue 38).
std::string with_cause(const json& verdict) {
  const std::string word = verdict["verdict"];
  return verdict.contains("cause") ? word + " (" + verdict["cause"].get<std::string>() + ")" : word;
}

Table verdict_table(const json& cmp) {
  Table t{{"quantity", "DEM", "predicted model", "fitted model", "tolerance", "detects",
           "predicted", "fitted"},
          {}};
  const auto& v = cmp["variants"];
  const auto& pred = v[cmp["verdicts"]["predicted_variant"].get<std::size_t>()]["verdicts"];
  const auto& fit = v[cmp["verdicts"]["fitted_variant"].get<std::size_t>()]["verdicts"];
  for (std::size_t i = 0; i < pred.size(); ++i) {
    const auto& p = pred[i];
    const std::string unit = p["unit"];
    t.rows.push_back({p["name"].get<std::string>() + (unit.empty() ? "" : " (" + unit + ")"),
                      with_interval(p), model_cell(p), model_cell(fit[i]),
                      tolerance_percent(p["tolerance"]), tolerance_percent(p["detection_limit"]),
                      with_cause(p), with_cause(fit[i])});
  }
  return t;
}

namespace {

// The cyclic verdicts of a comparison's predicted or fitted variant (empty for a monotonic run).
const json& cyclic_verdicts_of(const json& cmp, const char* which) {
  static const json none = json::array();
  const auto& variant = cmp["variants"][cmp["verdicts"][which].get<std::size_t>()];
  return variant.contains("cyclic") ? variant["cyclic"]["verdicts"] : none;
}

std::string cyclic_cell(const json& x) {
  if (!x["model"].is_number()) return std::string("not reached");
  return fmt::format("{:.3g} ({:+.0f} %)", x["model"].get<double>(),
                     100 * x["relative_error"].get<double>());
}

}  // namespace

Table cyclic_models_table(const std::vector<json>& comparisons) {
  Table t{{"quantity", "where", "DEM"}, {}};
  if (comparisons.empty()) return t;
  const auto& first = cyclic_verdicts_of(comparisons.front(), "predicted_variant");
  for (const auto& c : comparisons)
    for (const char* which : {"predicted", "fitted"})
      t.columns.push_back(c["model"].get<std::string>() + " " + which);
  for (const auto& row : first) {
    std::vector<std::string> cells = {row["quantity"], row["where"],
                                      row["dem"].is_number() ? with_interval(row) : "-"};
    for (const auto& c : comparisons)
      for (const char* which : {"predicted_variant", "fitted_variant"}) {
        const auto& verdicts = cyclic_verdicts_of(c, which);
        const auto same = std::find_if(verdicts.begin(), verdicts.end(), [&](const json& x) {
          return x["quantity"] == row["quantity"] && x["where"] == row["where"];
        });
        cells.push_back(same == verdicts.end()
                            ? "-"
                            : cyclic_cell(*same) + " " + (*same)["verdict"].get<std::string>());
      }
    t.rows.push_back(cells);
  }
  return t;
}

Table cyclic_verdict_table(const json& cmp) {
  Table t{{"quantity", "where", "DEM", "predicted model", "fitted model", "tolerance", "detects",
           "predicted", "fitted"},
          {}};
  const auto& p = cyclic_verdicts_of(cmp, "predicted_variant");
  const auto& f = cyclic_verdicts_of(cmp, "fitted_variant");
  for (std::size_t i = 0; i < p.size(); ++i)
    t.rows.push_back({p[i]["quantity"].get<std::string>(), p[i]["where"].get<std::string>(),
                      p[i]["dem"].is_number() ? with_interval(p[i]) : "-", cyclic_cell(p[i]),
                      cyclic_cell(f[i]), tolerance_percent(p[i]["tolerance"]),
                      tolerance_percent(p[i]["detection_limit"]),
                      p[i]["verdict"].get<std::string>(), f[i]["verdict"].get<std::string>()});
  return t;
}

std::vector<std::string> verdict_findings(const json& cmp) {
  const auto& s = cmp["verdicts"]["summary"];
  const auto& v = cmp["variants"];
  const auto label = [&](const char* which) {
    return v[cmp["verdicts"][which].get<std::size_t>()]["label"].get<std::string>();
  };
  return {
      fmt::format("Predicted ({}): holds on {}; does not hold on {}.", label("predicted_variant"),
                  holds_list(s["predicted"]["holds"]), holds_list(s["predicted"]["fails"])),
      fmt::format("Fitted ({}): holds on {}; does not hold on {}.", label("fitted_variant"),
                  holds_list(s["fitted"]["holds"]), holds_list(s["fitted"]["fails"])),
      fmt::format("Scan of the (kappa_r, d_s) box: {}.", s["scan"]["finding"].get<std::string>()),
      bound_note(cmp["fit"]),
      statistics_note(v[cmp["verdicts"]["predicted_variant"].get<std::size_t>()]["verdicts"])};
}

std::string to_text(const Table& t) {
  std::vector<std::size_t> w(t.columns.size());
  // UTF-8 "±" is two bytes and one column wide: count code points, not bytes
  auto width = [](const std::string& s) {
    return std::size_t(
        std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
  };
  for (std::size_t c = 0; c < w.size(); ++c) {
    w[c] = width(t.columns[c]);
    for (const auto& r : t.rows) w[c] = std::max(w[c], width(r[c]));
  }
  auto line = [&](const std::vector<std::string>& cells) {
    std::string s;
    for (std::size_t c = 0; c < cells.size(); ++c)
      s += cells[c] + std::string(w[c] - width(cells[c]) + 2, ' ');
    return s.substr(0, s.find_last_not_of(' ') + 1) + "\n";
  };
  std::string out = line(t.columns);
  for (const auto& r : t.rows) out += line(r);
  return out;
}

}  // namespace iwb::comparison
