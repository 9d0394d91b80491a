#include "assessment/element_sensitivity.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "assessment/evaluate.hpp"
#include "common/errors.hpp"
#include "driver/element_test.hpp"
#include "driver/path.hpp"

namespace iwb::assessment {

namespace {

using Ties = std::map<std::string, std::pair<double, std::string>>;

bool material(const models::ParameterSpec& e) {
  return e.role == models::ParameterRole::kMaterial ||
         e.role == models::ParameterRole::kCriticalFrictionAngle;
}

// Where each varied parameter lives: table and key, in the order of varied_parameters.
std::vector<std::pair<std::string, std::string>> locations(const models::ModelSpec& spec,
                                                           const models::ModelInputs& in,
                                                           const Ties& ties = {}) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto* table : spec.tables)
    for (const auto& e : table->entries)
      if (material(e) && in.tables.at(table->name).at(e.key) != 0.0 && !ties.count(e.key))
        out.emplace_back(table->name, e.key);
  return out;
}

// The table holding `key` in the model's tables; InputError naming what the model has.
std::string table_holding(const models::ModelSpec& spec, const std::string& key,
                          const std::string& option) {
  for (const auto* table : spec.tables)
    if (table->find(key)) return table->name;
  throw InputError(fmt::format("{}: {} has no parameter '{}'", option, spec.name, key));
}

// The tied parameters set from the ones they follow.
void apply_ties(const models::ModelSpec& spec, const Ties& ties, models::ModelInputs& in) {
  for (const auto& [key, tie] : ties)
    in.tables[table_holding(spec, key, "--tie")][key] =
        tie.first * in.tables.at(table_holding(spec, tie.second, "--tie")).at(tie.second);
}

constexpr std::size_t kQuantities = 5;  // kQuantityNames below

// One element test; NaN quantities where the model refuses the sample or the run stops.
std::vector<double> run_once(const models::ModelSpec& spec, const ElementSensitivityOptions& o,
                             const std::vector<std::pair<std::string, std::string>>& where,
                             const std::vector<double>& x) {
  const std::vector<double> failed(kQuantities, NAN);
  try {
    models::ModelInputs in = o.inputs;
    for (std::size_t i = 0; i < x.size(); ++i) in.tables[where[i].first][where[i].second] = x[i];
    apply_ties(spec, o.ties, in);
    const auto model = spec.make(in);
    const auto s0 = model->initial_state(
        models::offer(spec, in, {{"sigma_n_kPa", o.sigma_n_kPa}, {"e0", o.e0}}));
    driver::RunSettings rs;
    rs.output_every = 1;
    const auto r = driver::run_element_test(
        *model, s0,
        driver::monotonic_path({o.boundary, o.K_kPa_per_unit_strain}, o.gamma,
                               driver::ShearDirection::kX, o.increments),
        rs);
    if (r.status != "complete") return failed;
    double peak = 0.0, mean = 0.0;  // the path's average: the elastic branch's share in it too
    for (std::size_t i = 0; i < r.rows.size(); ++i) {
      const auto st = model->stress(r.rows[i].state);
      peak = std::max(peak, st.tau_x / st.sigma_n);
      if (i > 0) mean += st.tau_x / st.sigma_n / double(r.rows.size() - 1);
    }
    const auto end = model->stress(r.rows.back().state);
    return {peak, mean, end.tau_x / end.sigma_n, r.rows.back().eps_n, end.sigma_n};
  } catch (const std::exception&) {
    return failed;
  }
}

}  // namespace

std::vector<Distribution> varied_parameters(const models::ModelSpec& spec,
                                            const models::ModelInputs& in, double cov,
                                            const std::map<std::string, double>& cov_of,
                                            const Ties& ties) {
  for (const auto& [key, tie] : ties)
    table_holding(spec, key, "--tie"), table_holding(spec, tie.second, "--tie");
  std::vector<Distribution> out;
  std::string keys;
  for (const auto& [table, key] : locations(spec, in, ties)) {
    const auto own = cov_of.find(key);
    out.push_back({key, Distribution::Kind::kNormal, in.tables.at(table).at(key),
                   own == cov_of.end() ? cov : own->second});
    keys += (keys.empty() ? "" : ", ") + key;
  }
  for (const auto& [key, value] : cov_of)
    if (std::none_of(out.begin(), out.end(),
                     [&k = key](const Distribution& d) { return d.name == k; }))
      throw InputError(fmt::format("--cov-of {}={}: {} varies no parameter '{}'; it varies {}", key,
                                   value, spec.name, key, keys));
  return out;
}

const std::vector<std::string> kQuantityNames{"peak_friction", "mean_friction", "end_friction",
                                              "end_normal_strain", "end_sigma_n_kPa"};

SobolResult element_sensitivity(const models::ModelSpec& spec, const ElementSensitivityOptions& o) {
  const auto where = locations(spec, o.inputs, o.ties);
  const auto params = varied_parameters(spec, o.inputs, o.cov, o.cov_of, o.ties);
  const long total = long(o.samples) * long(params.size() + 2);
  const Quantities f = with_progress(
      [&](const std::vector<double>& x) { return run_once(spec, o, where, x); }, total, o.progress);
  return total_sobol_indices(params, kQuantityNames, f, o.samples, o.seed, 200, o.threads);
}

UncertaintyResult element_uncertainty(const models::ModelSpec& spec,
                                      const ElementSensitivityOptions& o,
                                      const std::vector<Distribution>& distributions) {
  std::vector<std::pair<std::string, std::string>> where;
  for (const auto& d : distributions) {
    const models::ParameterTable* found = nullptr;
    for (const auto* table : spec.tables)
      if (table->find(d.name)) found = table;
    if (!found)
      throw InputError(fmt::format("{} has no parameter '{}' to distribute", spec.name, d.name));
    where.emplace_back(found->name, d.name);
  }
  const Quantities f =
      with_progress([&](const std::vector<double>& x) { return run_once(spec, o, where, x); },
                    o.samples, o.progress);
  return parameter_uncertainty(distributions, kQuantityNames, f, o.samples, o.seed, o.threads);
}

}  // namespace iwb::assessment
