#include "studies/clay_cases.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "models/registry.hpp"

namespace iwb::studies {

namespace {

constexpr const char* kTable61 = "table_6_1_evaluation.toml";  // seed Table 6.1, HCC and HCE
constexpr const char* kTable64 = "table_6_4_cyclic.toml";      // seed Table 6.4, HCE with IGS

std::string label_of(double v) {
  return fmt::format("{:g}", v);
}

}  // namespace

std::vector<ClayCase> clay_cases() {
  std::vector<ClayCase> cases;
  for (const std::string m : {"hcc", "hce"}) {
    // 6.4.2: CV and CNL at 100 and 300 kPa, CNS at 100 kPa with K 100 and 1000 kPa
    for (double s : {100.0, 300.0}) {
      cases.push_back({fmt::format("cv{}_{}", label_of(s), m), m, kTable61, "CV", s});
      cases.push_back({fmt::format("cnl{}_{}", label_of(s), m), m, kTable61, "CNL", s});
    }
    for (double K : {100.0, 1000.0})
      cases.push_back(
          {fmt::format("cns100_K{}_{}", label_of(K), m), m, kTable61, "CNS", 100.0, 1.0, K});
    // the 300 kPa specimen's void ratio at 100 kPa: at one stress ratio (K0) the ASBS pressure is
    // proportional to p, so OCR 3 at 100 kPa is e0 of the normally consolidated 300 kPa start. The
    // normally consolidated responses are self-similar in stress; this one dilates.
    cases.push_back({fmt::format("cnl100_ocr3_{}", m), m, kTable61, "CNL", 100.0, 3.0});
    for (double K : {100.0, 1000.0})
      cases.push_back(
          {fmt::format("cns100_ocr3_K{}_{}", label_of(K), m), m, kTable61, "CNS", 100.0, 3.0, K});
    // 6.4.1: the 3D form of the same law under CV
    cases.push_back({fmt::format("cv100_{}3d", m), m + "3d", kTable61, "CV", 100.0});
    // 6.4.3: kappa_r 0.75 and 0.5 with the model's own scheme, and 0.5 with the other scheme
    for (double k : {0.75, 0.5})
      cases.push_back(
          {fmt::format("cnl100_{}_k{}", m, label_of(k)), m, kTable61, "CNL", 100.0, 1.0, 0.0, k});
    const std::string other = m == "hcc" ? "stutz-masin" : "arnold-herle";
    cases.push_back({fmt::format("cnl100_{}_k0.5_{}", m, other), m, kTable61, "CNL", 100.0, 1.0,
                     0.0, 0.5, other});
  }
  // 6.4.5: HCE without and with intergranular strain, Table 6.4, cyclic CNL and CV
  for (const std::string m : {"hce", "hce-igs"})
    for (const std::string bc : {"CNL", "CV"})
      cases.push_back({fmt::format("cyclic_{}_{}", bc == "CNL" ? "cnl" : "cv", m), m, kTable64, bc,
                       100.0, 1.0, 0.0, 1.0, "", true});
  return cases;
}

std::string element_test_text(const ClayCase& c, const std::string& parameters) {
  std::string t = fmt::format(
      "# iwb run --study clay: {}\ndescription = \"{}\"\n\n[model]\nname = \"{}\"\nparameters = "
      "\"{}\"\n\n",
      c.name, c.name, c.model, parameters);
  if (models::find_model(c.model).uses_roughness) {
    t += fmt::format("[roughness]\nkappa_r = {}\n", c.kappa_r);
    if (!c.scheme.empty()) t += fmt::format("scheme = \"{}\"\n", c.scheme);
    t += "\n";
  }
  t += fmt::format("[initial]\nsigma_n_kPa = {}\n", c.sigma_n_kPa);
  t += std::isnan(c.e0) ? fmt::format("OCR = {}\n", c.OCR) : fmt::format("e0 = {}\n", c.e0);
  for (const auto& [key, value] : c.initial_inputs) t += fmt::format("{} = {}\n", key, value);
  if (!std::isnan(c.K0)) t += fmt::format("K0 = {}\n", c.K0);
  if (c.model.ends_with("-igs")) t += "delta = \"seed\"\n";
  t += fmt::format("\n[shear_zone]\nd_s_mm = 1.0\n\n[boundary]\ntype = \"{}\"\n", c.boundary);
  if (c.boundary == "CNS") t += fmt::format("K_kPa = {}\n", c.K_kPa);
  if (c.cyclic)
    t += fmt::format(
        "\n[path]\nkind = \"cyclic\"\namplitude_gamma = {}\ncycles = {}\nincrements_per_quarter = "
        "{}\n",
        kCyclicAmplitude, kCycles, kIncrementsPerQuarter);
  else
    t += fmt::format(
        "\n[path]\nkind = \"monotonic\"\ngamma = {}\nincrements = {}\n\n[output]\nevery = 10\n",
        c.gamma, int(std::lround(c.gamma * kIncrementsPerUnitGamma)));
  return t;
}

std::string parameter_file_name(const ClayCase& c) {
  std::string name = c.parameters.substr(0, c.parameters.rfind(".toml"));
  for (const auto& [key, value] : c.parameter_changes)
    name += fmt::format("__{}={:g}", key.substr(key.rfind('.') + 1), value);
  return name + ".toml";
}

double ClayCurve::max_tau() const {
  return *std::max_element(tau.begin(), tau.end());
}

double ClayCurve::tau_at(double g) const {
  for (std::size_t k = 0; k < gamma.size(); ++k)
    if (gamma[k] >= g * (1.0 - 1e-9)) return tau[k];
  return NAN;
}

nlohmann::json ClayCurve::end_values() const {
  return {{"gamma", gamma.back()},
          {"eps_n", eps_n.back()},
          {"tau_kPa", tau.back()},
          {"sigma_n_kPa", sigma_n.back()}};
}

}  // namespace iwb::studies
