#include "studies/sand_study.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <nlohmann/json.hpp>

#include "element/element_run.hpp"
#include "io/parameter_sets.hpp"
#include "io/run_directory.hpp"
#include "io/toml_reader.hpp"

namespace iwb::studies {

const char* const kDefaultElementTest = R"(# Embedded default element test (iwb run).
description = "Table 5.1 sand, e0 = 0.80, sigma_n0 = 100 kPa, simple shear to gamma = 0.3"
[model]
name = "{model}"
parameters = "{parameters}"  # seed Table 5.1 ("Evaluation"), data/params/table_5_1_evaluation.toml
[initial]
sigma_n_kPa = 100
e0 = 0.80
[shear_zone]
d_s_mm = 1.0
[boundary]
type = "{boundary}"
K_kPa_per_mm = 1000
[path]
kind = "monotonic"
gamma = 0.3
increments = 3000
[output]
every = 10
)";

namespace {

// The shipped set the study runs on, built into iwb (data/params/), so that `iwb run` works from
// any directory; written into the output directory for the run directories to name.
constexpr const char* kStudyParameters = "table_5_1_evaluation.toml";

std::filesystem::path sand_parameters(const std::filesystem::path& out) {
  for (const auto& set : io::parameter_sets({}))
    if (set.name == kStudyParameters) return io::parameter_set_file(set, out / "parameters");
  throw std::logic_error(
      fmt::format("{} is not among the parameter sets built into iwb", kStudyParameters));
}

std::string test_text(const std::string& model, const std::string& bc,
                      const std::filesystem::path& parameters) {
  std::string t = kDefaultElementTest;
  auto replace = [&t](const std::string& key, const std::string& value) {
    for (auto p = t.find(key); p != std::string::npos; p = t.find(key))
      t.replace(p, key.size(), value);
  };
  replace("{model}", model);
  replace("{boundary}", bc);
  replace("{parameters}", parameters.string());
  if (bc != "CNS") replace("K_kPa_per_mm = 1000\n", "");
  return t;
}

struct SandCurve {
  double peak = 0.0, last = 0.0, e_last = 0.0, sigma_last = 0.0;
  std::vector<std::array<double, 4>> path;  // tau, sigma_n, sigma_p, e per row
};

// Largest difference of each of tau, sigma_n, sigma_p (kPa) and e between two curves.
std::array<double, 4> max_differences(const SandCurve& a, const SandCurve& b) {
  std::array<double, 4> d{0, 0, 0, 0};
  for (std::size_t k = 0; k < std::min(a.path.size(), b.path.size()); ++k)
    for (int i = 0; i < 4; ++i) d[i] = std::max(d[i], std::abs(a.path[k][i] - b.path[k][i]));
  return d;
}

SandCurve sand_curve(const element::ElementRunOutcome& o, const models::Model& m) {
  SandCurve c;
  for (const auto& r : o.result.rows) {
    const auto s = m.stress(r.state);
    c.path.push_back({s.tau_x, s.sigma_n, s.sigma_p.value_or(0.0), m.void_ratio(r.state)});
    c.peak = std::max(c.peak, s.tau_x / s.sigma_n);
    c.last = s.tau_x / s.sigma_n;
    c.e_last = m.void_ratio(r.state);
    c.sigma_last = s.sigma_n;
  }
  return c;
}

nlohmann::json row_json(const SandRow& r) {
  const auto& d = r.differences;
  return {{"hvwe_peak_tau_over_sigma_n", r.peak},
          {"hvwe_end_tau_over_sigma_n", r.last},
          {"hvwe_end_sigma_n_kPa", r.sigma_last},
          {"hvwe_end_e", r.e_last},
          {"max_abs_difference_hvwe_vw3d",
           {{"tau_kPa", d[0]}, {"sigma_n_kPa", d[1]}, {"sigma_p_kPa", d[2]}, {"e", d[3]}}}};
}

}  // namespace

bool run_sand_study(const std::filesystem::path& out, bool force, const std::string& command_line,
                    const std::function<void(const SandRow&)>& on_row) {
  nlohmann::json summary;
  bool ok = true;
  const auto parameters = sand_parameters(out);
  for (const std::string bc : {"CNL", "CNS", "CV"}) {
    SandCurve curves[2];
    int i = 0;
    std::string status;
    for (const std::string model : {"hvwe", "vw3d"}) {
      const std::string text = test_text(model, bc, parameters);
      const std::string name = fmt::format("<embedded:default {} {}>", model, bc);
      const auto spec = element::parse_element_test(io::parse_toml_text(text, name), name, ".");
      element::ElementRunOptions opt{out / fmt::format("{}-{}", model, bc), force, command_line,
                                     text, nullptr};
      const auto outcome = element::run_element_to_directory(spec, opt);
      const auto m = models::find_model(model).make(spec.inputs);
      curves[i++] = sand_curve(outcome, *m);
      status = outcome.result.status;
      ok = ok && outcome.result.complete();
    }
    const SandCurve& h = curves[0];
    const SandRow row{
        bc, h.peak, h.last, h.sigma_last, h.e_last, max_differences(curves[0], curves[1]), status};
    on_row(row);
    summary[bc] = row_json(row);
  }
  io::write_atomically(out / "summary.json", summary.dump(2) + "\n");
  return ok;
}

}  // namespace iwb::studies
