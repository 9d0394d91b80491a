#include "calibration/calibrate.hpp"

#include <fmt/core.h>
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <limits>

#include "calibration/simulate.hpp"
#include "common/errors.hpp"
#include "fitting/least_squares.hpp"
#include "models/registry.hpp"

namespace iwb::calibration {

namespace {

// The box the optimiser searches: each parameter's declared calibration box (ParameterSpec), the
// range sands span inside the physical bounds, finite because BOBYQA needs finite bounds; h_s is
// declared logarithmic and fitted as ln h_s.
struct BoxEntry {
  std::string key;
  double lower, upper;
  bool logarithmic;
};
using Boxes = std::vector<BoxEntry>;

// The table a model is calibrated on: `name`, or the first of its tables whose parameters declare
// boxes.
const models::ParameterTable& calibrated_table(const std::string& model, const std::string& name) {
  const auto declares_boxes = [](const models::ParameterTable& t) {
    return std::any_of(t.entries.begin(), t.entries.end(),
                       [](const auto& e) { return e.calibration.has_value(); });
  };
  std::string tables;
  for (const auto* t : models::find_model(model).tables) {
    if (!declares_boxes(*t)) continue;
    if (name.empty() || t->name == name) return *t;
    tables += (tables.empty() ? "" : ", ") + t->name;
  }
  if (!name.empty())
    throw InputError(fmt::format(
        "calibrate --table {}: model '{}' has no such table with calibration boxes (it has: {})",
        name, model, tables.empty() ? "none" : tables));
  throw InputError(fmt::format(
      "calibrate: model '{}' declares no calibration box for any parameter; it cannot be "
      "calibrated",
      model));
}

// Every table of the model but the fitted one must be held at given values.
void check_held(const std::string& model, const std::string& fitted,
                const std::map<std::string, models::ParameterValues>& held) {
  for (const auto* t : models::find_model(model).tables)
    if (t->name != fitted && held.count(t->name) == 0)
      throw InputError(fmt::format(
          "calibrate: model '{}' needs [{}] held while [{}] is fitted; give a parameter file "
          "with it (--params)",
          model, t->name, fitted));
}

// The recipe that starts `table`: the one given, else the one the model declares, if it is for
// this table (the -igs models declare Herle & Gudehus's, which starts [hypoplastic] only).
const CalibrationRecipe* recipe_for(const CalibrationOptions& o,
                                    const models::ParameterTable& table) {
  if (o.recipe && o.recipe->table != table.name)
    throw InputError(fmt::format("calibrate: recipe '{}' is for [{}], not [{}]", o.recipe->name,
                                 o.recipe->table, table.name));
  const auto* r =
      o.recipe ? o.recipe : find_recipe(models::find_model(o.model).declaration.calibration_recipe);
  return r && r->table == table.name ? r : nullptr;
}

Boxes declared_boxes(const models::ParameterTable& table) {
  Boxes out;
  for (const auto& e : table.entries)
    if (e.calibration)
      out.push_back(
          {e.key, e.calibration->lower, e.calibration->upper, e.calibration->logarithmic});
  return out;
}

double to_fit(const BoxEntry& b, double v) {
  return b.logarithmic ? std::log(v) : v;
}
double from_fit(const BoxEntry& b, double x) {
  return b.logarithmic ? std::exp(x) : x;
}

// Parameters converged when a BOBYQA step changes them by less than this: the objective is
// computed to the integrator's tolerance (1e-7), finer steps only chase its noise.
constexpr double kFitRelativeTolerance = 1e-6;
// The joint fit starts near the staged estimate: a trust region of 2 % of the box.
constexpr double kJointInitialStepShare = 0.02;
// BOBYQA's share of a refit with a factor moved: it starts at the estimate, Levenberg-Marquardt
// does the rest.
constexpr int kFactorRefitEvaluations = 20;

using Keys = std::vector<std::string>;
using Indices = std::vector<std::size_t>;

struct Calibrator {
  const std::vector<soil_test::SoilTest>& tests;
  const CalibrationOptions& options;
  std::string table;  // the model's calibrated table
  Boxes boxes;
  models::ParameterValues current;
  ObjectiveWeights weights;  // of the fit under way: unit for the stages, the options' jointly
  int evaluations = 0;
  std::vector<std::string> notes;
  // The recipe's ties, set to hold once a tied key is found unidentifiable: every trial then
  // takes the tied keys from their partners by the factors (varied by factor_uncertainty to give
  // the systematic sigma).
  std::vector<FactorTie> ties = {};
  bool ties_hold = false;
  const models::ParameterTable* declared = nullptr;  // the fitted table's declaration
  // Progress (CalibrationOptions::progress): what is being fitted, phase k of n, since when.
  std::string phase = "start";
  int phase_index = 0, phases = 1;
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now(),
                                        reported = started;

  void enter(const std::string& what) {
    phase = what;
    ++phase_index;
  }
  void report(const Eigen::VectorXd& r) {
    if (!options.progress) return;
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - reported).count() < options.progress_every_s) return;
    reported = now;
    const double rms = r.size() > 0 ? std::sqrt(r.squaredNorm() / double(r.size())) : 0.0;
    options.progress(fmt::format(
        "calibrating: {}, phase {} of {}, evaluation {}, RMS {:.4g} scatter units, {:.0f} s", phase,
        phase_index, phases, evaluations, rms,
        std::chrono::duration<double>(now - started).count()));
  }

  const BoxEntry& box(const std::string& key) const {
    for (const auto& b : boxes)
      if (key == b.key) return b;
    throw std::logic_error("no calibration box for " + key);
  }
  bool is_fixed(const std::string& key) const { return options.fixed.count(key) > 0; }
  // The fixed parameters at their given values, over whatever a stage or a trial set.
  void pin(models::ParameterValues& v) const {
    for (const auto& [k, value] : options.fixed) v[k] = value;
  }
  Keys free(const Keys& keys) const {
    Keys out;
    for (const auto& k : keys)
      if (!is_fixed(k)) out.push_back(k);
    return out;
  }

  models::ModelInputs inputs(const models::ParameterValues& v) const {
    models::ModelInputs in;
    in.tables = options.held;
    in.tables[table] = v;
    in.source = "calibration trial";
    return in;
  }

  // Scaled residuals of every weighted group (objectives.hpp), each times sqrt(weight).
  Eigen::VectorXd residuals(const models::ParameterValues& v, const Indices& which) {
    ++evaluations;
    std::vector<double> r, group;
    for (const std::size_t i : which) {
      const Simulated s = simulate(tests[i], options.model, inputs(v));
      for (const auto g : kObjectiveGroups) {
        if (weights[g] == 0.0) continue;
        group.clear();
        append_group_residuals(g, tests[i], s, group);
        for (const double x : group) r.push_back(std::sqrt(weights[g]) * x);
      }
    }
    Eigen::VectorXd out = Eigen::Map<Eigen::VectorXd>(r.data(), Eigen::Index(r.size()));
    report(out);
    return out;
  }

  models::ParameterValues with(const Keys& keys, const Eigen::VectorXd& x) const {
    models::ParameterValues v = current;
    for (std::size_t k = 0; k < keys.size(); ++k)
      if (!order_of(keys[k])) v[keys[k]] = from_fit(box(keys[k]), x(Eigen::Index(k)));
    for (std::size_t k = 0; k < keys.size(); ++k)  // after their partners
      if (order_of(keys[k])) {
        const auto [lo, hi] = span(keys[k], v);
        v[keys[k]] = from_fit(box(keys[k]), lo + x(Eigen::Index(k)) * (hi - lo));
      }
    if (ties_hold) apply_ties(ties, v);
    pin(v);
    return v;
  }

  // The order whose lower member `key` is (m_T of m_T <= m_R), when `key` is fitted: it is then
  // fitted as a share in [0, 1] of the way from its box's lower edge to its partner, so that no
  // trial breaks the order. Why: the model refuses such a set, and against that penalty wall the
  // fit of DEM cyclic tests (which ask for m_T = m_R) returned no sigma at all; holding the
  // member at its partner instead trapped a fit from the middle of the boxes (a target with m_T
  // 2, m_R 5 fitted as 4.95 and 4.95).
  const models::ParameterTable::AtMost* order_of(const std::string& key) const {
    for (const auto& o : declared->at_most)
      if (o.lower == key && !is_fixed(key)) return &o;
    return nullptr;
  }
  // The range in fit space an ordered key spans at the partner's value in `v`.
  std::pair<double, double> span(const std::string& key, const models::ParameterValues& v) const {
    const auto& b = box(key);
    const double lo = to_fit(b, b.lower);
    return {lo, std::max(lo, to_fit(b, std::min(b.upper, v.at(order_of(key)->upper))))};
  }
  // The optimiser's variable of `key` at `v`: the fit-space value, or an ordered key's share.
  double variable(const std::string& key, const models::ParameterValues& v) const {
    if (!order_of(key)) return to_fit(box(key), v.at(key));
    const auto [lo, hi] = span(key, v);
    return hi > lo ? std::clamp((to_fit(box(key), v.at(key)) - lo) / (hi - lo), 0.0, 1.0) : 0.0;
  }

  // Fits the free ones of `keys` (none free: nothing to do, an empty result).
  fitting::LeastSquaresResult fit(const Keys& all_keys, const Indices& which, int max_evaluations,
                                  double initial_step_share = 0.0, int polish_iterations = 0) {
    const Keys keys = free(all_keys);
    if (keys.empty()) return {};
    fitting::LeastSquaresProblem p;
    const auto n = Eigen::Index(keys.size());
    p.start.resize(n), p.lower.resize(n), p.upper.resize(n), p.difference_step.resize(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      const auto& b = box(keys[std::size_t(k)]);
      const bool share = order_of(b.key) != nullptr;
      p.lower(k) = share ? 0.0 : to_fit(b, b.lower);
      p.upper(k) = share ? 1.0 : to_fit(b, b.upper);
      p.start(k) = variable(b.key, current);
      // Steps well above the integrator's relative tolerance (simulate.cpp), far below the box.
      p.difference_step(k) = 1e-4 * (p.upper(k) - p.lower(k));
    }
    p.residuals = [&](const Eigen::VectorXd& x) { return residuals(with(keys, x), which); };
    fitting::LeastSquaresSettings s;
    s.max_evaluations = max_evaluations;
    s.xtol_rel = kFitRelativeTolerance;
    s.initial_step_share = initial_step_share;
    s.polish_iterations = polish_iterations;
    auto r = fitting::fit_least_squares(p, s);
    current = with(keys, r.x);
    return r;
  }

  Indices of_kind(soil_test::SoilTestKind kind) const {
    Indices out;
    for (std::size_t i = 0; i < tests.size(); ++i)
      if (tests[i].kind == kind) out.push_back(i);
    return out;
  }
  Indices all() const {
    Indices out(tests.size());
    for (std::size_t i = 0; i < tests.size(); ++i) out[i] = i;
    return out;
  }
  Indices selected(StageTests which) const {
    if (which == StageTests::kOedometer) return of_kind(soil_test::SoilTestKind::kOedometer);
    if (which == StageTests::kAll) return all();
    Indices out;  // the shear tests whose end is a critical state
    for (const auto i : of_kind(soil_test::SoilTestKind::kSimpleShear))
      if (soil_test::ends_at_critical_state(tests[i])) out.push_back(i);
    return out;
  }
  const FactorTie& tie_of(const std::string& key) const {
    for (const auto& t : ties)
      if (t.key == key) return t;
    throw std::logic_error("no factor tie for " + key);
  }
};

// Whether a stage of the recipe will be a fit on these tests (run_stage's own conditions): a phase
// of the progress lines.
bool stage_fits(const Calibrator& c, const RecipeStage& s) {
  return !s.estimate && !(s.only_with && c.of_kind(*s.only_with).empty()) &&
         !c.selected(s.tests).empty();
}

// One stage of a recipe: a closed form for its keys (the keys tied to them follow, fixed ones are
// put back) or a fit of them on its tests, noted.
void run_stage(Calibrator& c, const RecipeStage& s, const CalibrationOptions& o) {
  if (s.only_with && c.of_kind(*s.only_with).empty()) return;
  if (s.estimate && c.free(s.keys).empty()) return;  // nothing for the closed form to set
  const Indices which = c.selected(s.tests);
  if (which.empty()) {
    c.notes.push_back(s.without_tests);
    return;
  }
  if (s.estimate) {
    c.notes.push_back(s.estimate({c.tests, which}, c.current));
    std::vector<FactorTie> following;
    std::copy_if(c.ties.begin(), c.ties.end(), std::back_inserter(following), [&](const auto& t) {
      return std::find(s.keys.begin(), s.keys.end(), t.of) != s.keys.end();
    });
    apply_ties(following, c.current);
    c.pin(c.current);
    return;
  }
  c.enter(fmt::format("stage {} ({})", s.label, fmt::join(c.free(s.keys), ", ")));
  const auto r = c.fit(s.keys, which, o.max_evaluations_per_stage, 0.0, o.polish_iterations);
  c.notes.push_back(s.fitted(c.current, which.size(), r));
}

// The systematic sigma of each fitted parameter when the recipe's ties hold (e_d0 and e_i0 follow
// e_c0 by the factors): refit with each factor moved by its one-sigma spread (from the estimate, so
// only a few Levenberg-Marquardt iterations) and take the shifts, added in quadrature over both
// factors. Linear in the spread: the factors' sigmas are a few percent of their values.
Eigen::VectorXd factor_uncertainty(Calibrator& c, const Keys& keys, const CalibrationOptions& o) {
  const models::ParameterValues estimate = c.current;
  Eigen::VectorXd variance = Eigen::VectorXd::Zero(Eigen::Index(keys.size()));
  for (auto& tie : c.ties) {
    tie.factor += tie.sigma;
    c.fit(keys, c.all(), kFactorRefitEvaluations, kJointInitialStepShare, o.polish_iterations);
    for (std::size_t k = 0; k < keys.size(); ++k) {
      const auto& b = c.box(keys[k]);
      const double shift = to_fit(b, c.current.at(keys[k])) - to_fit(b, estimate.at(keys[k]));
      variance(Eigen::Index(k)) += shift * shift;
    }
    tie.factor -= tie.sigma;
    c.current = estimate;
  }
  return variance.cwiseSqrt();
}

// Judged at the scatter the residual scales declare (s^2 >= 1): a noise-free synthetic target
// has s^2 ~ 0 and would otherwise call every direction with J != 0 identified.
double identifiability_sigma(const fitting::LeastSquaresResult& r, Eigen::Index k) {
  const double m = double(r.residuals.size()), p = double(r.x.size());
  const double s2 = r.residuals.squaredNorm() / std::max(m - p, 1.0);
  return std::sqrt(std::max(s2, 1.0) * r.unit_covariance(k, k));
}

// `variable_scale`: fit space per unit of the optimiser's variable (an ordered key's share spans
// its range below its partner; 1 otherwise).
bool unidentified(const fitting::LeastSquaresResult& r, const BoxEntry& b, Eigen::Index k,
                  double variable_scale = 1.0) {
  const double s = variable_scale * identifiability_sigma(r, k);
  return !std::isfinite(s) ||
         s > kUnidentifiedShareOfBox * (to_fit(b, b.upper) - to_fit(b, b.lower));
}

// The joint fit of every free parameter with the options' weights; the recipe's tied keys (e_d0,
// e_i0) set from their partners by the factors when the tests cannot identify one of them, and
// the rest refitted.
struct JointFit {
  fitting::LeastSquaresResult result;
  Keys keys, by_factor;
  Eigen::VectorXd systematic;  // per key: the factors' share of its sigma (factor_uncertainty)
};

JointFit joint_fit(Calibrator& c, const CalibrationOptions& o) {
  c.weights = o.weights;
  JointFit j;
  for (const auto& b : c.boxes)
    if (!c.is_fixed(b.key)) j.keys.push_back(b.key);
  if (j.keys.empty()) throw InputError("calibrate: every parameter is fixed; nothing to fit");
  c.enter(fmt::format("joint fit of {} parameters", j.keys.size()));
  if (c.residuals(c.current, c.all()).size() == 0)
    throw InputError(
        "calibrate: no test gives a residual to a group of weight > 0 (--weight); nothing to "
        "fit");
  j.result =
      c.fit(j.keys, c.all(), o.max_evaluations_joint, kJointInitialStepShare, o.polish_iterations);
  for (const auto& tie : c.ties) {
    const auto it = std::find(j.keys.begin(), j.keys.end(), tie.key);
    if (it != j.keys.end() &&
        unidentified(j.result, c.box(tie.key), Eigen::Index(it - j.keys.begin())))
      j.by_factor.push_back(tie.key);
  }
  if (!j.by_factor.empty()) {  // fix them by the factors and refit the rest
    c.ties_hold = true;
    std::erase_if(j.keys, [&](const std::string& k) {
      return std::any_of(c.ties.begin(), c.ties.end(), [&](const auto& t) { return t.key == k; });
    });
    j.result = c.fit(j.keys, c.all(), o.max_evaluations_joint, kJointInitialStepShare,
                     o.polish_iterations);
  }
  j.systematic = j.by_factor.empty() ? Eigen::VectorXd::Zero(Eigen::Index(j.keys.size()))
                                     : factor_uncertainty(c, j.keys, o);
  return j;
}

// "e_d0, e_i0": the tied keys as the notes write them.
std::string tie_names(const std::vector<FactorTie>& ties) {
  std::string out;
  for (const auto& t : ties) out += (out.empty() ? "" : ", ") + t.name;
  return out;
}

// Within a thousandth of the box (in the fitted variable) of an edge: the fit wanted beyond it.
std::string at_bound(const BoxEntry& b, double value) {
  constexpr double kEdgeShare = 1e-3;
  const double lo = to_fit(b, b.lower), hi = to_fit(b, b.upper), x = to_fit(b, value);
  if (x - lo <= kEdgeShare * (hi - lo)) return "lower";
  if (hi - x <= kEdgeShare * (hi - lo)) return "upper";
  return "";
}

ParameterEstimate estimate_of(const Calibrator& c, const BoxEntry& b, const JointFit& j) {
  const double none = std::numeric_limits<double>::infinity();
  ParameterEstimate e{
      b.key, c.current.at(b.key), none, none, 0.0, none, false, false, "", "", b.lower, b.upper};
  const auto it = std::find(j.keys.begin(), j.keys.end(), b.key);
  if (c.is_fixed(b.key)) {
    e.identified = e.fixed = true;
    e.sigma = e.sigma_statistical = e.sigma_at_scatter = 0.0;
    e.how = "fixed at the value given (--fix), not fitted";
  } else if (it == j.keys.end()) {
    const auto& tie = c.tie_of(b.key);
    e.how = fmt::format("not identifiable from these tests: set to {} {} ({})", tie.factor,
                        tie.of_name, tie.source);
  } else {
    const auto k = Eigen::Index(it - j.keys.begin());
    const auto* order = c.order_of(b.key);
    // an ordered key's share to fit space (with its partner held: first order), then ln h_s:
    // sigma(h_s) = h_s sigma(ln h_s)
    const auto [lo, hi] = order ? c.span(b.key, c.current) : std::pair{0.0, 1.0};
    const double scale = (b.logarithmic ? e.value : 1.0) * (hi - lo);
    e.at_bound = at_bound(b, e.value);
    if (order && j.result.x(k) >= 1.0 - 1e-3) e.at_bound = "order";
    e.identified = !unidentified(j.result, b, k, hi - lo);
    e.sigma_statistical = scale * j.result.sigma(k);
    e.sigma_systematic = scale * j.systematic(k);
    e.sigma = std::hypot(e.sigma_statistical, e.sigma_systematic);
    e.sigma_at_scatter = scale * identifiability_sigma(j.result, k);
    e.how = e.identified
                ? (e.sigma_systematic > 0.0
                       ? fmt::format("joint fit (Gauss-Newton sigma with the {} factors' share)",
                                     tie_names(c.ties))
                       : "joint fit (Gauss-Newton sigma)")
                : fmt::format(
                      "NOT IDENTIFIED: at the declared scatter its sigma would be {:.3g}, "
                      "beyond {} of its box [{:g}, {:g}]",
                      e.sigma_at_scatter, kUnidentifiedShareOfBox, b.lower, b.upper);
  }
  if (e.at_bound == "order") {
    const auto* order = c.order_of(b.key);
    e.how += fmt::format("; AT ITS ORDER {} <= {} ({}): the tests ask for beyond it", order->lower,
                         order->upper, order->why);
  }
  return e;
}

// Fixed keys the model's table declares, at values inside their bounds; InputError otherwise.
void check_fixed(const models::ParameterTable& table, const Boxes& boxes,
                 const models::ParameterValues& fixed) {
  for (const auto& [key, value] : fixed) {
    const bool calibrated = std::any_of(boxes.begin(), boxes.end(),
                                        [&k = key](const BoxEntry& b) { return b.key == k; });
    const auto* spec = table.find(key);
    if (!calibrated)
      throw InputError(
          fmt::format("--fix {}: [{}] has no calibrated parameter '{}'", key, table.name, key));
    if (!spec->admits(value))
      throw InputError(
          fmt::format("--fix {}={:g}: outside the declared range {}", key, value, spec->range()));
  }
}

// Any other table: the middle of each box.
models::ParameterValues box_middles(const Boxes& boxes) {
  models::ParameterValues v;
  for (const auto& b : boxes)
    v[b.key] = from_fit(b, 0.5 * (to_fit(b, b.lower) + to_fit(b, b.upper)));
  return v;
}

// The start of the joint fit: the set given, else the recipe's estimate (its starting values and
// its stages in order), else the middle of the boxes.
void start_estimate(Calibrator& c, const CalibrationRecipe* recipe, const CalibrationOptions& o) {
  const bool staged = recipe && !o.start;
  c.current = o.start.value_or(staged ? recipe->start(c.tests) : box_middles(c.boxes));
  c.pin(c.current);
  if (o.start) {
    c.notes.push_back("start: the given set (the staged estimate A-D skipped)");
  } else if (!staged) {
    c.notes.push_back(
        fmt::format("start: the middle of each calibration box of [{}] (no staged recipe for it){}",
                    c.table, o.held.empty() ? "" : "; the model's other tables held as given"));
  } else {
    for (const auto& stage : recipe->stages) run_stage(c, stage, o);
  }
}

// The estimates, the tests and the objective groups at the fitted set, and the notes.
CalibrationResult result_of(Calibrator& c, const JointFit& joint) {
  CalibrationResult out;
  out.model = c.options.model;
  out.table = c.table;
  out.held = c.options.held;
  out.converged = joint.result.converged;
  if (!joint.result.converged)
    c.notes.push_back(
        "E: the joint fit did NOT converge (it stopped at its limit): the estimates "
        "and their sigmas are not to be trusted");
  const double m = double(joint.result.residuals.size()), p = double(joint.keys.size());
  out.s2 = joint.result.residuals.squaredNorm() / std::max(m - p, 1.0);
  for (const auto& b : c.boxes) out.parameters.push_back(estimate_of(c, b, joint));
  for (const auto& k : joint.by_factor)
    c.notes.push_back(
        fmt::format("{} is not identifiable from these tests (sigma beyond {} of its box): "
                    "set from {} by the usual factor",
                    k, kUnidentifiedShareOfBox, c.tie_of(k).of_name));
  const models::ModelInputs fitted = c.inputs(c.current);
  for (const auto& t : c.tests) out.tests.push_back(test_fit(t, c.options.model, fitted));
  out.objectives = group_fits(c.tests, c.options.model, fitted, c.options.weights);
  out.notes = c.notes;
  out.evaluations = c.evaluations;
  return out;
}

}  // namespace

models::ParameterValues CalibrationResult::values() const {
  models::ParameterValues v;
  for (const auto& p : parameters) v[p.key] = p.value;
  return v;
}

models::ModelInputs CalibrationResult::inputs() const {
  models::ModelInputs in;
  in.tables = held;
  in.tables[table] = values();
  in.source = "calibrated set";
  return in;
}

TestFit test_fit(const soil_test::SoilTest& t, const std::string& model,
                 const models::ModelInputs& in) {
  const Simulated s = simulate(t, model, in);
  TestFit f{t.name,
            to_string(t.kind),
            t.kind == soil_test::SoilTestKind::kOedometer ? "" : driver::to_string(t.boundary),
            s.status,
            s.rows(),
            t.rows(),
            {}};
  const auto rmse = [&](const std::string& column, const std::vector<double>& model_values,
                        const std::vector<double>& data) {
    double sum = 0.0;
    for (std::size_t i = 0; i < model_values.size(); ++i)
      sum += (model_values[i] - data[i]) * (model_values[i] - data[i]);
    const double end_model = model_values.empty() ? NAN : model_values.back();
    const double end_data =
        data.empty() ? NAN : data[model_values.empty() ? 0 : model_values.size() - 1];
    f.rmse.push_back({column,
                      std::sqrt(sum / double(std::max<std::size_t>(model_values.size(), 1))),
                      end_model, end_data});
  };
  rmse("e", s.e, t.e);
  if (soil_test::is_shear(t.kind)) {
    rmse("tau_kPa", s.tau_kPa, t.tau_kPa);
    rmse("sigma_n_kPa", s.sigma_n_kPa, t.sigma_n_kPa);
  }
  if (t.kind == soil_test::SoilTestKind::kSimpleShear && t.boundary == driver::BoundaryKind::kCNL &&
      s.rows() == t.rows()) {
    f.peak_rate_model = peak_dilatancy_rate(t.control, s.e, s.rows());
    f.peak_rate_measured = peak_dilatancy_rate(t.control, t.e, t.rows());
  }
  return f;
}

std::array<std::vector<double>, kObjectiveGroups.size()> group_residuals(
    const std::vector<soil_test::SoilTest>& tests, const std::string& model,
    const models::ModelInputs& in) {
  std::vector<Simulated> simulated(tests.size());
  // one test per task: a simulation takes milliseconds, far above TBB's scheduling cost
  tbb::parallel_for(std::size_t(0), tests.size(),
                    [&](std::size_t i) { simulated[i] = simulate(tests[i], model, in); });
  std::array<std::vector<double>, kObjectiveGroups.size()> residuals;
  for (std::size_t i = 0; i < tests.size(); ++i)
    for (const auto g : kObjectiveGroups)
      append_group_residuals(g, tests[i], simulated[i], residuals[std::size_t(g)]);
  return residuals;
}

GroupFit group_fit(ObjectiveGroup group, const std::vector<double>& r, double weight) {
  double squares = 0.0;
  std::size_t unreached = 0;
  for (const double x : r)
    if (x == kUnreachedResidual)
      ++unreached;
    else
      squares += x * x;
  const std::size_t reached = r.size() - unreached;
  return {group, weight, r.size(), reached == 0 ? 0.0 : std::sqrt(squares / double(reached)),
          unreached};
}

std::vector<GroupFit> group_fits(const std::vector<soil_test::SoilTest>& tests,
                                 const std::string& model, const models::ModelInputs& in,
                                 const ObjectiveWeights& weights) {
  const auto residuals = group_residuals(tests, model, in);
  std::vector<GroupFit> out;
  for (const auto g : kObjectiveGroups)
    if (!residuals[std::size_t(g)].empty())  // else no test of this group
      out.push_back(group_fit(g, residuals[std::size_t(g)], weights[g]));
  return out;
}

CalibrationResult calibrate(const std::vector<soil_test::SoilTest>& tests,
                            const CalibrationOptions& o) {
  if (tests.empty()) throw InputError("calibrate: no soil tests given");
  const auto t0 = std::chrono::steady_clock::now();
  const auto& table = calibrated_table(o.model, o.table);
  const Boxes boxes = declared_boxes(table);
  check_fixed(table, boxes, o.fixed);
  check_held(o.model, table.name, o.held);
  const CalibrationRecipe* recipe = recipe_for(o, table);
  Calibrator c{tests, o, table.name, boxes, {}, {}, 0, {}};
  c.declared = &table;
  if (recipe) c.ties = recipe->ties;
  if (recipe && !o.start)  // the recipe's stages that will fit, then the joint fit
    for (const auto& st : recipe->stages) c.phases += stage_fits(c, st) ? 1 : 0;
  start_estimate(c, recipe, o);
  const JointFit joint = joint_fit(c, o);
  c.notes.push_back(fmt::format(
      "E: joint fit of {} parameters on {} tests: RMS residual {:.3g} (weighted) "
      "scatter units, {} ({} evaluations in all)",
      joint.keys.size(), tests.size(), joint.result.rmse, joint.result.stop_reason, c.evaluations));
  CalibrationResult out = result_of(c, joint);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace iwb::calibration
