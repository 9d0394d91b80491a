#include "studies/thermo_study.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace iwb::studies {

namespace {

constexpr double kKelvin = 273.15;
constexpr double kThermoGammaEnd = 0.5;  // the seed's figures end near their asymptotes well before
constexpr const char* kSoil1 = "table_6_5_soil_1.toml";
constexpr const char* kCvSet = "table_6_5_cv.toml";
constexpr const char* kCnlSet = "table_6_5_cnl.toml";

// Starts: Table 6.5's e0 0.5 (Soil 1) and 0.45 (CV column) at 300 kPa lie outside the sets' own
// state boundary surfaces (src/models/thermo_hydro/README.md), so the study starts them denser,
// the same e0 at every temperature as the seed's "different applied constant temperatures" reads.
// The CNL column's e0 0.45 at 100 kPa lies outside too (the surface is at e 0.400-0.435 at 40 deg
// C over the varied l_t and n_t: OCR 0.68-0.89), but its kappa* / lambda* = 0.44 gives alpha < 0,
// where such a start has f_d / f_d^SBS = 0.97-0.99 and runs as the seed ran it: kept, with the
// model's warning (seed_start_outside). Suctions: one e0 at 100 kPa net stress.
constexpr double kSoil1E0 = 0.44, kCvE0 = 0.38, kCnlE0 = 0.45, kSuctionE0 = 0.5;
const std::vector<double> kTemperaturesC{25.0, 40.0, 60.0};
const std::vector<double> kVariedNt{-0.02, 0.0, 0.02};
const std::vector<double> kVariedLt{-0.01, 0.0, 0.01};
const std::vector<double> kSuctions{0.0, 100.0, 200.0, 400.0};

std::string label(double v) {
  return fmt::format("{:g}", v);
}

ClayCase thermo_case(const std::string& name, const std::string& model, const char* set,
                     const std::string& bc, double sigma_n, double e0, double T_C) {
  ClayCase k{name, model, set, bc, sigma_n};
  k.e0 = e0, k.gamma = kThermoGammaEnd;
  k.initial_inputs = {{"T_K", T_C + kKelvin}};
  return k;
}

std::string temperature_case(const std::string& bc, double T_C) {
  return fmt::format("{}_T{}", bc, label(T_C));
}
std::string variation_case(const std::string& bc, const std::string& key, double v) {
  return fmt::format("{}_40C_{}{}", bc, key, label(v));
}
std::string suction_case(double s) {
  return fmt::format("cnl_s{}", label(s));
}

std::vector<ClayCase> thermo_cases() {
  std::vector<ClayCase> cases;
  for (double T : kTemperaturesC) {  // 6.5.1, figures 6.12 and 6.13
    cases.push_back(
        thermo_case(temperature_case("cnl", T), "hcthm", kSoil1, "CNL", 300.0, kSoil1E0, T));
    cases.push_back(
        thermo_case(temperature_case("cv", T), "hcthm", kSoil1, "CV", 300.0, kSoil1E0, T));
  }
  cases.push_back(thermo_case("cv_T40_3d", "hcthm3d", kSoil1, "CV", 300.0, kSoil1E0, 40.0));
  for (const auto& [key, values] :
       {std::pair{"n_t", kVariedNt}, {"l_t", kVariedLt}})  // 6.5.2, figures 6.14-6.17
    for (double v : values) {
      auto cv =
          thermo_case(variation_case("cv", key, v), "hcthm", kCvSet, "CV", 300.0, kCvE0, 40.0);
      cv.parameter_changes = {{std::string("thermo_hydro.") + key, v}};
      cases.push_back(cv);
      auto cnl =
          thermo_case(variation_case("cnl", key, v), "hcthm", kCnlSet, "CNL", 100.0, kCnlE0, 40.0);
      cnl.parameter_changes = cv.parameter_changes;
      cnl.seed_start_outside = true;
      cases.push_back(cnl);
    }
  for (double s : kSuctions) {  // 6.5.3, figure 6.18
    auto k = thermo_case(suction_case(s), "hcthm", kSoil1, "CNL", 100.0, kSuctionE0, 25.0);
    k.initial_inputs["s_kPa"] = s;
    cases.push_back(k);
  }
  return cases;
}

// Whether a quantity of the end state moves in one direction along a list of cases.
struct Trend {
  std::vector<double> values;
  bool rising() const {
    return std::adjacent_find(values.begin(), values.end(), std::greater_equal<>()) == values.end();
  }
  bool falling() const {
    return std::adjacent_find(values.begin(), values.end(), std::less_equal<>()) == values.end();
  }
  std::string text(const std::string& unit) const {
    std::string s;
    for (double v : values) s += (s.empty() ? "" : ", ") + fmt::format("{:.4g}", v);
    return s + " " + unit;
  }
};

Trend end_of(const std::map<std::string, ClayCurve>& curves, const std::vector<std::string>& names,
             Axis a) {
  Trend t;
  for (const auto& n : names) {
    const auto& c = curves.at(n);
    t.values.push_back(a == Axis::kTau      ? c.end_tau()
                       : a == Axis::kSigmaN ? c.sigma_n.back()
                                            : c.eps_n.back());
  }
  return t;
}

std::vector<std::string> names_over(const std::vector<double>& values,
                                    const std::function<std::string(double)>& name) {
  std::vector<std::string> out;
  for (double v : values) out.push_back(name(v));
  return out;
}

ClayClaim cnl_temperature(const std::map<std::string, ClayCurve>& curves) {
  const auto names =
      names_over(kTemperaturesC, [](double T) { return temperature_case("cnl", T); });
  const auto tau = end_of(curves, names, Axis::kTau), eps = end_of(curves, names, Axis::kEpsN);
  ClayClaim c{"6.5.1 CNL",
              "at higher temperature the shear stress ends slightly lower and the normal strain "
              "(compression) larger "
              "(Fig. 6.12)",
              "",
              tau.falling() && eps.falling(),
              {}};
  c.measured = fmt::format("at 25, 40, 60 deg C: tau {}; eps_n {} (opening positive)",
                           tau.text("kPa"), eps.text(""));
  c.values = {{"tau_kPa", tau.values}, {"eps_n", eps.values}};
  return c;
}

ClayClaim cv_temperature(const std::map<std::string, ClayCurve>& curves) {
  const auto names = names_over(kTemperaturesC, [](double T) { return temperature_case("cv", T); });
  const auto tau = end_of(curves, names, Axis::kTau), sig = end_of(curves, names, Axis::kSigmaN);
  ClayClaim c{"6.5.1 CV",
              "increasing temperature leads to decreasing shear and normal stresses (Fig. 6.13)",
              "",
              tau.falling() && sig.falling(),
              {}};
  c.measured =
      fmt::format("at 25, 40, 60 deg C: tau {}; sigma_n {}", tau.text("kPa"), sig.text("kPa"));
  c.values = {{"tau_kPa", tau.values}, {"sigma_n_kPa", sig.values}};
  return c;
}

// 6.5.2: "a positive algebraic sign of l_t and n_t leads to decreased shear and normal stresses, a
// negative one to increased" (CV, figs. 6.14, 6.15; CNL: shear stress, figs. 6.16, 6.17).
ClayClaim variation(const std::map<std::string, ClayCurve>& curves, const std::string& bc,
                    const std::string& key, const std::vector<double>& values,
                    const std::string& figure) {
  const auto names = names_over(values, [&](double v) { return variation_case(bc, key, v); });
  const auto tau = end_of(curves, names, Axis::kTau), sig = end_of(curves, names, Axis::kSigmaN);
  const bool cv = bc == "cv";
  ClayClaim c{
      fmt::format("6.5.2 {}", cv ? "CV" : "CNL"),
      fmt::format("a positive {} decreases the {} stress, a negative one increases it (Fig. {})",
                  key, cv ? "shear and normal" : "shear", figure),
      "",
      tau.falling() && (!cv || sig.falling()),
      {}};
  c.measured = fmt::format("{} = {}: tau {}", key, Trend{values}.text(""), tau.text("kPa"));
  if (cv) c.measured += "; sigma_n " + sig.text("kPa");
  if (cv && key == "n_t")
    c.measured +=
        ". N(T) = N + n_t ln(T/T0) (6.45): a positive n_t lifts the NCL when heated, so a state of "
        "the same e is "
        "relatively denser and ends at higher stresses; the seed's statement fits l_t, not n_t";
  if (!cv) {
    const auto [lo, hi] = std::minmax_element(tau.values.begin(), tau.values.end());
    c.measured += fmt::format(
        ". Under CNL every case approaches the critical state at the same sigma_n: the spread is "
        "{:.2f} % "
        "of tau, and its direction is the opposite of CV's",
        100.0 * (*hi - *lo) / *hi);
  }
  c.values = {{"tau_kPa", tau.values}, {"sigma_n_kPa", sig.values}};
  return c;
}

ClayClaim suction(const std::map<std::string, ClayCurve>& curves) {
  const auto names = names_over(kSuctions, suction_case);
  const auto tau = end_of(curves, names, Axis::kTau);
  ClayClaim c{"6.5.3 CNL",
              "the shear strength increases with increasing suction (Fig. 6.18)",
              "",
              tau.rising(),
              {}};
  c.measured = fmt::format(
      "at s = 0, 100, 200, 400 kPa: tau {} (chi s adds effective stress at the same net load)",
      tau.text("kPa"));
  c.values = {{"tau_kPa", tau.values}};
  return c;
}

ClayClaim reduced_against_3d(const std::map<std::string, ClayCurve>& curves) {
  const auto& r = curves.at(temperature_case("cv", 40.0));
  const auto& d = curves.at("cv_T40_3d");
  const double dt = largest_relative_difference(r.tau, d.tau),
               ds = largest_relative_difference(r.sigma_n, d.sigma_n);
  ClayClaim c{"6.3",
              "the model on the reduced interface vectors equals its 3D form in simple shear (CV "
              "at 40 deg C)",
              "",
              dt < 1e-8 && ds < 1e-8,
              {{"tau", dt}, {"sigma_n", ds}}};
  c.measured = fmt::format("largest |reduced - 3D| {:.1e} of tau, {:.1e} of sigma_n", dt, ds);
  return c;
}

std::vector<ClayClaim> thermo_claims(const std::map<std::string, ClayCurve>& curves) {
  return {reduced_against_3d(curves),
          cnl_temperature(curves),
          cv_temperature(curves),
          variation(curves, "cv", "n_t", kVariedNt, "6.14"),
          variation(curves, "cv", "l_t", kVariedLt, "6.15"),
          variation(curves, "cnl", "n_t", kVariedNt, "6.16"),
          variation(curves, "cnl", "l_t", kVariedLt, "6.17"),
          suction(curves)};
}

std::vector<std::pair<std::string, std::string>> curves_over(
    const std::vector<double>& values, const std::function<std::string(double)>& name,
    const std::string& title) {
  std::vector<std::pair<std::string, std::string>> out;
  for (double v : values) out.push_back({name(v), fmt::format(fmt::runtime(title), v)});
  return out;
}

std::vector<FigureSpec> thermo_figures() {
  const auto cnl_T = curves_over(
      kTemperaturesC, [](double T) { return temperature_case("cnl", T); }, "{:g} deg C");
  const auto cv_T = curves_over(
      kTemperaturesC, [](double T) { return temperature_case("cv", T); }, "{:g} deg C");
  std::vector<FigureSpec> out{
      {"fig_6_12a_cnl_tau",
       "Soil 1, CNL 300 kPa: shear stress at constant temperatures (seed Fig. 6.12a)", Axis::kGamma,
       Axis::kTau, cnl_T},
      {"fig_6_12b_cnl_eps_n",
       "Soil 1, CNL 300 kPa: normal strain, opening positive (seed Fig. 6.12b)", Axis::kGamma,
       Axis::kEpsN, cnl_T},
      {"fig_6_13a_cv_tau", "Soil 1, CV from 300 kPa: shear stress (seed Fig. 6.13a)", Axis::kGamma,
       Axis::kTau, cv_T},
      {"fig_6_13b_cv_sigma_n", "Soil 1, CV from 300 kPa: normal stress (seed Fig. 6.13b)",
       Axis::kGamma, Axis::kSigmaN, cv_T}};
  const std::string figs[2][2] = {{"6_14", "6_16"}, {"6_15", "6_17"}};
  int row = 0;
  for (const auto& [key, values] : {std::pair{"n_t", kVariedNt}, {"l_t", kVariedLt}}) {
    const std::string k = key;
    const auto cv = curves_over(
        values, [&](double v) { return variation_case("cv", k, v); }, k + " = {:g}");
    const auto cnl = curves_over(
        values, [&](double v) { return variation_case("cnl", k, v); }, k + " = {:g}");
    out.push_back(
        {"fig_" + figs[row][0] + "_cv_" + k,
         fmt::format("CV column, CV at 40 deg C: {} varied (seed Fig. {})", k, figs[row][0]),
         Axis::kSigmaN, Axis::kTau, cv});
    out.push_back({"fig_" + figs[row][1] + "_cnl_" + k,
                   fmt::format("CNL column, CNL 100 kPa at 40 deg C: {} varied (seed Fig. {})", k,
                               figs[row][1]),
                   Axis::kGamma, Axis::kTau, cnl});
    ++row;
  }
  out.push_back({"fig_6_18_suction",
                 "Soil 1, CNL 100 kPa: shear stress at constant suctions (seed Fig. 6.18)",
                 Axis::kGamma, Axis::kTau, curves_over(kSuctions, suction_case, "s = {:g} kPa")});
  return out;
}

}  // namespace

StudyDefinition thermo_study() {
  return {"thermo",
          "iwb thermo study: the thermo-hydro-mechanical clay interface model hcthm (seed 6.5)",
          "Seed section 6.5 redrawn with hcthm (Masin & Khalili 2012 on the reduced vectors, a "
          "smooth wall, kappa_r 1), "
          "Table 6.5's sets: Soil 1 under CNL at 300 kPa and CV from 300 kPa at 25, 40 and 60 deg "
          "C (reference 25 deg C), "
          "from e0 0.44 (the table's 0.5 lies outside the set's state boundary surface at 300 "
          "kPa); the CV column (CV from "
          "300 kPa, e0 0.38 for the same reason) and the CNL column (CNL 100 kPa, e0 0.45, the "
          "table's, though outside its surface too: a warning per case) at 40 deg C with n_t in "
          "{-0.02, 0, 0.02} and l_t in {-0.01, 0, 0.01} (the table's \"var.\"); Soil 1 under CNL "
          "at 100 kPa net stress "
          "from e0 0.5 at constant suctions 0, 100, 200 and 400 kPa with this workbench's suction "
          "parameters (s_e 50 kPa, "
          "l_s -0.005, n_s 0.02: the table gives none). Temperature and suction are constant "
          "during shear; simple shear "
          "to gamma 0.5.",
          thermo_cases(),
          thermo_claims,
          thermo_figures()};
}

}  // namespace iwb::studies
