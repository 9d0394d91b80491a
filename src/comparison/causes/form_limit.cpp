#include "comparison/causes/form_limit.hpp"

#include <fmt/core.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "common/errors.hpp"
#include "comparison/compare/compare.hpp"
#include "comparison/replay/fit.hpp"
#include "comparison/verdicts/form_limit_causes.hpp"
#include "comparison/verdicts/verdicts.hpp"
#include "fitting/constrained.hpp"
#include "fitting/least_squares.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::comparison {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

bool named_in(const std::vector<std::string>& free, const std::string& table,
              const std::string& key) {
  return std::find(free.begin(), free.end(), key) != free.end() ||
         std::find(free.begin(), free.end(), table + "." + key) != free.end();
}

// The material unknowns: every parameter of the model's tables with a declared calibration box
// (`free` empty), or those `free` names.
std::vector<Unknown> material_unknowns(const models::ModelSpec& spec,
                                       const std::vector<std::string>& free = {}) {
  std::vector<Unknown> out;
  for (const auto* table : spec.tables)
    for (const auto& e : table->entries)
      if (e.calibration && (free.empty() || named_in(free, table->name, e.key)))
        out.push_back(
            {{e.key, models::FitParameter::Target::kParameter, table->name, e.key,
              e.calibration->lower, e.calibration->upper, false, e.calibration->logarithmic},
             e.calibration->lower,
             e.calibration->upper});
  return out;
}

// Each name of --free is a parameter of the model's tables with a calibration box.
void check_free(const models::ModelSpec& spec, const std::vector<std::string>& free) {
  for (const auto& name : free) {
    bool found = false;
    for (const auto* table : spec.tables)
      for (const auto& e : table->entries)
        if (e.calibration && named_in({name}, table->name, e.key)) found = true;
    if (!found)
      throw InputError(fmt::format(
          "form-limit: --free {}: not a parameter of {} with a calibration box (iwb models {} "
          "lists them; write KEY or TABLE.KEY)",
          name, spec.name, spec.name));
  }
}

// A wall: the runs of one R_n and d50 share its kappa_r and d_s.
struct Wall {
  double R_n, d50_mm;
  std::string name() const { return wall_name(R_n, d50_mm); }
};

struct Problem {
  std::vector<DemRun> runs;  // the fit runs, then the held-out ones
  std::size_t fitted = 0;
  std::vector<SeedScatter> scatters;  // per run: its cell among all runs given
  std::vector<FitTargets> targets;
  std::vector<Variant> starts;  // per run: the predicted variant of the soil-test set
  std::vector<std::size_t> wall_of;
  std::vector<Wall> walls;
  std::vector<Unknown> unknowns;  // the material ones first, then each wall's fit parameters
  std::size_t materials = 0, per_wall = 0;
  // Walls of the fit runs come first (runs are read in order): only they have fit unknowns. A
  // held-out run on a wall no fit run has keeps its prediction: nothing fitted says anything of it.
  std::size_t fitted_walls = 0;

  std::size_t unknown_of(std::size_t wall, std::size_t f) const {
    return materials + wall * per_wall + f;
  }
  Variant variant_at(std::size_t run, const Eigen::VectorXd& x) const {
    Variant v = starts[run];
    for (std::size_t k = 0; k < materials; ++k) set_value(v, unknowns[k].what, at(k, x));
    if (wall_of[run] >= fitted_walls) return v;
    for (std::size_t f = 0; f < per_wall; ++f) {
      const auto k = unknown_of(wall_of[run], f);
      set_value(v, unknowns[k].what, at(k, x));
    }
    return v;
  }
  double at(std::size_t k, const Eigen::VectorXd& x) const {
    return unknowns[k].what.logarithmic ? std::exp(x(Eigen::Index(k))) : x(Eigen::Index(k));
  }
  double to_x(std::size_t k, double v) const {
    return unknowns[k].what.logarithmic ? std::log(v) : v;
  }
};

std::size_t wall_index(std::vector<Wall>& walls, const DemRun& r) {
  for (std::size_t w = 0; w < walls.size(); ++w)
    if (std::abs(walls[w].R_n - r.R_n) < 1e-9 && std::abs(walls[w].d50_mm - r.d50_mm) < 1e-9)
      return w;
  walls.push_back({r.R_n, r.d50_mm});
  return walls.size() - 1;
}

// The wall's fit parameters of the model's declaration, boxes in the wall's d50 where per d50.
void add_wall_unknowns(Problem& p, const models::ModelSpec& spec) {
  for (std::size_t i = 0; i < p.fitted_walls; ++i)
    for (const auto& f : spec.declaration.fit) {
      const auto& w = p.walls[i];
      const double scale = f.per_d50 ? w.d50_mm : 1.0;
      Unknown u{f, f.lower * scale, f.upper * scale};
      u.what.name = fmt::format("{} ({})", f.name, w.name());
      p.unknowns.push_back(u);
    }
}

Problem set_up(const FormLimitOptions& o, const models::ModelInputs& soil_set) {
  const auto& spec = models::find_model(o.model);
  Problem p;
  for (const auto& d : o.fit_runs) p.runs.push_back(load_dem_run(d));
  p.fitted = p.runs.size();
  for (const auto& d : o.held_out) p.runs.push_back(load_dem_run(d));
  for (const auto& r : p.runs) {
    p.scatters.push_back(seed_scatter(r, seeds_of(r, p.runs)));
    p.targets.push_back(joint_targets(r, p.scatters.back()));
    p.starts.push_back(standard_variants(r, o.model, soil_set).front());
    p.wall_of.push_back(wall_index(p.walls, r));
    if (p.wall_of.size() == p.fitted) p.fitted_walls = p.walls.size();
  }
  p.unknowns = material_unknowns(spec, o.free);
  p.materials = p.unknowns.size();
  p.per_wall = o.hold_walls ? 0 : spec.declaration.fit.size();
  if (!o.hold_walls) add_wall_unknowns(p, spec);
  return p;
}

void check_inputs(const FormLimitOptions& o) {
  const auto& spec = models::find_model(o.model);
  if (material_unknowns(spec).empty())
    throw InputError(fmt::format(
        "form-limit: model '{}' declares no calibration box for any parameter: there are no "
        "declared bounds to fit its form within",
        o.model));
  check_free(spec, o.free);
  if (o.hold_walls && material_unknowns(spec, o.free).empty())
    throw InputError("form-limit: --hold-walls with nothing else to fit");
  if (o.fit_runs.empty()) throw InputError("form-limit: no run to fit (--runs)");
  // a run twice would count its residuals twice, or be judged on the fit it took part in
  io::refuse_repeated_directories(
      "form-limit", {{o.fit_runs, "fit", "--runs"}, {o.held_out, "hold out", "--held-out"}});
}

// The fit runs' residuals at x, each run replayed on its own core (a replay is independent of
// every other; they are joined in run order, so the result does not depend on the schedule).
Eigen::VectorXd interface_residuals(const Problem& p, const Eigen::VectorXd& x) {
  std::vector<Eigen::VectorXd> per_run(p.fitted);
  tbb::parallel_for(std::size_t(0), p.fitted, [&](std::size_t i) {
    per_run[i] = fit_residuals(p.runs[i], replay(p.runs[i], p.variant_at(i, x)), p.targets[i]);
  });
  Eigen::Index n = 0;
  for (const auto& r : per_run) n += r.size();
  Eigen::VectorXd out(n);
  n = 0;
  for (const auto& r : per_run) out.segment(n, r.size()) = r, n += r.size();
  return out;
}

// The box of each unknown in the fit's coordinates, and the start: the soil-test set, and each
// wall's predicted kappa_r and d_s (its first run's).
struct Box {
  Eigen::VectorXd start, lower, upper;
};

Box box_of(const Problem& p) {
  const auto n = Eigen::Index(p.unknowns.size());
  Box b{Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (std::size_t k = 0; k < p.unknowns.size(); ++k) {
    const auto& u = p.unknowns[k];
    const auto i = Eigen::Index(k);
    b.lower(i) = p.to_x(k, u.lower), b.upper(i) = p.to_x(k, u.upper);
    std::size_t run = 0;
    if (k >= p.materials)
      while (p.wall_of[run] != (k - p.materials) / p.per_wall) ++run;
    b.start(i) = std::clamp(p.to_x(k, value_of(p.starts[run], u.what)), b.lower(i), b.upper(i));
  }
  return b;
}

struct Fitted {
  Eigen::VectorXd x;
  fitting::LeastSquaresResult result;
  double seconds = 0.0;
};

Fitted fit(const Problem& p, const FormLimitOptions& o) {
  const auto n = Eigen::Index(p.unknowns.size());
  const Box b = box_of(p);
  fitting::LeastSquaresProblem lsq;
  lsq.start = b.start, lsq.lower = b.lower, lsq.upper = b.upper;
  lsq.difference_step = 1e-4 * (b.upper - b.lower);
  fitting::LeastSquaresSettings s;
  s.max_evaluations = o.max_evaluations;
  s.polish_iterations = o.polish_iterations;
  const auto t0 = std::chrono::steady_clock::now();
  int evaluations = 0;
  const int budget = fitting::most_evaluations(s, int(n));
  lsq.residuals = [&](const Eigen::VectorXd& x) {
    const Eigen::VectorXd out = interface_residuals(p, x);
    if (++evaluations % 100 == 0 && o.progress) {
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      o.progress(fmt::format(
          "{}: {} of at most {} evaluations, RMS {:.4g} scatter units, {:.0f} s, ETA at most "
          "~{:.0f} s",
          o.restricted() ? "fit" : "form limit", evaluations, budget,
          std::sqrt(out.squaredNorm() / double(out.size())), seconds,
          seconds / evaluations * std::max(0, budget - evaluations)));
    }
    return out;
  };
  Fitted f{{}, fitting::fit_least_squares(lsq, s), 0.0};
  f.x = f.result.x;
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return f;
}

// The soil tests' verdict on a set: each group's RMS against kSoilAcceptance times the soil-test
// set's, and the groups that refuse it.
struct SoilJudgement {
  std::vector<FormLimitOptions::SoilGroup> groups;
  bool accepted = true;
  std::vector<std::string> refusing;
};

using Groups = std::vector<FormLimitOptions::SoilGroup>;

// Rows a set leaves unreached beyond the soil-test set's own.
std::size_t more_unreached(const FormLimitOptions::SoilGroup& at,
                           const FormLimitOptions::SoilGroup& soil_set) {
  return at.unreached > soil_set.unreached ? at.unreached - soil_set.unreached : 0;
}

// c_g = RMS_g / (factor RMS_g at the soil-test set) - 1 per group, each row unreached beyond the
// soil-test set's own adding 1: the set is accepted where every c_g <= 0.
Eigen::VectorXd soil_constraints(const Groups& at, const Groups& soil_set, double factor) {
  Eigen::VectorXd c(Eigen::Index(at.size()));
  for (std::size_t g = 0; g < at.size(); ++g)
    c(Eigen::Index(g)) = at[g].rms / (factor * std::max(soil_set[g].rms, 1e-12)) - 1.0 +
                         double(more_unreached(at[g], soil_set[g]));
  return c;
}

SoilJudgement judge_soil(const Groups& at, const Groups& soil_set, double factor) {
  SoilJudgement j{at, true, {}};
  const auto c = soil_constraints(at, soil_set, factor);
  for (std::size_t g = 0; g < at.size(); ++g)
    if (c(Eigen::Index(g)) > 0.0)
      j.accepted = false,
      j.refusing.push_back(fmt::format(
          "{} RMS {:.3g} against {:.3g} ({:.3g} x {:.3g}){}", at[g].group, at[g].rms,
          factor * soil_set[g].rms, factor, soil_set[g].rms,
          more_unreached(at[g], soil_set[g])
              ? fmt::format(", {} more rows not reached", more_unreached(at[g], soil_set[g]))
              : std::string()));
  return j;
}

FormLimitOptions::Tables tables_at(const Problem& p, const Eigen::VectorXd& x) {
  return p.variant_at(0, x).inputs.tables;
}

constexpr int kJointPasses = 4;
constexpr int kJointStarts = 2;  // the soil-test set and the free form limit's (fit_joint)
constexpr double kRestartGain = 0.01;

struct JointFit {
  Eigen::VectorXd x;
  fitting::ConstrainedResult result;
  SoilJudgement soil;
  double seconds = 0.0;
};

// COBYLA from c.start, restarted from where it stopped with a fresh simplex while a pass still
// lowers ||r||^2 by kRestartGain among the sets that meet the constraints (at most kJointPasses
// passes): its linear models can stop short on a curved boundary. A "calibration" is certified by
// the set found (form_limit_joint.toml, which the soil tests accept); a "form" only says that this
// search found no accepted set that holds.
fitting::ConstrainedResult search_feasible(fitting::ConstrainedProblem c,
                                           const fitting::ConstrainedSettings& s) {
  auto best = fitting::fit_constrained(c, s);
  int used = best.evaluations;
  for (int pass = 1; pass < kJointPasses && best.feasible; ++pass) {
    c.start = best.x;
    const auto again = fitting::fit_constrained(c, s);
    used += again.evaluations;
    const double before = best.at.residuals.squaredNorm();
    const bool better = again.feasible && again.at.residuals.squaredNorm() < before;
    if (better) best = again;
    if (!better || again.at.residuals.squaredNorm() > (1.0 - kRestartGain) * before) break;
  }
  best.evaluations = used;
  return best;
}

// The fit runs' residuals as in the free fit, over the sets the soil tests accept (search_feasible
// from two starts), each point's runs and soil tests in parallel.
JointFit fit_joint(const Problem& p, const FormLimitOptions& o, const Groups& soil_set,
                   const Eigen::VectorXd& free_x) {
  const Box b = box_of(p);
  fitting::ConstrainedProblem c;
  c.start = b.start, c.lower = b.lower, c.upper = b.upper;
  c.constraints = Eigen::Index(soil_set.size());
  const auto t0 = std::chrono::steady_clock::now();
  int evaluations = 0;
  c.evaluate = [&](const Eigen::VectorXd& x) {
    fitting::ConstrainedEvaluation e{
        interface_residuals(p, x),
        soil_constraints(o.soil_tests(tables_at(p, x)), soil_set, o.soil_acceptance)};
    if (++evaluations % 50 == 0 && o.progress) {
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      o.progress(fmt::format(
          "form limit with the soil tests: {} of at most {} evaluations, RMS {:.4g} scatter "
          "units{}, {:.0f} s, ETA at most ~{:.0f} s",
          evaluations, kJointStarts * kJointPasses * o.joint_evaluations,
          std::sqrt(e.residuals.squaredNorm() / double(e.residuals.size())),
          (e.constraints.array() <= 0.0).all() ? "" : " (soil tests refuse this set)", seconds,
          seconds / evaluations *
              std::max(0, kJointStarts * kJointPasses * o.joint_evaluations - evaluations)));
    }
    return e;
  };
  fitting::ConstrainedSettings s;
  s.max_evaluations = o.joint_evaluations;
  JointFit j;
  // Two starts: the soil-test set (accepted by construction) and the free form limit's set
  // (refused, as a rule, but near what the walls ask for): COBYLA finds different optima from
  // them, and the sets a looser acceptance admits are not always reached from the first alone.
  c.start = b.start;
  j.result = search_feasible(c, s);
  c.start = free_x;
  const auto from_free = search_feasible(c, s);
  const int used = j.result.evaluations + from_free.evaluations;
  if (from_free.feasible && (!j.result.feasible || from_free.at.residuals.squaredNorm() <
                                                       j.result.at.residuals.squaredNorm()))
    j.result = from_free;
  j.result.evaluations = used;
  j.x = j.result.x;
  j.soil = judge_soil(o.soil_tests(tables_at(p, j.x)), soil_set, o.soil_acceptance);
  j.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return j;
}

// The soil-test set's sigma per key, from its calibration.json (parameters[].sigma: a number, or
// null where the calibration could not tell). Read before anything is written: a truncated or
// edited file is refused before the fit, not after it with the manifest left "running" (issue 60).
std::map<std::string, double> soil_sigmas(const FormLimitOptions& o) {
  std::map<std::string, double> out;
  const auto file =
      o.calibration.empty() ? fs::path(o.params).parent_path() / "calibration.json" : o.calibration;
  if (!fs::exists(file)) return out;
  const auto j = io::read_json_file(file);
  if (io::json_optional<std::string>(j, "/kind", file).value_or("") != "calibration")
    throw InputError(
        fmt::format("{}: not a calibration record (iwb calibrate's calibration.json, \"kind\": "
                    "\"calibration\")",
                    file.string()));
  const auto& parameters = io::json_array(j, "/parameters", file);
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const auto at = fmt::format("/parameters/{}", i);
    const auto key = io::json_field<std::string>(j, at + "/key", file);
    if (const auto sigma = io::json_optional<double>(j, at + "/sigma", file)) out[key] = *sigma;
  }
  return out;
}

// Each unknown's value at x, with its sigma where the fit gives one (the free fit's Gauss-Newton
// sigma; the constrained fit has none), its box and its move from the soil-test set.
json parameters_json(const Problem& p, const Eigen::VectorXd& x, const Eigen::VectorXd* sigma_x,
                     const models::ModelInputs& soil_set,
                     const std::map<std::string, double>& sigmas) {
  json out = json::array();
  for (std::size_t k = 0; k < p.unknowns.size(); ++k) {
    const auto& u = p.unknowns[k];
    const auto i = Eigen::Index(k);
    const double v = p.at(k, x);
    const double width = p.to_x(k, u.upper) - p.to_x(k, u.lower);
    json e = {{"name", u.what.name},
              {"value", v},
              {"box", {u.lower, u.upper}},
              {"at_bound", std::abs(x(i) - p.to_x(k, u.lower)) < 1e-3 * width ||
                               std::abs(x(i) - p.to_x(k, u.upper)) < 1e-3 * width}};
    if (sigma_x) {
      const double s = u.what.logarithmic ? v * (*sigma_x)(i) : (*sigma_x)(i);
      e["sigma"] = std::isfinite(s) ? json(s) : json();
    }
    if (k < p.materials) {
      const double soil = soil_set.tables.at(u.what.table).at(u.what.key);
      e["soil_test_value"] = soil;
      const auto s = sigmas.find(u.what.key);
      if (s != sigmas.end() && s->second > 0.0) {
        e["soil_test_sigma"] = s->second;
        e["moved_in_soil_test_sigmas"] = (v - soil) / s->second;
      }
    }
    out.push_back(e);
  }
  return out;
}

// What a fit of some parameters only gives a break: not the form, not the calibration.
constexpr const char* kNotJudged = "not judged";

// What the fit frees, in words: the record's "fitted".
std::string fitted_text(const FormLimitOptions& o) {
  std::string materials = "every material parameter with a calibration box";
  if (!o.free.empty()) {
    materials.clear();
    for (const auto& f : o.free) materials += (materials.empty() ? "" : ", ") + f;
  }
  return materials + (o.hold_walls ? "; each wall's kappa_r and d_s held at the prediction"
                                   : "; each wall's fit parameters");
}

// The cause of a "breaks" of the prediction (form_limit.hpp): the joint set holds it, or not.
std::pair<std::string, std::string> cause_and_note(const Verdict& free, const Verdict* joint,
                                                   const SoilJudgement* soil) {
  const bool free_breaks = free.verdict == "breaks";
  if (!joint)
    return {free_breaks ? "form" : "calibration (unchecked)",
            free_breaks ? "" : "no soil tests judged the set that holds it"};
  if (soil->accepted && joint->verdict != "breaks") return {"calibration", ""};
  if (free_breaks) return {"form", "no set inside the boxes holds it"};
  std::string refusing;
  for (const auto& r : soil->refusing) refusing += (refusing.empty() ? "" : "; ") + r;
  return {"form", soil->accepted ? "only sets the soil tests refuse hold it"
                                 : "the soil tests refuse the joint set: " + refusing};
}

json variant_json(const Verdict& v) {
  return {{"error", v.error ? json(*v.error) : json()}, {"verdict", v.verdict}};
}

// A quantity's verdicts for one run: the soil-test set predicted (kappa_r from the wall, d_s 5
// d50), fitted (kappa_r and d_s to this run), the free form limit and, with soil tests, the joint
// set; the cause a break of the prediction has.
json run_verdicts(const Problem& p, std::size_t i, const Eigen::VectorXd& free_x,
                  const JointFit* joint, const FormLimitOptions& o) {
  const auto& dem = p.runs[i];
  const auto tolerances = tolerances_for(dem);
  const auto own = fit_kappa_and_ds(dem, p.starts[i], p.targets[i], fit_bounds(o.model));
  Variant fitted = p.starts[i];
  fitted.inputs.roughness.kappa_r = own.kappa_r, fitted.d_s_mm = own.d_s_mm;
  const auto judged = [&](const Variant& v) {
    return judge(dem, p.scatters[i], replay(dem, v), tolerances);
  };
  const auto predicted = judged(p.starts[i]), fit_ds = judged(fitted);
  const auto limit = judged(p.variant_at(i, free_x));
  const auto with_soil = joint ? judged(p.variant_at(i, joint->x)) : std::vector<Verdict>{};
  json q = json::object();
  for (std::size_t k = 0; k < limit.size(); ++k) {
    auto [cause, note] =
        cause_and_note(limit[k], joint ? &with_soil[k] : nullptr, joint ? &joint->soil : nullptr);
    if (o.restricted())
      cause = kNotJudged, note = "the fit held parameters (see fitted): not a form limit";
    json e = {{"dem", limit[k].dem ? json(*limit[k].dem) : json()},
              {"tolerance", limit[k].tolerance},
              {"soil_test_predicted", variant_json(predicted[k])},
              {"soil_test_fitted_kappa_ds", variant_json(fit_ds[k])},
              {"form_limit", variant_json(limit[k])},
              {"cause_if_breaks", cause}};
    if (joint) e["joint"] = variant_json(with_soil[k]);
    if (!note.empty()) e["cause_note"] = note;
    if (const auto c = cause_of(predicted[k].verdict, cause); !c.empty()) e["cause"] = c;
    q[limit[k].key] = e;
  }
  return {{"dir", dem.dir.string()},
          {"role", i < p.fitted ? "fitted" : "held out"},
          {"wall", p.walls[p.wall_of[i]].name()},
          {"boundary", driver::to_string(dem.boundary)},
          {"seeds", p.scatters[i].runs.size()},
          {"cell_runs", p.scatters[i].runs},  // the seeds its scatter came from: its cell
          {"quantities", q}};
}

std::string num(const json& v, const char* f) {
  return v.is_number() ? fmt::format(fmt::runtime(f), v.get<double>()) : std::string("-");
}

std::string percent(const json& v) {
  return v.is_number() ? fmt::format("{:+.0f} %", 100.0 * v.get<double>()) : std::string("-");
}

std::string parameters_markdown(const json& j) {
  const bool joint = j.contains("joint");
  std::string md = fmt::format(
      "| parameter | form limit |{} soil-test set | moved (soil-test sigmas) |{} on a bound "
      "|\n|---|---|{}---|---|{}---|\n",
      joint ? " with the soil tests |" : "", joint ? " moved with the soil tests |" : "",
      joint ? "---|" : "", joint ? "---|" : "");
  for (std::size_t k = 0; k < j["parameters"].size(); ++k) {
    const auto& e = j["parameters"][k];
    const json* s = joint ? &j["joint"]["parameters"][k] : nullptr;
    md += fmt::format(
        "| {} | {} |{} {} | {} |{} {} |\n", e["name"].get<std::string>(), num(e["value"], "{:.5g}"),
        s ? " " + num((*s)["value"], "{:.5g}") + " |" : "",
        num(e.value("soil_test_value", json()), "{:.5g}"),
        num(e.value("moved_in_soil_test_sigmas", json()), "{:+.1f}"),
        s ? " " + num(s->value("moved_in_soil_test_sigmas", json()), "{:+.1f}") + " |" : "",
        e["at_bound"].get<bool>() ? "yes" : "");
  }
  return md;
}

std::string soil_markdown(const json& j) {
  if (!j.contains("soil_tests")) return "";
  std::string md = fmt::format(
      "\nThe soil tests ({}) on each set, RMS in scatter units per objective group; a set is "
      "accepted when every group is at most {:g} x the soil-test set's:\n\n| group | soil-test "
      "set | form limit | with the soil tests | accepted up to |\n|---|---|---|---|---|\n",
      j.value("soil_tests_about", std::string("soil tests")), j["soil_acceptance"].get<double>());
  const auto cell = [&](const json& g, const char* set) {
    const auto& s = g[set];
    return num(s["rms"], "{:.4g}") +
           (s["unreached"].get<int>() > 0
                ? fmt::format(" ({} rows not reached)", s["unreached"].get<int>())
                : std::string());
  };
  for (const auto& g : j["soil_tests"])
    md += fmt::format("| {} | {} | {} | {} | {} |\n", g["group"].get<std::string>(),
                      cell(g, "soil_test"), cell(g, "form_limit"), cell(g, "joint"),
                      num(g["accepted_up_to"], "{:.4g}"));
  return md;
}

std::string runs_markdown(const json& j) {
  const bool joint = j.contains("joint");
  std::string md = fmt::format(
      "\n| run | role | quantity | DEM | tolerance | predicted error | fitted kappa_r, d_s | form "
      "limit |{} cause of a break |\n|---|---|---|---|---|---|---|---|{}---|\n",
      joint ? " with the soil tests |" : "", joint ? "---|" : "");
  for (const auto& r : j["runs"])
    for (const auto& [key, q] : r["quantities"].items()) {
      const auto cell = [&q = q](const char* variant) {
        return fmt::format("{} ({})", percent(q[variant]["error"]),
                           q[variant]["verdict"].get<std::string>());
      };
      const std::string cause =
          q.contains("cause")
              ? q["cause"].get<std::string>() + (q.contains("cause_note")
                                                     ? ": " + q["cause_note"].get<std::string>()
                                                     : std::string())
              : std::string();
      md += fmt::format("| {} | {} | {} | {} | {:.0f} % | {} | {} | {} |{} {} |\n",
                        fs::path(r["dir"].get<std::string>()).filename().string(),
                        r["role"].get<std::string>(), key, num(q["dem"], "{:.4g}"),
                        100.0 * q["tolerance"].get<double>(), cell("soil_test_predicted"),
                        cell("soil_test_fitted_kappa_ds"), cell("form_limit"),
                        joint ? " " + cell("joint") + " |" : "", cause);
    }
  return md;
}

std::string markdown(const json& j) {
  std::string md = fmt::format(
      "# {} of {} ({} fitted runs, {} held out)\n\nFitted: {}, jointly (src: "
      "comparison/causes/form_limit.hpp); RMS {:.3g} scatter units, {} evaluations, {:.0f} s, "
      "{}.\n",
      j.value("restricted", false) ? "Fit" : "Form limit", j["model"].get<std::string>(),
      j["fit_runs"].size(), j["held_out"].size(), j["fitted"].get<std::string>(),
      j["rms_scaled"].get<double>(), j["evaluations"].get<int>(), j["seconds"].get<double>(),
      j["stop"].get<std::string>());
  if (j.contains("joint")) {
    const auto& s = j["joint"];
    md += fmt::format(
        "\nWith the soil tests: the same unknowns over the sets the soil tests accept (COBYLA from "
        "the soil-test set and from the free set): RMS {:.3g} scatter units, {} evaluations, "
        "{:.0f} s, {}; the soil "
        "tests {} the set.\n",
        s["rms_scaled"].get<double>(), s["evaluations"].get<int>(), s["seconds"].get<double>(),
        s["stop"].get<std::string>(), s["accepted"].get<bool>() ? "accept" : "REFUSE");
  } else {
    md +=
        "\nNo soil tests judged the sets: a break the form limit holds is \"calibration "
        "(unchecked)\".\n";
  }
  return md + "\n" + parameters_markdown(j) + soil_markdown(j) + runs_markdown(j);
}

// A fitted material set as a parameter file, usable with `iwb compare --params`.
std::string parameter_file(const Problem& p, const Eigen::VectorXd& x, const std::string& what,
                           const FormLimitOptions& o) {
  // every table of the set, the held parameters as given: a file `iwb compare --params` reads
  std::map<std::string, std::string> tables;
  for (const auto& [table, values] : tables_at(p, x))
    for (const auto& [key, value] : values)
      tables[table] += fmt::format("{} = {:.9g}\n", key, value);
  std::string s = fmt::format(
      "# {} of {} (`iwb form-limit`, {}): fitted to DEM runs ({}), not a soil calibration. "
      "form_limit.json says on which runs.\n# Command: {}\n",
      what, o.model, io::utc_timestamp(), fitted_text(o), o.command_line);
  for (const auto& [name, body] : tables) s += fmt::format("[{}]\n{}", name, body);
  return s;
}

// Per group, its RMS at the soil-test set, the free form limit and the joint set.
json soil_json(const Groups& soil, const Groups& free, const Groups& joint, double factor) {
  json out = json::array();
  const auto at = [](const FormLimitOptions::SoilGroup& g) {
    return json{{"rms", g.rms}, {"unreached", g.unreached}};
  };
  for (std::size_t g = 0; g < soil.size(); ++g)
    out.push_back({{"group", soil[g].group},
                   {"soil_test", at(soil[g])},
                   {"form_limit", at(free[g])},
                   {"joint", at(joint[g])},
                   {"accepted_up_to", factor * soil[g].rms}});
  return out;
}

}  // namespace

json run_form_limit(const FormLimitOptions& o) {
  check_inputs(o);
  const auto soil_set = validated_parameters(o.model, o.params);
  const auto sigmas = soil_sigmas(o);     // a bad calibration.json too, before the fit
  const Problem p = set_up(o, soil_set);  // InputError for a bad run, before anything is written
  io::prepare_run_directory(o.out, {"form_limit"}, o.force);
  json manifest = {{"kind", "form_limit"},
                   {"command_line", o.command_line},
                   {"started", io::utc_timestamp()},
                   {"status", "running"}};
  io::write_manifest(o.out, manifest);
  const Fitted f = fit(p, o);
  std::optional<JointFit> joint;
  Groups at_soil;
  if (o.soil_tests) {
    at_soil = o.soil_tests(soil_set.tables);
    joint = fit_joint(p, o, at_soil, f.x);
  }
  json j = {
      {"kind", "form_limit"},
      {"model", o.model},
      {"soil_test_parameters", o.params},
      {"fit_runs", json::array()},
      {"held_out", json::array()},
      {"walls", json::array()},
      {"fitted", fitted_text(o)},
      {"restricted", o.restricted()},
      {"rms_scaled", f.result.rmse},
      {"evaluations", f.result.evaluations},
      {"seconds", f.seconds},
      {"converged", f.result.converged},
      {"stop", f.result.stop_reason},
      {"parameters", parameters_json(p, f.x, &f.result.sigma, soil_set, sigmas)},
      {"soil_test_calibration", o.calibration.empty() ? json() : json(o.calibration.string())},
      {"runs", json::array()}};
  if (joint) {
    j["soil_tests_about"] = o.soil_tests_about;
    j["soil_acceptance"] = o.soil_acceptance;
    j["soil_tests"] =
        soil_json(at_soil, o.soil_tests(tables_at(p, f.x)), joint->soil.groups, o.soil_acceptance);
    j["joint"] = {{"rms_scaled", joint->result.rmse},
                  {"evaluations", joint->result.evaluations},
                  {"seconds", joint->seconds},
                  {"stop", joint->result.stop_reason},
                  {"accepted", joint->soil.accepted},
                  {"refusing", joint->soil.refusing},
                  {"parameters", parameters_json(p, joint->x, nullptr, soil_set, sigmas)}};
  }
  for (const auto& d : o.fit_runs) j["fit_runs"].push_back(d.string());
  for (const auto& d : o.held_out) j["held_out"].push_back(d.string());
  for (const auto& w : p.walls) j["walls"].push_back(w.name());
  for (std::size_t i = 0; i < p.runs.size(); ++i)
    j["runs"].push_back(run_verdicts(p, i, f.x, joint ? &*joint : nullptr, o));
  std::vector<std::string> files = {"form_limit.json", "form_limit.md", "form_limit.toml"};
  io::write_atomically(o.out / "form_limit.json", j.dump(2) + "\n");
  io::write_atomically(o.out / "form_limit.md", markdown(j));
  io::write_atomically(o.out / "form_limit.toml", parameter_file(p, f.x, "The form limit", o));
  if (joint) {
    io::write_atomically(o.out / "form_limit_joint.toml",
                         parameter_file(p, joint->x, "The form limit with the soil tests", o));
    files.push_back("form_limit_joint.toml");
  }
  manifest["finished"] = io::utc_timestamp();
  manifest["status"] = "complete";
  manifest["files"] = files;
  io::write_manifest(o.out, manifest);
  return j;
}

}  // namespace iwb::comparison
