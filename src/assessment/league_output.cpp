#include "assessment/league_output.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "comparison/presentation/figure.hpp"
#include "comparison/verdicts/verdicts.hpp"

namespace iwb::assessment {

using nlohmann::json;

namespace {

json points_json(const std::vector<ObjectivePoint>& points) {
  json out = json::array();
  for (const auto& p : points)
    out.push_back({{"name", p.name},
                   {"u_x_mm", p.u_x},
                   {"reference", p.reference},
                   {"model", p.model},
                   {"ua", p.ua}});
  return out;
}

// Curves to 6 significant digits: the DEM's own are no more precise, and the records stay small.
std::vector<double> rounded(const std::vector<double>& v) {
  std::vector<double> out;
  for (double x : v) out.push_back(std::isfinite(x) ? std::stod(fmt::format("{:.6g}", x)) : x);
  return out;
}

json curve_json(const ResponseCurve& c) {
  return {{"u_x_mm", rounded(c.u_x)}, {"tau_kPa", rounded(c.tau)}, {"normal", rounded(c.normal)}};
}

json sobol_json(const SobolResult& s) {
  json out = {{"base_samples", s.base_samples},
              {"evaluations", s.evaluations},
              {"failed", s.failed},
              {"indices", json::array()}};
  for (std::size_t q = 0; q < s.quantities.size(); ++q)
    for (std::size_t i = 0; i < s.parameters.size(); ++i)
      out["indices"].push_back({{"quantity", s.quantities[q]},
                                {"parameter", s.parameters[i]},
                                {"S_T", s.total[q][i].value},
                                {"low", s.total[q][i].low},
                                {"high", s.total[q][i].high}});
  return out;
}

const char* kind_name(Distribution::Kind k) {
  return k == Distribution::Kind::kNormal      ? "normal"
         : k == Distribution::Kind::kLognormal ? "lognormal"
                                               : "uniform";
}

// A record's number; NaN for null (JSON has no NaN or infinity: nlohmann writes them as null).
double number(const json& v) {
  return v.is_number() ? v.get<double>() : NAN;
}

std::vector<double> numbers(const json& v) {
  std::vector<double> out;
  for (const auto& x : v) out.push_back(number(x));
  return out;
}

// A number for a table: 3 significant digits, "-" for NaN.
std::string num(const json& v) {
  return std::isfinite(number(v)) ? fmt::format("{:.3g}", number(v)) : "-";
}

std::string fitted_values(const json& e) {
  std::string s;
  for (const auto& v : e["fit"]["values"])
    s +=
        fmt::format("{}{} = {:.4g} {}{}", s.empty() ? "" : ", ", v["name"].get<std::string>(),
                    number(v["value"]),
                    std::isfinite(number(v["sigma"])) ? fmt::format("+- {:.2g}", number(v["sigma"]))
                                                      : "(not identified: the data do not move it)",
                    v["at_bound"].get<bool>() ? " (on its bound)" : "");
  return s.empty() ? "nothing fitted" : s;
}

std::string model_section(const json& e) {
  std::string md = fmt::format(
      "### {}\n\nParameters from {}; calibrated to the runs ({} replays, RMS {:.3g} scatter "
      "units): {}.\n",
      e["model"].get<std::string>(), e["parameters_source"].get<std::string>(),
      e["fit"]["evaluations"].get<int>(), number(e["fit"]["rms_scaled"]), fitted_values(e));
  if (e["status"] != "assessed") md += fmt::format("\n**{}**\n", e["status"].get<std::string>());
  md += "\n| objective point | u_x (mm) | DEM | model | UA_k |\n|---|---|---|---|---|\n";
  for (const char* set : {"shear", "normal"})
    for (const auto& p : e["model_uncertainty"][set])
      md += fmt::format("| {} | {:.2f} | {} | {} | {} |\n", p["name"].get<std::string>(),
                        number(p["u_x_mm"]), num(p["reference"]), num(p["model"]), num(p["ua"]));
  const auto& pu = e["parameter_uncertainty"];
  md += fmt::format("\nParameter uncertainty ({} Latin hypercube samples, {} failed): ",
                    pu["samples"].get<int>(), pu["failed"].get<long>());
  for (const auto& q : pu["quantities"])
    md += fmt::format("CV {} {}; ", q["name"].get<std::string>(), num(q["cv"]));
  md += "distributions ";
  for (const auto& d : e["distributions"])
    md += fmt::format("{} {} COV {:g}, ", d["name"].get<std::string>(),
                      d["kind"].get<std::string>(), d["cov"].get<double>());
  md += fmt::format("held: {}.\n", e["held"].empty() ? "none" : e["held"].dump());
  if (e.contains("sobol")) {
    md += fmt::format(
        "\nTotal Sobol indices (N = {}, {} runs, 95 % bootstrap intervals):\n\n| parameter |",
        e["sobol"]["base_samples"].get<int>(), e["sobol"]["evaluations"].get<long>());
    for (const auto& q : league_quantities()) md += " " + q + " |";
    md += "\n|---|";
    for (std::size_t q = 0; q < league_quantities().size(); ++q) md += "---|";
    md += "\n";
    for (const auto& d : e["distributions"]) {
      md += "| " + d["name"].get<std::string>() + " |";
      for (const auto& q : league_quantities())
        for (const auto& i : e["sobol"]["indices"])
          if (i["quantity"] == q && i["parameter"] == d["name"])
            md += fmt::format(" {:.3f} [{:.3f}, {:.3f}] |", number(i["S_T"]), number(i["low"]),
                              number(i["high"]));
      md += "\n";
    }
  }
  const std::string m = e["model"];
  md += fmt::format("\n![{0}: tau](figures/{0}_tau.svg) ![{0}: normal](figures/{0}_normal.svg)\n\n",
                    m);
  return md;
}

}  // namespace

json entry_json(const LeagueEntry& e) {
  json fit = {{"values", json::array()},
              {"rms_scaled", e.fit.rms_scaled},
              {"evaluations", e.fit.evaluations},
              {"stop_reason", e.fit.stop_reason},
              {"kappa_r", e.fit.best.inputs.roughness.kappa_r},
              {"d_s_mm", e.fit.best.d_s_mm},
              {"parameters", e.fit.best.inputs.tables}};
  for (const auto& v : e.fit.values)
    fit["values"].push_back(
        {{"name", v.name}, {"value", v.value}, {"sigma", v.sigma}, {"at_bound", v.at_bound}});
  json dist = json::array();
  for (const auto& d : e.distributions)
    dist.push_back(
        {{"name", d.name}, {"kind", kind_name(d.kind)}, {"mean", d.mean}, {"cov", d.cov}});
  json pu = {{"samples", e.parameter_uncertainty.samples},
             {"failed", e.parameter_uncertainty.failed},
             {"quantities", json::array()}};
  for (const auto& q : e.parameter_uncertainty.quantities)
    pu["quantities"].push_back({{"name", q.name}, {"mean", q.mean}, {"sd", q.sd}, {"cv", q.cv}});
  const auto& mu = e.model_uncertainty;
  json out = {
      {"model", e.model},
      {"parameters_source", e.parameters_source},
      {"status", e.status},
      {"fit", fit},
      {"model_uncertainty",
       {{"shear", points_json(mu.shear)},
        {"normal", points_json(mu.normal)},
        {"shear_norm", mu.shear_norm},
        {"normal_norm", mu.normal_norm},
        {"peaked", mu.peaked}}},
      {"verdicts", comparison::to_json(e.verdicts)},
      {"distributions", dist},
      {"held", e.held},
      {"parameter_uncertainty", pu},
      {"ua_par", e.ua_par},
      {"global_shear", e.global_shear},
      {"global", e.global},
      {"reference", curve_json(e.reference)},
      {"fitted", curve_json(e.fitted)},
      {"band", {{"tau_low_kPa", rounded(e.band_low)}, {"tau_high_kPa", rounded(e.band_high)}}}};
  if (e.sobol) out["sobol"] = sobol_json(*e.sobol);
  return out;
}

std::vector<json> ranked(std::vector<json> entries) {
  const auto key = [](const json& e) {
    const double g = number(e["global"]);
    return e["status"] == "assessed" && std::isfinite(g) ? g : INFINITY;
  };
  std::stable_sort(entries.begin(), entries.end(),
                   [&](const json& a, const json& b) { return key(a) < key(b); });
  return entries;
}

// The form-limit column's cell of an entry (issue 38): what its prediction breaks and why.
std::string causes_of(const json& e) {
  return e.contains("form_limit") ? e["form_limit"]["causes"].get<std::string>() : "";
}

std::string league_markdown(const json& h, const std::vector<json>& entries) {
  const bool with_causes = !h.value("form_limits", std::string()).empty();
  std::string md = fmt::format(
      "# Interface models on the DEM runs in {}\n\nReference: the seed mean of {} DEM run(s) ({}, "
      "{}). Each model is calibrated to them "
      "(tau and the free normal quantity, each in units of its seed scatter), replayed along their "
      "path, and judged "
      "at the seed's objective points (eq. 4.3: UA_k = |model - DEM| / (1.645 |DEM|); eq. 4.15's "
      "norm over the "
      "points). UA_par is the CV of the peak shear stress over {} Latin hypercube samples of the "
      "calibrated set "
      "({}). Global: sqrt(UA_model^2 + UA_par^2) (eq. 4.4, ERRATA 16), "
      "the seed's on the shear points, and the workbench's on shear and {} together, by which the "
      "table is ranked.\n\n"
      "| rank | model | UA_model shear | UA_model {} | UA_par | global (seed: shear) | global "
      "(shear and {}) | status |{}\n"
      "|---|---|---|---|---|---|---|---|{}\n",
      h["scene"].get<std::string>(), h["runs"].size(), h["boundary"].get<std::string>(),
      h["wall"].get<std::string>(), h["uncertainty_samples"].get<int>(),
      h.value("parameter_uncertainty", "seed") == "fit"
          ? "each calibrated quantity spread by its own sigma from the fit to the runs"
          : "COVs of the seed's Table 4.8 and Appendix A",
      h["normal"].get<std::string>(), h["normal"].get<std::string>(),
      h["normal"].get<std::string>(),
      with_causes ? " what the prediction breaks, and why (form limit) |" : "",
      with_causes ? "---|" : "");
  int rank = 0;
  for (const auto& e : entries)
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |{}\n", ++rank,
                      e["model"].get<std::string>(), num(e["model_uncertainty"]["shear_norm"]),
                      num(e["model_uncertainty"]["normal_norm"]), num(e["ua_par"]),
                      num(e["global_shear"]), num(e["global"]), e["status"].get<std::string>(),
                      with_causes ? " " + causes_of(e) + " |" : "");
  if (with_causes)
    md += fmt::format(
        "\nWhat the prediction breaks: each quantity that the model's own set (the soil-test "
        "calibration, or the seed's table for the others), predicted with kappa_r from eq. 5.35 "
        "and d_s = 5 d50, breaks on this wall and boundary, over the runs of its form-limit "
        "record in {}: *form* where the form limit (every parameter fitted within its box) "
        "breaks it too, else *calibration* (`iwb form-limit`, issue 38).\n",
        h["form_limits"].get<std::string>());
  md += "\n![uncertainties](figures/league.svg)\n\n## Per model\n\n";
  for (const auto& e : entries) md += model_section(e);
  return md;
}

std::string league_csv(const std::vector<json>& entries) {
  std::string out =
      "rank,model,ua_model_shear,ua_model_normal,ua_par,global_shear,global,status,form_limit_"
      "causes\n";
  int rank = 0;
  for (const auto& e : entries)
    out += fmt::format("{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},\"{}\",\"{}\"\n", ++rank,
                       e["model"].get<std::string>(), number(e["model_uncertainty"]["shear_norm"]),
                       number(e["model_uncertainty"]["normal_norm"]), number(e["ua_par"]),
                       number(e["global_shear"]), number(e["global"]),
                       e["status"].get<std::string>(), causes_of(e));
  return out;
}

void draw_league_figures(const std::vector<json>& entries, const std::filesystem::path& dir) {
  using comparison::PlotCurve;
  std::filesystem::create_directories(dir);
  for (const auto& e : entries) {
    const std::string m = e["model"];
    const auto& r = e["reference"];
    const auto& f = e["fitted"];
    const auto x = numbers(r["u_x_mm"]);
    std::vector<PlotCurve> tau = {
        {"DEM, seed mean", x, numbers(r["tau_kPa"])},
        {m + ", calibrated", numbers(f["u_x_mm"]), numbers(f["tau_kPa"])}};
    if (!e["band"]["tau_low_kPa"].empty()) {
      tau.push_back({m + ", 5 % of the parameter samples", x, numbers(e["band"]["tau_low_kPa"])});
      tau.push_back({m + ", 95 % of the parameter samples", x, numbers(e["band"]["tau_high_kPa"])});
    }
    comparison::draw(
        comparison::curves_figure(m + "_tau", m + ": shear stress", "u_x (mm)", "tau (kPa)", tau),
        dir);
    comparison::draw(
        comparison::curves_figure(
            m + "_normal", m + ": free normal quantity (u_n in mm, or sigma_n in kPa under CV)",
            "u_x (mm)", "change from the start",
            {{"DEM, seed mean", x, numbers(r["normal"])},
             {m + ", calibrated", numbers(f["u_x_mm"]), numbers(f["normal"])}}),
        dir);
  }
  comparison::Figure bars{
      "league", "Uncertainties per model (ranked)", "model", "uncertainty", {}, {}, "", ""};
  bars.data.columns = {"rank", "ua_model_shear", "ua_model_normal", "ua_par", "global"};
  std::string xtics;
  int rank = 0;
  for (const auto& e : entries) {
    ++rank;
    bars.data.rows.push_back({double(rank), number(e["model_uncertainty"]["shear_norm"]),
                              number(e["model_uncertainty"]["normal_norm"]), number(e["ua_par"]),
                              number(e["global"])});
    // a histogram's clusters sit at 0, 1, 2, ...
    xtics += fmt::format("{}{} {}", xtics.empty() ? "" : ", ",
                         comparison::gnuplot_string(e["model"].get<std::string>()), rank - 1);
  }
  bars.extra =
      "set style data histograms\nset style histogram clustered\nset style fill solid 0.8\nset "
      "xtics (" +
      xtics + ") rotate by -30\nset logscale y\n";
  bars.plot =
      "plot 'league.csv' using 2 skip 1 title 'UA_model shear', '' using 3 skip 1 title 'UA_model "
      "normal', "
      "'' using 4 skip 1 title 'UA_par', '' using 5 skip 1 title 'global'";
  comparison::draw(bars, dir);
}

}  // namespace iwb::assessment
