#include "studies/chapter8_study.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace iwb::studies {

namespace {

struct Clay {
  std::string key, label, parameters;
  double N, lambda_star;  // Table 8.1: the isotropic NCL, for the common start
};

const std::vector<Clay>& clays() {
  static const std::vector<Clay> c{
      {"london", "London clay", "table_8_1_london_clay.toml", 1.375, 0.11},
      {"kaolin", "Kaolin clay", "table_8_1_kaolin_clay.toml", 0.88, 0.065}};
  return c;
}

// The seed states no start for 8.4. One start every model reads alike: isotropic, sigma_n 100 kPa,
// normally consolidated, i.e. e0 on the isotropic NCL ln(1+e) = N - lambda* ln p of the hypoplastic
// and barodetic sets (HCE: the ASBS at F_m = 0; Barodesy: (1+e)/(1+e_c) = 2^lambda*; modified Cam
// clay: p_c = p, its e0 a label). Sheared to gamma 0.5: MCC is within 0.3 % of its critical state
// there (test of mcc), the seed's figures' end.
constexpr double kSigmaN = 100.0;
constexpr double kChapter8GammaEnd = 0.5;
const std::vector<std::pair<std::string, std::string>> kModels{
    {"hce", "HCE"}, {"barodesy-clay", "BC"}, {"mcc", "MCC"}};
const std::vector<std::string> kThreeDimensional{"barodesy-clay3d", "mcc3d"};

std::string case_name(const Clay& c, const std::string& model) {
  return c.key + "_" + model;
}

std::vector<ClayCase> chapter8_cases() {
  std::vector<ClayCase> cases;
  for (const auto& c : clays()) {
    const double e0 = std::exp(c.N - c.lambda_star * std::log(kSigmaN)) - 1.0;
    for (const auto& m : kModels) {
      ClayCase k{case_name(c, m.first), m.first, c.parameters, "CV", kSigmaN};
      k.e0 = e0, k.K0 = 1.0, k.gamma = kChapter8GammaEnd;
      cases.push_back(k);
    }
    for (const auto& m : kThreeDimensional) {
      ClayCase k{case_name(c, m), m, c.parameters, "CV", kSigmaN};
      k.e0 = e0, k.K0 = 1.0, k.gamma = kChapter8GammaEnd;
      cases.push_back(k);
    }
  }
  return cases;
}

// "No peak": the largest value is within 1 % of the end value; a "peak": more than 1 % above both
// the start and the end.
constexpr double kPeak = 0.01;
// "The same stress": within 5 % (the seed reads it off figures).
constexpr double kSame = 0.05;

bool has_peak(const std::vector<double>& v) {
  const double top = *std::max_element(v.begin(), v.end());
  return top > (1.0 + kPeak) * v.back() && top > (1.0 + kPeak) * v.front();
}

std::string peak_words(const std::vector<double>& v) {
  const double top = *std::max_element(v.begin(), v.end());
  return fmt::format("max {:.1f}, end {:.1f} kPa ({})", top, v.back(),
                     has_peak(v) ? "peak" : "no peak");
}

// Which of the three models peak in `axis` (tau or sigma_n); the claim holds if exactly `peaking`
// do.
ClayClaim peaks(const std::map<std::string, ClayCurve>& curves, const Clay& c, bool shear,
                const std::set<std::string>& peaking, const std::string& words) {
  ClayClaim out{fmt::format("8.4 {}", c.label), words, "", true, {}};
  for (const auto& [model, label] : kModels) {
    const auto& k = curves.at(case_name(c, model));
    const auto& v = shear ? k.tau : k.sigma_n;
    out.measured += fmt::format("{}{}: {}", out.measured.empty() ? "" : "; ", label, peak_words(v));
    out.values[label] = {{"max_kPa", *std::max_element(v.begin(), v.end())},
                         {"end_kPa", v.back()},
                         {"peak", has_peak(v)}};
    out.holds = out.holds && has_peak(v) == (peaking.count(model) == 1);
  }
  return out;
}

// HCE and BC end at the same tau and sigma_n (within kSame); MCC's place against them in the words.
ClayClaim same_asymptote(const std::map<std::string, ClayCurve>& curves, const Clay& c,
                         const std::string& words, bool mcc_higher) {
  ClayClaim out{fmt::format("8.4 {}", c.label), words, "", true, {}};
  const auto& hce = curves.at(case_name(c, "hce"));
  const auto& bc = curves.at(case_name(c, "barodesy-clay"));
  const auto& mcc = curves.at(case_name(c, "mcc"));
  const double dt = bc.end_tau() / hce.end_tau() - 1.0,
               ds = bc.sigma_n.back() / hce.sigma_n.back() - 1.0;
  out.values = {{"hce", hce.end_values()}, {"bc", bc.end_values()}, {"mcc", mcc.end_values()}};
  out.measured = fmt::format(
      "at gamma {}: tau HCE {:.1f}, BC {:.1f} ({:+.1f} %), MCC {:.1f} kPa; sigma_n HCE {:.1f}, BC "
      "{:.1f} "
      "({:+.1f} %), MCC {:.1f} kPa",
      kChapter8GammaEnd, hce.end_tau(), bc.end_tau(), 100.0 * dt, mcc.end_tau(), hce.sigma_n.back(),
      bc.sigma_n.back(), 100.0 * ds, mcc.sigma_n.back());
  out.holds = std::abs(dt) < kSame && std::abs(ds) < kSame;
  if (mcc_higher) out.holds = out.holds && mcc.end_tau() > std::max(hce.end_tau(), bc.end_tau());
  return out;
}

// 8.1: the reformulation carries other frameworks; the seed assumes reduced = 3D, the study
// measures it (largest difference over the path, both clays) against the round-off the hypoplastic
// forms reach.
ClayClaim reduced_against_3d(const std::map<std::string, ClayCurve>& curves,
                             const std::string& model, const std::string& label,
                             const std::string& why) {
  ClayClaim out{
      "8.1, 8.5",
      fmt::format("{} on the reduced interface vectors equals its 3D form in simple shear (CV)",
                  label),
      "",
      true,
      {}};
  for (const auto& c : clays())
    add_reduced_against_3d(out, c.key, c.label, curves.at(case_name(c, model)),
                           curves.at(case_name(c, model + "3d")));
  out.measured += " (" + why + ")";
  return out;
}

std::vector<ClayClaim> chapter8_claims(const std::map<std::string, ClayCurve>& curves) {
  const auto& london = clays()[0];
  const auto& kaolin = clays()[1];
  return {
      reduced_against_3d(
          curves, "mcc", "modified Cam clay",
          "the return reads only p and the deviator, which the reduced operators carry exactly"),
      reduced_against_3d(curves, "barodesy-clay", "Barodesy",
                         "R = -exp(alpha D^0) leaves the embedding: its (3,3) entry is 1 in 3D, "
                         "the (2,2) entry on the "
                         "reduced vectors; src/models/barodesy/README.md"),
      peaks(curves, london, true, {},
            "shear stress: no peak under continuous shear for any model (Fig. 8.1a)"),
      peaks(curves, london, false, {"hce", "barodesy-clay"},
            "normal stress: a distinctive peak for BC and HCE, none for MCC (Fig. 8.1b)"),
      same_asymptote(curves, london,
                     "BC and HCE reach the same critical state stress; MCC's slightly higher",
                     true),
      peaks(curves, kaolin, true, {}, "shear stress: no peak for all three models (Fig. 8.2a)"),
      peaks(curves, kaolin, false, {"hce"},
            "normal stress: a peak for HCE, none for MCC and BC (Fig. 8.2b)"),
      same_asymptote(curves, kaolin, "HCE and BC reach a nearly identical asymptotic state",
                     false)};
}

std::vector<FigureSpec> chapter8_figures() {
  std::vector<FigureSpec> out;
  for (const auto& c : clays()) {
    std::vector<std::pair<std::string, std::string>> three;
    for (const auto& [model, label] : kModels) three.push_back({case_name(c, model), label});
    const std::string fig = c.key == "london" ? "8.1" : "8.2";
    const std::string stem = "fig_" + std::string(c.key == "london" ? "8_1" : "8_2");
    out.push_back({stem + "a_" + c.key + "_tau",
                   fmt::format("{}, CV: shear stress (seed Fig. {}a)", c.label, fig), Axis::kGamma,
                   Axis::kTau, three});
    out.push_back({stem + "b_" + c.key + "_sigma_n",
                   fmt::format("{}, CV: normal stress (seed Fig. {}b)", c.label, fig), Axis::kGamma,
                   Axis::kSigmaN, three});
    out.push_back({"path_" + c.key, fmt::format("{}, CV: stress paths", c.label), Axis::kSigmaN,
                   Axis::kTau, three});
  }
  return out;
}

}  // namespace

StudyDefinition chapter8_study() {
  return {
      "chapter8",
      "iwb chapter 8 study: HCE, Barodesy and modified Cam clay on the reduced vectors (seed 8.4)",
      "Seed section 8.4 redrawn: constant-volume simple shear of HCE, Barodesy for clay (BC) and "
      "modified Cam clay "
      "(MCC) with Table 8.1's London and Kaolin sets (HCE's nu 0.2, not in the table), a smooth "
      "interface (kappa_r 1); "
      "from an isotropic start at 100 kPa, normally consolidated (e0 on the isotropic NCL; the "
      "seed gives no start), "
      "to gamma 0.5.",
      chapter8_cases(),
      chapter8_claims,
      chapter8_figures()};
}

}  // namespace iwb::studies
