#include "assessment/league.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "assessment/distribution_file.hpp"
#include "assessment/evaluate.hpp"
#include "common/errors.hpp"
#include "comparison/compare/compare.hpp"

namespace iwb::assessment {

namespace fs = std::filesystem;
using comparison::DemRun;

namespace {

template <class T>
std::vector<T> first(const std::vector<T>& v, std::size_t n) {
  return std::vector<T>(v.begin(), v.begin() + long(std::min(n, v.size())));
}

bool cv_boundary(const DemRun& dem) {
  return dem.boundary == driver::BoundaryKind::kCV;
}

// The floor of the normal points' denominators: the verdicts' (0.02 d50 of u_n, 1 kPa of sigma_n).
double normal_floor(const DemRun& dem) {
  return cv_boundary(dem) ? 1.0 : 0.02 * dem.d50_mm;
}

// The distributions of the model's parameters, about their values in `inputs`: each table's file
// <dir>/<table>.toml gives kind and COV (its means are the seed's data sets, not this scene's).
// A parameter without a file entry is held; so is one whose value a lognormal cannot take.
std::vector<Distribution> distributions_about(const models::ModelSpec& spec,
                                              const models::ModelInputs& inputs,
                                              const std::map<std::string, std::string>& files,
                                              std::vector<std::string>& held,
                                              std::vector<models::FitParameter>& where) {
  std::vector<Distribution> out;
  for (const auto* table : spec.tables) {
    const std::string file = table->name + ".toml";
    std::vector<Distribution> given;
    if (const auto f = files.find(file); f != files.end())
      given = parse_distributions(f->second, file);
    for (const auto& d : given)
      if (!table->find(d.name))
        throw InputError(fmt::format("{}: [[parameter]] key = \"{}\": [{}] has no such parameter",
                                     file, d.name, table->name));
    for (const auto& e : table->entries) {
      if (e.role != models::ParameterRole::kMaterial &&
          e.role != models::ParameterRole::kCriticalFrictionAngle)
        continue;
      const double v = inputs.tables.at(table->name).at(e.key);
      const auto d = std::find_if(given.begin(), given.end(),
                                  [&](const Distribution& g) { return g.name == e.key; });
      if (d == given.end() || v == 0.0 || (d->kind == Distribution::Kind::kLognormal && v < 0.0)) {
        held.push_back(e.key);
        continue;
      }
      out.push_back({e.key, d->kind, v, d->cov});
      where.push_back({e.key, models::FitParameter::Target::kParameter, table->name, e.key});
    }
  }
  return out;
}

// A fit's sigma above this share of its value does not identify the quantity: it is held, and
// the note says so, rather than sampled across signs and orders of magnitude.
constexpr double kNotIdentifiedCov = 0.5;

// Each fitted quantity spread by its own sigma: normal, or lognormal where it was fitted as ln x
// (a stiffness, d_s); a quantity without a usable sigma (not identified) is held.
std::vector<Distribution> distributions_of_fit(const comparison::VariantFit& fit,
                                               const std::vector<comparison::Unknown>& unknowns,
                                               std::vector<std::string>& held,
                                               std::vector<models::FitParameter>& where) {
  std::vector<Distribution> out;
  for (std::size_t k = 0; k < fit.values.size(); ++k) {
    const auto& v = fit.values[k];
    const double cov = v.value != 0.0 ? v.sigma / std::abs(v.value) : NAN;
    if (!(std::isfinite(cov) && cov > 0.0 && cov <= kNotIdentifiedCov)) {
      held.push_back(v.name + " (not identified)");
      continue;
    }
    const auto kind =
        unknowns[k].what.logarithmic ? Distribution::Kind::kLognormal : Distribution::Kind::kNormal;
    out.push_back({v.name, kind, v.value, cov});
    where.push_back(unknowns[k].what);
  }
  return out;
}

// A variant with the sampled values x set where they go.
comparison::Variant with_values(comparison::Variant v,
                                const std::vector<models::FitParameter>& where,
                                const std::vector<double>& x) {
  for (std::size_t i = 0; i < where.size(); ++i) comparison::set_value(v, where[i], x[i]);
  return v;
}

// Least-squares slope of y over the last fifth of x.
double slope_last_fifth(const std::vector<double>& x, const std::vector<double>& y) {
  const double from = x.front() + 0.8 * (x.back() - x.front());
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i] >= from) n += 1, sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  const double d = n * sxx - sx * sx;
  return d > 0 ? (n * sxy - sx * sy) / d : NAN;
}

double last_fifth_mean(const ResponseCurve& c) {
  const double from = c.u_x.front() + 0.8 * (c.u_x.back() - c.u_x.front());
  double s = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < c.u_x.size(); ++i)
    if (c.u_x[i] >= from) s += c.tau[i], ++n;
  return n > 0 ? s / n : NAN;
}

// The league's quantities of one replay, then tau at every reference row (NaN where it stopped).
std::vector<double> sample_outputs(const DemRun& dem, const comparison::Replay& r) {
  const std::size_t rows = dem.u_x_mm.size();
  std::vector<double> out(4 + rows, NAN);
  if (r.u_x_mm.size() < rows) return out;  // a run that stopped early fails the sample
  const auto c = response_curve(dem, r.u_x_mm, r.tau_kPa, r.u_n_mm, r.sigma_n_kPa);
  out[0] = *std::max_element(c.tau.begin(), c.tau.end());
  out[1] = last_fifth_mean(c);
  out[2] = c.normal.back();
  out[3] = slope_last_fifth(c.u_x, c.normal);
  std::copy(c.tau.begin(), c.tau.end(), out.begin() + 4);
  return out;
}

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  return v.empty() ? NAN : v[std::size_t(p * double(v.size() - 1) + 0.5)];
}

}  // namespace

SceneReference scene_reference(const std::vector<DemRun>& runs) {
  if (runs.empty()) throw InputError("a league needs at least one DEM run");
  const std::vector<DemRun> others(runs.begin() + 1, runs.end());
  SceneReference ref{runs.front(), comparison::seed_scatter(runs.front(), others)};
  auto& m = ref.mean;
  const std::size_t n = ref.scatter.rows;
  m.t_s = first(m.t_s, n), m.u_x_mm = first(m.u_x_mm, n), m.e_band = first(m.e_band, n);
  m.tau_kPa = first(ref.scatter.tau.mean, n), m.u_n_mm = first(ref.scatter.u_n.mean, n);
  m.sigma_n_kPa = first(ref.scatter.sigma_n.mean, n);
  if (n < 5)
    throw InputError(
        fmt::format("{}: fewer than 5 rows that every seed covers", runs.front().dir.string()));
  return ref;
}

ResponseCurve response_curve(const DemRun& dem, const std::vector<double>& u_x,
                             const std::vector<double>& tau, const std::vector<double>& u_n,
                             const std::vector<double>& sigma_n) {
  ResponseCurve c{u_x, tau, {}};
  const auto& normal = cv_boundary(dem) ? sigma_n : u_n;
  for (double v : normal) c.normal.push_back(v - normal.front());
  return c;
}

std::vector<comparison::Unknown> calibration_unknowns(const models::ModelSpec& spec,
                                                      const DemRun& dem) {
  using Target = models::FitParameter::Target;
  const auto& d = spec.declaration;
  std::vector<comparison::Unknown> out;
  for (const auto& f : d.fit) {
    const double scale = f.per_d50 ? dem.d50_mm : 1.0;
    out.push_back({f, f.lower * scale, f.upper * scale});
  }
  if (d.fit.empty() && !d.displacement_based)
    out.push_back({{"d_s_mm", Target::kShearZone, {}, {}, 1.0, 40.0, true, true},
                   1.0 * dem.d50_mm,
                   40.0 * dem.d50_mm});
  if (!d.calibration_recipe.empty()) return out;  // the material is calibrated from soil tests
  for (const auto* table : spec.tables)
    for (const auto& e : table->entries)
      if (e.calibration && e.role != models::ParameterRole::kOption) {
        models::FitParameter p{e.key, Target::kParameter, table->name, e.key};
        p.logarithmic = e.calibration->logarithmic;
        out.push_back({p, e.calibration->lower, e.calibration->upper});
      }
  return out;
}

const std::vector<std::string>& league_quantities() {
  static const std::vector<std::string> q{"peak_tau_kPa", "residual_tau_kPa", "normal_end",
                                          "normal_rate"};
  return q;
}

LeagueEntry assess_model(const SceneReference& ref, const std::string& model,
                         const models::ModelInputs& start, const LeagueOptions& o) {
  const auto& spec = models::find_model(model);
  const DemRun& dem = ref.mean;
  LeagueEntry e;
  e.model = model;
  e.parameters_source = start.source;
  auto variant = comparison::standard_variants(dem, model, start).front();
  const auto unknowns = calibration_unknowns(spec, dem);
  e.fit =
      comparison::fit_variant(dem, variant, comparison::joint_targets(dem, ref.scatter), unknowns);
  const auto best = comparison::replay(dem, e.fit.best);
  e.verdicts = comparison::judge(dem, ref.scatter, best, comparison::tolerances_for(dem));
  e.reference = response_curve(dem, dem.u_x_mm, dem.tau_kPa, dem.u_n_mm, dem.sigma_n_kPa);
  e.fitted = response_curve(dem, best.u_x_mm, best.tau_kPa, best.u_n_mm, best.sigma_n_kPa);
  if (best.status != "complete")
    e.status = "the calibrated model stops before the end: " + best.status;
  e.model_uncertainty = model_uncertainty(e.reference, e.fitted, normal_floor(dem));

  e.distributions =
      o.spread == ParameterSpread::kSeedCovs
          ? distributions_about(spec, e.fit.best.inputs, o.distributions, e.held, e.sampled)
          : distributions_of_fit(e.fit, unknowns, e.held, e.sampled);
  const long runs =
      long(o.uncertainty_samples) +
      (o.sobol_samples > 0 ? long(o.sobol_samples) * long(e.distributions.size() + 2) : 0);
  const Quantities f = with_progress(
      [&](const std::vector<double>& x) {
        return sample_outputs(dem, comparison::replay(dem, with_values(e.fit.best, e.sampled, x)));
      },
      runs, o.progress);
  if (!e.distributions.empty()) {
    const auto outputs = evaluate_rows(
        latin_hypercube(e.distributions, o.uncertainty_samples, o.seed), f, o.threads);
    std::vector<std::vector<double>> quantities;
    for (const auto& q : outputs) quantities.emplace_back(q.begin(), q.begin() + 4);
    e.parameter_uncertainty = summarize(league_quantities(), quantities);
    for (std::size_t row = 0; row < dem.u_x_mm.size(); ++row) {
      std::vector<double> tau;
      for (const auto& q : outputs)
        if (std::isfinite(q[0])) tau.push_back(q[4 + row]);
      e.band_low.push_back(percentile(tau, 0.05)), e.band_high.push_back(percentile(tau, 0.95));
    }
    e.ua_par = e.parameter_uncertainty.quantities.front().cv;
    if (o.sobol_samples > 0) {
      const Quantities four = [&](const std::vector<double>& x) {
        const auto q = f(x);
        return std::vector<double>(q.begin(), q.begin() + 4);
      };
      e.sobol = total_sobol_indices(e.distributions, league_quantities(), four, o.sobol_samples,
                                    o.seed + 1, 200, o.threads);
    }
  }
  e.global_shear = root_sum_square({e.model_uncertainty.shear_norm, e.ua_par});
  e.global =
      root_sum_square({e.model_uncertainty.shear_norm, e.model_uncertainty.normal_norm, e.ua_par});
  return e;
}

}  // namespace iwb::assessment
