#include "tradeoff/tradeoff_output.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "comparison/presentation/figure.hpp"
#include "dem/scene/requirements.hpp"
#include "io/output_path.hpp"
#include "io/run_directory.hpp"
#include "tradeoff/tradeoff.hpp"

namespace iwb::tradeoff {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string number(const json& v, const char* format = "{:.4g}") {
  return v.is_number() ? fmt::format(fmt::runtime(format), v.get<double>()) : "n/a";
}
std::string percent(const json& v) {
  return v.is_number() ? fmt::format("{:.1f} %", 100 * v.get<double>()) : "n/a";
}

// The QoIs a setting meets at tolerance `tol` ("0.05"), joined by `sep`; `none` if it meets none.
std::string met(const json& s, const char* tol, const char* sep, const char* none) {
  std::string out;
  if (s.contains("meets"))
    for (const auto& [k, v] : s["meets"][tol].items())
      if (v.get<bool>()) out += (out.empty() ? "" : sep) + k;
  return out.empty() ? none : out;
}

std::string settings_table(const json& t) {
  std::string md = "| setting | what | particles | particle-steps | wall s |";
  for (const auto& q : dem::quantities_of_interest()) md += fmt::format(" {} | err |", q.key);
  md += " meets 5 % | meets 1 % |\n|---|---|---|---|---|";
  for (std::size_t i = 0; i < dem::quantities_of_interest().size(); ++i) md += "---|---|";
  md += "---|---|\n";
  for (const auto& s : t["settings"]) {
    md += fmt::format("| {} | {} |", s["name"].get<std::string>(), s.value("settings", ""));
    if (!completed(s)) {
      md += fmt::format(" {} |\n", s.value("status", "?"));
      continue;
    }
    md += fmt::format(" {} | {:.3g} | {:.0f} |", number(s["particles"], "{:.0f}"),
                      s["particle_steps"].get<double>(), s["wall_seconds"].get<double>());
    for (const auto& q : dem::quantities_of_interest())
      md += fmt::format(" {} | {} |", number(s["qoi"][q.key]),
                        s.contains("error") ? percent(s["error"][q.key]) : "");
    for (const char* tol : {"0.05", "0.01"}) md += " " + met(s, tol, ", ", "-") + " |";
    md += "\n";
  }
  return md;
}

std::string noise_table(const json& t) {
  std::string md = "| QoI | base mean | seed sd | relative (noise floor) |\n|---|---|---|---|\n";
  for (const auto& q : dem::quantities_of_interest()) {
    // a tradeoff stopped before any base seed completed has no floor yet: blank cells, n=0
    const json n = t.value("noise_floor", json::object()).value(q.key, json::object());
    md += fmt::format("| {} | {} | {} (n={}) | {} |\n", q.label, number(n.value("mean", json())),
                      number(n.value("sd", json())), n.value("n", 0),
                      percent(n.value("relative", json())));
  }
  return md;
}

std::string effects_table(const json& t) {
  std::string md = "| knob | factor | cost / base |";
  for (const auto& q : dem::quantities_of_interest()) md += fmt::format(" {} moves |", q.key);
  md += "\n|---|---|---|";
  for (std::size_t i = 0; i < dem::quantities_of_interest().size(); ++i) md += "---|";
  md += "\n";
  for (const auto& e : t.value("knob_effects", json::array())) {
    md += fmt::format("| {} | x{:g} | {:.2f} |", e["knob"].get<std::string>(),
                      e["factor"].get<double>(), e["cost_ratio"].get<double>());
    for (const auto& q : dem::quantities_of_interest()) {
      const auto& s = e["shift"][q.key];
      md += s.is_number() ? fmt::format(" {:+.1f} % ({} noise) |", 100 * s.get<double>(),
                                        number(e["shift_in_noise"][q.key], "{:.1f}x"))
                          : " n/a |";
    }
    md += "\n";
  }
  return md;
}

std::string cheapest_table(const json& t) {
  std::string md =
      "| tolerance | QoI | cheapest setting | particle-steps | wall s |\n|---|---|---|---|---|\n";
  const json cheapest = t.value("cheapest", json::object());  // named: items() must not outlive it
  for (const auto& [tol, per] : cheapest.items())
    for (const auto& [q, c] : per.items())
      md += c.is_null()
                ? fmt::format("| {:g} % | {} | none | | |\n", 100 * std::stod(tol), q)
                : fmt::format("| {:g} % | {} | {} | {:.3g} | {:.0f} |\n", 100 * std::stod(tol), q,
                              c["name"].get<std::string>(), c["particle_steps"].get<double>(),
                              c["wall_seconds"].get<double>());
  return md;
}

// Error against cost, one series per QoI, each point labelled with its setting; the noise floors
// are not drawn (one per QoI would crowd the plot) but listed in tradeoff.md.
void draw_pareto(const json& t, const fs::path& dir) {
  comparison::Figure f{"pareto",
                       "error against cost: " + t.value("scene", ""),
                       "cost, particle-steps",
                       "relative error against the reference",
                       {},
                       {},
                       "",
                       ""};
  f.data.columns = {"particle_steps"};
  for (const auto& q : dem::quantities_of_interest())
    f.data.columns.push_back(std::string(q.key) + "_error");
  for (const auto& q : dem::quantities_of_interest()) f.titles.push_back(q.key);
  std::string labels;
  double lowest = INFINITY, highest = 0.0;
  for (const auto& s : t["settings"]) {
    if (!completed(s) || !s.contains("error") || s["name"] == t["reference"]["name"])
      continue;  // the reference has no error
    std::vector<double> row = {s["particle_steps"].get<double>()};
    for (const auto& q : dem::quantities_of_interest()) {
      const auto& e = s["error"][q.key];
      row.push_back(e.is_number() ? std::max(e.get<double>(), 1e-4)
                                  : NAN);  // log axis: 0 drawn at 1e-4
    }
    f.data.rows.push_back(row);
    lowest = std::min(lowest, row[0]), highest = std::max(highest, row[0]);
    labels += fmt::format("set label {} at {},{} offset 0.6,0.6 font ',9'\n",
                          comparison::gnuplot_string(s["name"].get<std::string>()), row[0], row[2]);
  }
  f.extra =
      "set logscale xy\nset format y '%g'\nset arrow from graph 0, first 0.05 to graph 1, first "
      "0.05 nohead "
      "dt 2\nset arrow from graph 0, first 0.01 to graph 1, first 0.01 nohead dt 3\n" +
      labels;
  // Room right of the costliest point for its label (autoscale stops at the next decade, which
  // cut boxx2's at 9.8e8).
  if (highest > 0.0) f.extra += fmt::format("set xrange [{:g}:{:g}]\n", lowest / 2, highest * 3);
  const std::string csv = comparison::gnuplot_string("pareto.csv");
  f.plot = "plot ";
  for (std::size_t i = 0; i < f.titles.size(); ++i)
    f.plot += fmt::format("{}{} using 1:{} skip 1 with points pt {} ps 1.3 title {}", i ? ", " : "",
                          csv, i + 2, 5 + 2 * int(i), comparison::gnuplot_string(f.titles[i]));
  comparison::draw(f, dir);
}

}  // namespace

std::string tradeoff_markdown(const json& t) {
  std::string md = fmt::format("# DEM speed against accuracy: {}\n\nstatus: {}\n\n",
                               t.value("scene", ""), t.value("status", "?"));
  if (t["reference"].is_null()) {
    md += fmt::format(
        "No reference: the {} has not completed; errors are not measured yet.\n\n",
        t.value("reference_mode", "refined") == "base" ? "base setting (no seed)" : "refined run");
  } else {
    md += fmt::format(
        "Reference: `{}` ({}): {}.\nError = |QoI - QoI_ref| / |QoI_ref|; a setting meets a "
        "tolerance "
        "when error + noise floor <= tolerance.\n\n",
        t["reference"]["name"].get<std::string>(), t["reference"]["settings"].get<std::string>(),
        t["reference"]["why"].get<std::string>());
  }
  md += "## Noise floor (seed scatter of the base setting)\n\n" + noise_table(t);
  md += "\n## Settings\n\n" + settings_table(t);
  md += "\n## How far each QoI moves when a knob is halved or doubled (against the base mean)\n\n" +
        effects_table(t);
  md += "\n## Cheapest setting meeting each tolerance\n\n" + cheapest_table(t);
  return md;
}

std::string tradeoff_csv(const json& t) {
  std::string csv = "setting,kind,knob,factor,status,particles,particle_steps,wall_s";
  for (const auto& q : dem::quantities_of_interest()) csv += fmt::format(",{0},{0}_error", q.key);
  csv += ",meets_5pct,meets_1pct\n";
  auto cell = [](const json& v) {
    return v.is_number() ? fmt::format("{:.6g}", v.get<double>()) : std::string();
  };
  for (const auto& s : t["settings"]) {
    csv +=
        fmt::format("{},{},{},{:g},{},{},{},{}", s["name"].get<std::string>(),
                    s["kind"].get<std::string>(), s.value("knob", ""), s.value("factor", 1.0),
                    s.value("status", ""), cell(s.value("particles", json())),
                    cell(s.value("particle_steps", json())), cell(s.value("wall_seconds", json())));
    for (const auto& q : dem::quantities_of_interest())
      csv += "," + cell(s.value("qoi", json::object()).value(q.key, json())) + "," +
             cell(s.value("error", json::object()).value(q.key, json()));
    for (const char* tol : {"0.05", "0.01"}) csv += "," + met(s, tol, " ", "");
    csv += "\n";
  }
  return csv;
}

void write_tradeoff(const json& t, const fs::path& dir) {
  io::StagedDirectory staged(dir);  // the tables and the front together or not at all
  io::write_atomically(staged.path() / "tradeoff.json", t.dump(2) + "\n");
  io::write_atomically(staged.path() / "tradeoff.csv", tradeoff_csv(t));
  io::write_atomically(staged.path() / "tradeoff.md", tradeoff_markdown(t));
  if (!t["reference"].is_null()) draw_pareto(t, staged.path());
  staged.commit_into();
}

}  // namespace iwb::tradeoff
