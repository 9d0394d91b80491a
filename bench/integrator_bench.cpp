#include "bench/integrator_bench.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "comparison/presentation/figure.hpp"
#include "driver/element_test.hpp"
#include "io/output_path.hpp"
#include "io/parameter_sets.hpp"
#include "io/run_directory.hpp"

namespace iwb::bench {

namespace {

using Clock = std::chrono::steady_clock;

// The reference: rk54 this tight is converged to round-off over the path (its own error against
// 1e-11 is below 1e-9 of tau), far below the 1e-8 the finest setting measured aims at.
constexpr double kReferenceRtol = 1e-10;
// The normal row is solved far below every integration error measured, so the error measured is
// the integration's and not Newton's (the default 1e-8 would floor CNS and CV at 1e-8).
constexpr double kNewtonTolerance = 1e-13;
constexpr int kTimingRepeats = 3;  // wall time: best of these

// Seed Table 5.3, Toyoura sand (Arnold 2008): both column groups, so the -igs model runs too.
constexpr const char* kParameterSet = "table_5_3_toyoura.toml";

integration::IntegratorSettings adaptive(const std::string& pair, double rtol) {
  integration::IntegratorSettings s;
  s.pair = pair;
  s.rtol = rtol;
  return s;
}

driver::ElementTestResult run_with(const models::Model& m, const models::StateVector& s0,
                                   const driver::Path& path,
                                   const integration::IntegratorSettings& set) {
  driver::RunSettings rs;
  rs.integrator = set;
  rs.mixed.tolerance = kNewtonTolerance;
  return driver::run_element_test(m, s0, path, rs);
}

// Max over the path of |x - x_ref|, divided by max over the path of |x_ref| (header comment).
double relative_max_error(const std::vector<double>& x, const std::vector<double>& ref) {
  double dev = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    dev = std::max(dev, std::abs(x[i] - ref[i]));
    scale = std::max(scale, std::abs(ref[i]));
  }
  return dev / std::max(scale, 1e-300);
}

struct Curves {
  std::vector<double> tau, sigma_n;
};
Curves curves_of(const models::Model& m, const driver::ElementTestResult& r) {
  Curves c;
  for (const auto& row : r.rows) {
    const auto st = m.stress(row.state);
    c.tau.push_back(st.tau_x);
    c.sigma_n.push_back(st.sigma_n);
  }
  return c;
}

void mark_front(std::vector<TradeoffPoint>& pts) {
  for (auto& p : pts) {
    p.on_front = p.status == "complete";
    for (const auto& q : pts)
      if (q.status == "complete" && &q != &p && q.rate_evaluations <= p.rate_evaluations &&
          q.error <= p.error && (q.rate_evaluations < p.rate_evaluations || q.error < p.error))
        p.on_front = false;
  }
}

}  // namespace

std::vector<TradeoffSetting> tradeoff_settings(int max_substeps, double min_rtol) {
  std::vector<TradeoffSetting> out;
  for (int n = 1; n <= max_substeps; n *= 2) {
    integration::IntegratorSettings s;
    s.scheme = integration::Scheme::kExplicitEuler;
    s.substeps = n;
    out.push_back({"euler", double(n), s});
  }
  for (const std::string pair : {"rk32", "rk54"})
    for (double rtol = 1e-2; rtol >= min_rtol * 0.999; rtol /= 10.0)
      out.push_back({pair, rtol, adaptive(pair, rtol)});
  return out;
}

std::vector<TradeoffPoint> run_tradeoff(const models::ModelSpec& spec,
                                        const models::ModelInputs& inputs, driver::BoundaryKind bc,
                                        const TradeoffPath& tp,
                                        const std::vector<TradeoffSetting>& settings) {
  const auto model = spec.make(inputs);
  const auto s0 = model->initial_state(
      models::offer(spec, inputs, {{"sigma_n_kPa", tp.sigma_n_kPa}, {"e0", tp.e0}}));
  const auto path = driver::monotonic_path({bc, tp.cns_K_kPa}, tp.gamma, driver::ShearDirection::kX,
                                           tp.increments);
  const auto ref = run_with(*model, s0, path, adaptive("rk54", kReferenceRtol));
  std::vector<TradeoffPoint> out;
  if (!ref.complete()) {  // nothing to measure against: every setting says so, the bench goes on
    for (const auto& st : settings)
      out.push_back({spec.name, driver::to_string(bc), st.scheme, st.parameter, INFINITY, INFINITY,
                     INFINITY, 0, 0.0, "reference (rk54, rtol 1e-10) " + ref.status});
    return out;
  }
  const Curves rc = curves_of(*model, ref);
  for (const auto& st : settings) {
    TradeoffPoint p{
        spec.name, driver::to_string(bc), st.scheme, st.parameter, 0.0, 0.0, 0.0, 0, INFINITY, ""};
    driver::ElementTestResult r;
    for (int i = 0; i < kTimingRepeats; ++i) {
      const auto t0 = Clock::now();
      r = run_with(*model, s0, path, st.settings);
      p.seconds = std::min(p.seconds, std::chrono::duration<double>(Clock::now() - t0).count());
    }
    p.status = r.status;
    p.rate_evaluations = r.counters.rate_evaluations;
    p.error = p.error_tau = p.error_sigma_n = INFINITY;
    if (r.complete()) {
      const Curves c = curves_of(*model, r);
      p.error_tau = relative_max_error(c.tau, rc.tau);
      p.error_sigma_n = relative_max_error(c.sigma_n, rc.sigma_n);
      p.error = std::max(p.error_tau, p.error_sigma_n);
    }
    out.push_back(p);
  }
  mark_front(out);
  return out;
}

namespace {

std::string setting_name(const std::string& scheme, double parameter) {
  return scheme == "euler" ? fmt::format("Euler n={:g}", parameter)
                           : fmt::format("{} rtol={:g}", scheme, parameter);
}

// Per (scheme, parameter): the worst error over every model and boundary condition and the mean
// rate evaluations per increment; the cheapest whose worst error meets `target`.
struct Overall {
  std::string scheme;
  double parameter = 0.0, worst_error = 0.0, evals_per_increment = 0.0, ms_sum = 0.0;
};
std::vector<Overall> overall(const std::vector<TradeoffPoint>& all, int increments) {
  std::map<std::pair<std::string, double>, std::vector<const TradeoffPoint*>> by;
  for (const auto& p : all)
    if (p.status.rfind("reference", 0) != 0)
      by[{p.scheme, p.parameter}].push_back(&p);  // measurable only
  std::vector<Overall> out;
  for (const auto& [key, pts] : by) {
    Overall o{key.first, key.second};
    for (const auto* p : pts) {
      o.worst_error = std::max(o.worst_error, p->error);
      o.evals_per_increment += double(p->rate_evaluations) / increments / double(pts.size());
      o.ms_sum += 1e3 * p->seconds;
    }
    out.push_back(o);
  }
  return out;
}
const Overall* cheapest(const std::vector<Overall>& all, double target) {
  const Overall* best = nullptr;
  for (const auto& o : all)
    if (o.worst_error <= target &&
        (best == nullptr || o.evals_per_increment < best->evals_per_increment))
      best = &o;
  return best;
}

const TradeoffPoint* cheapest(const std::vector<TradeoffPoint>& pts, const std::string& model,
                              const std::string& bc, double target) {
  const TradeoffPoint* best = nullptr;
  for (const auto& p : pts)
    if (p.model == model && p.boundary == bc && p.error <= target &&
        (best == nullptr || p.rate_evaluations < best->rate_evaluations))
      best = &p;
  return best;
}

std::string describe(const TradeoffPoint* p) {
  if (p == nullptr) return "none measured";
  return fmt::format("{} ({} evals, {:.2f} ms, error {:.1e})",
                     setting_name(p->scheme, p->parameter), p->rate_evaluations, 1e3 * p->seconds,
                     p->error);
}

std::string points_csv(const std::vector<TradeoffPoint>& pts) {
  std::string csv =
      "model,boundary,scheme,parameter,error,error_tau,error_sigma_n,rate_evaluations,seconds,on_"
      "pareto_front,status\n";
  for (const auto& p : pts)
    csv += fmt::format("{},{},{},{:g},{:.6e},{:.6e},{:.6e},{},{:.6e},{},\"{}\"\n", p.model,
                       p.boundary, p.scheme, p.parameter, p.error, p.error_tau, p.error_sigma_n,
                       p.rate_evaluations, p.seconds, p.on_front ? 1 : 0, p.status);
  return csv;
}

// Error against rate evaluations, log-log: every setting as a point (colour: boundary condition,
// shape: scheme), the Pareto front of each boundary condition as a line.
comparison::Figure pareto_figure(const std::vector<TradeoffPoint>& pts, const std::string& model) {
  comparison::Figure f{"pareto_" + model,
                       model + ": integration error against cost (Table 5.3 Toyoura, 100 kPa)",
                       "rate evaluations over the path",
                       "max relative error of tau and sigma_n",
                       {},
                       {},
                       "",
                       ""};
  f.data.columns = {"rate_evaluations", "error", "scheme", "boundary", "on_front"};
  const std::vector<std::string> schemes{"euler", "rk32", "rk54"}, bcs{"CNL", "CNS", "CV"};
  for (const auto& p : pts) {
    if (p.model != model || !(p.error < INFINITY)) continue;
    const auto si = std::find(schemes.begin(), schemes.end(), p.scheme) - schemes.begin();
    const auto bi = std::find(bcs.begin(), bcs.end(), p.boundary) - bcs.begin();
    f.data.rows.push_back({double(p.rate_evaluations), std::max(p.error, 1e-16), double(si),
                           double(bi), p.on_front ? 1.0 : 0.0});
  }
  f.extra =
      "set logscale xy\nset format y '%.0e'\nset linetype 1 lc rgb '#1f77b4'\nset linetype 2 lc "
      "rgb '#d62728'\n"
      "set linetype 3 lc rgb '#2ca02c'\n";
  const std::string csv = comparison::gnuplot_string(f.name + ".csv");
  static const int kShape[] = {7, 5, 9};  // circle, square, triangle
  f.plot = "plot ";
  for (std::size_t b = 0; b < bcs.size(); ++b) {
    for (std::size_t s = 0; s < schemes.size(); ++s)
      f.plot += fmt::format(
          "{} using 1:(($3=={}&&$4=={})?$2:1/0) skip 1 with points pt {} ps 1.2 lc {} title '{} "
          "{}', ",
          csv, s, b, kShape[s], b + 1, bcs[b], schemes[s]);
    // smooth unique sorts by x and drops the undefined (off-front) points: the front as one line
    f.plot += fmt::format(
        "{} using 1:(($4=={}&&$5==1)?$2:1/0) skip 1 smooth unique with lines lw 2 lc {} title '{} "
        "Pareto front'{}",
        csv, b, b + 1, bcs[b], b + 1 < bcs.size() ? ", " : "");
  }
  return f;
}

std::string markdown(const std::vector<TradeoffPoint>& pts, const std::vector<Overall>& ov,
                     const IntegratorBenchOptions& opt, const TradeoffPath& tp) {
  std::string md = fmt::format(
      "# Integrator trade-off\n\nTable 5.3 Toyoura sand, sigma_n0 = {:g} kPa, e0 = {:g}, K0 = 1 - "
      "sin(phi_c); "
      "monotonic simple shear to gamma = {:g} in {} increments; CNS K = {:g} kPa per unit strain; "
      "Newton to {:g}. "
      "Reference: rk54 at rtol {:g}. Error: max over the path of |x - x_ref| / max |x_ref|, for x "
      "= tau and "
      "sigma_n, the larger of the two. Evaluations include Newton's dual-number ones.\n\n",
      tp.sigma_n_kPa, tp.e0, tp.gamma, tp.increments, tp.cns_K_kPa, kNewtonTolerance,
      kReferenceRtol);
  md +=
      "| model | BC | cheapest for error <= 1e-3 | cheapest for error <= 1e-6 "
      "|\n|---|---|---|---|\n";
  for (const auto& m : opt.models)
    for (const std::string bc : {"CNL", "CNS", "CV"})
      md += fmt::format("| {} | {} | {} | {} |\n", m, bc, describe(cheapest(pts, m, bc, 1e-3)),
                        describe(cheapest(pts, m, bc, 1e-6)));
  for (const auto& p : pts)
    if (p.status.rfind("reference", 0) == 0 && p.scheme == "euler" && p.parameter == 1.0)
      md += fmt::format("\nNot measured: {} {}, the {}\n", p.model, p.boundary, p.status);
  md +=
      "\n## One setting for every model and BC (with a reference)\n\n| setting | worst error | "
      "rate evaluations per increment (mean) | "
      "wall time, sum over models and BCs (ms) |\n|---|---:|---:|---:|\n";
  for (const auto& o : ov)
    md += fmt::format("| {} | {:.2e} | {:.1f} | {:.1f} |\n", setting_name(o.scheme, o.parameter),
                      o.worst_error, o.evals_per_increment, o.ms_sum);
  for (double target : {1e-3, 1e-6}) {
    const auto* c = cheapest(ov, target);
    md += c == nullptr
              ? fmt::format("\nNo single setting reaches {:g} everywhere.\n", target)
              : fmt::format(
                    "\nCheapest single setting for {:g} everywhere: {} (worst error {:.1e}, {:.1f} "
                    "evaluations per increment).\n",
                    target, setting_name(c->scheme, c->parameter), c->worst_error,
                    c->evals_per_increment);
  }
  return md;
}

}  // namespace

nlohmann::json run_integrator_bench(const IntegratorBenchOptions& opt) {
  const auto inputs = io::shipped_inputs(kParameterSet);
  const TradeoffPath tp;
  const auto settings = tradeoff_settings();
  // refused before the runs; the files enter the directory's ledger together at the end
  const io::OutputKind kind{"bench-integrators", "integrators.md"};
  io::require_output_directory(opt.out, kind, false);
  std::vector<TradeoffPoint> all;
  fmt::print("{:<11} {:<4} {:<16} {:>10} {:>10} {:>10} {:>9}\n", "model", "BC", "setting", "error",
             "evals", "ms", "front");
  for (const auto& name : opt.models)
    for (auto bc :
         {driver::BoundaryKind::kCNL, driver::BoundaryKind::kCNS, driver::BoundaryKind::kCV})
      for (const auto& p : run_tradeoff(models::find_model(name), inputs, bc, tp, settings)) {
        fmt::print("{:<11} {:<4} {:<16} {:>10.2e} {:>10} {:>10.2f} {:>9}{}\n", p.model, p.boundary,
                   setting_name(p.scheme, p.parameter), p.error, p.rate_evaluations,
                   1e3 * p.seconds, p.on_front ? "*" : "",
                   p.status == "complete" ? "" : "  " + p.status.substr(0, 80));
        all.push_back(p);
      }
  io::StagedDirectory staged(
      opt.out,
      kind.kind);  // the table, its summary and its fronts together or not at all
  io::write_atomically(staged.path() / "integrators.csv", points_csv(all));
  const auto ov = overall(all, tp.increments);
  const std::string md = markdown(all, ov, opt, tp);
  io::write_atomically(staged.path() / "integrators.md", md);
  for (const auto& m : opt.models) comparison::draw(pareto_figure(all, m), staged.path());
  staged.commit_into();
  fmt::print("\n{}\n-> {}\n", md.substr(md.find("| model | BC")), opt.out.string());
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : all)
    out.push_back({{"model", p.model},
                   {"boundary", p.boundary},
                   {"scheme", p.scheme},
                   {"parameter", p.parameter},
                   {"error", p.error},
                   {"rate_evaluations", p.rate_evaluations},
                   {"seconds", p.seconds}});
  return out;
}

}  // namespace iwb::bench
