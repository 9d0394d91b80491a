#include "pile/pile_run.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "common/errors.hpp"
#include "comparison/presentation/figure.hpp"
#include "cycles/cycle_quantities.hpp"
#include "io/directory_lock.hpp"
#include "io/output_path.hpp"
#include "io/run_directory.hpp"
#include "pile/load_transfer.hpp"

namespace iwb::pile {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The head's targets: settlements (mm) or loads (kN), in order.
std::vector<double> head_path(const Loading& l) {
  std::vector<double> t;
  if (l.kind == LoadingKind::kSettlement) {
    for (int k = 1; k <= l.increments; ++k) t.push_back(l.settlement_mm * k / l.increments);
    return t;
  }
  const int q = l.increments_per_quarter;
  const auto ramp = [&](double from, double to) {
    for (int k = 1; k <= q; ++k) t.push_back(from + (to - from) * k / q);
  };
  // a load about its mean, or a settlement about 0
  const bool load = l.kind == LoadingKind::kCyclicLoad;
  const double mean = load ? l.mean_kN : 0.0, amplitude = load ? l.amplitude_kN : l.amplitude_mm;
  if (mean > 0.0) ramp(0.0, mean);
  for (int c = 0; c < l.cycles; ++c) {
    ramp(mean, mean + amplitude);
    ramp(mean + amplitude, mean);
    ramp(mean, mean - amplitude);
    ramp(mean - amplitude, mean);
  }
  return t;
}

// The head from `from` to `to` (settlement or load): in one step, or, where equilibrium or a stress
// point fails, in two halves, down to 1/2^kSubdivisions of the step.
constexpr int kSubdivisions = 8;

PileSnapshot advance(LoadTransfer& pile, const Loading& l, double from, double to, int depth) {
  try {
    return l.settlement_given() ? pile.settle_to(to) : pile.load_to(to);
  } catch (const ConvergenceError&) {
    if (depth >= kSubdivisions) throw;
    advance(pile, l, from, 0.5 * (from + to), depth + 1);
    return advance(pile, l, 0.5 * (from + to), to, depth + 1);
  }
}

struct Analysis {
  std::vector<PileSnapshot> curve;
  std::vector<std::pair<double, std::vector<ProfileRow>>> profiles;  // (head load, rows)
  std::string status = "complete";
};

Analysis analyse(const PileSpec& spec, const ShaftMaterial& material, int elements,
                 const PileRunOptions& opt, long& done, long total) {
  Analysis a;
  LoadTransfer pile(spec, material, elements);
  a.curve.push_back(pile.snapshot());
  double previous = 0.0;  // the head's last target reached
  std::vector<double> pending = spec.loading.profile_loads_kN;
  std::sort(pending.begin(), pending.end());
  // the profiles at the last state reached when none was asked for, or the run stopped early
  const auto ended = [&](std::string status) {
    a.status = std::move(status);
    if (a.profiles.empty()) a.profiles.push_back({a.curve.back().head_load_kN, pile.profile()});
    return a;
  };
  for (double target : head_path(spec.loading)) {
    try {
      a.curve.push_back(advance(pile, spec.loading, previous, target, 0));
      previous = target;
    } catch (const std::exception& e) {
      return ended(fmt::format("failed: {}", e.what()));
    }
    while (!pending.empty() && a.curve.back().head_load_kN >= pending.front() * (1.0 - 1e-12)) {
      a.profiles.push_back({pending.front(), pile.profile()});
      pending.erase(pending.begin());
    }
    if (opt.on_step) opt.on_step(++done, total);
    if (opt.interrupt && opt.interrupt->load()) return ended("interrupted");
  }
  return ended("complete");
}

std::string curve_csv(const std::vector<PileSnapshot>& c) {
  std::string out =
      "step,head_settlement_mm,head_load_kN,shaft_load_kN,base_load_kN,tip_settlement_mm,newton_"
      "iterations,shaft_sigma_n_mean_kPa\n";
  for (std::size_t k = 0; k < c.size(); ++k)
    out += fmt::format("{},{},{},{},{},{},{},{}\n", k, c[k].head_settlement_mm, c[k].head_load_kN,
                       c[k].shaft_load_kN, c[k].base_load_kN, c[k].tip_settlement_mm,
                       c[k].newton_iterations, c[k].shaft_sigma_n_mean_kPa);
  return out;
}

std::string profiles_csv(const Analysis& a) {
  std::string out = "head_load_kN,z_m,w_mm,axial_kN,tau_kPa,sigma_n_kPa\n";
  for (const auto& [load, rows] : a.profiles)
    for (const auto& r : rows)
      out += fmt::format("{},{},{},{},{},{}\n", load, r.z_m, r.w_mm, r.axial_kN, r.tau_kPa,
                         r.sigma_n_kPa);
  return out;
}

// The quantity mesh convergence is judged on: the head load at the last settlement, the head
// settlement at the end of the last load cycle, or the shaft's mean normal stress at the end of
// the last settlement cycle (its friction fatigue).
double end_value(const PileSpec& spec, const Analysis& a) {
  switch (spec.loading.kind) {
    case LoadingKind::kSettlement:
      return a.curve.back().head_load_kN;
    case LoadingKind::kCyclicLoad:
      return a.curve.back().head_settlement_mm;
    case LoadingKind::kCyclicSettlement:
      return a.curve.back().shaft_sigma_n_mean_kPa;
  }
  return NAN;
}

const char* end_quantity(const PileSpec& spec) {
  switch (spec.loading.kind) {
    case LoadingKind::kSettlement:
      return "head load at the last settlement, kN";
    case LoadingKind::kCyclicLoad:
      return "head settlement at the end of the last cycle, mm";
    case LoadingKind::kCyclicSettlement:
      return "the shaft's mean normal stress at the end of the last cycle, kPa";
  }
  return "";
}

json mesh_convergence(const PileSpec& spec,
                      const std::vector<std::pair<int, const Analysis*>>& runs) {
  json j;
  j["quantity"] = end_quantity(spec);
  std::vector<double> v;
  for (const auto& [n, a] : runs) {
    j["elements"].push_back(n);
    j["values"].push_back(a->status == "complete" ? json(end_value(spec, *a)) : json(nullptr));
    v.push_back(a->status == "complete" ? end_value(spec, *a) : NAN);
  }
  if (v.size() == 3 && std::isfinite(v[0] + v[1] + v[2])) {
    const double d1 = v[0] - v[1], d2 = v[1] - v[2];
    j["change_to_finest"] = (v[2] - v[1]) / v[1];
    if (d1 != 0.0 && d2 != 0.0 && d1 / d2 > 0.0) {
      const double p = std::log2(d1 / d2);
      j["observed_order"] = p;
      j["extrapolated"] = v[2] - d2 / (std::pow(2.0, p) - 1.0);
    }
  }
  return j;
}

// The shaft as one interface under the head's displacement cycles (issue 34, item 6): tau the
// shaft load over the shaft's area, sigma_n its mean normal stress, u_n the mean normal
// displacement (sigma_n - sigma_n0) / K of the cavity's spring; measured per cycle by the
// definitions the DEM's cyclic cells are (src/cycles/). The head's targets land on the reversals,
// so the travel is the sum of their steps. nullopt for other loadings, or too few rows.
std::optional<cycles::CyclicQuantities> shaft_cycles(const PileSpec& spec, const Analysis& a) {
  if (spec.loading.kind != LoadingKind::kCyclicSettlement || a.curve.size() <= 2)
    return std::nullopt;
  const double area_m2 = M_PI * spec.pile.diameter_m * spec.pile.length_m;
  const double K = 4.0 * spec.soil.shear_modulus_kPa / (spec.pile.diameter_m * 1000.0);
  cycles::Path p;
  const double sigma_n0 = a.curve.front().shaft_sigma_n_mean_kPa;
  for (const auto& s : a.curve) {
    p.travel_mm.push_back(p.travel_mm.empty() ? 0.0
                                              : p.travel_mm.back() + std::abs(s.head_settlement_mm -
                                                                              p.u_x_mm.back()));
    p.u_x_mm.push_back(s.head_settlement_mm);
    p.tau_kPa.push_back(s.shaft_load_kN / area_m2);
    p.sigma_n_kPa.push_back(s.shaft_sigma_n_mean_kPa);
    p.u_n_mm.push_back((s.shaft_sigma_n_mean_kPa - sigma_n0) / K);
  }
  return cycles::cyclic_quantities(p, {spec.loading.amplitude_mm, spec.loading.cycles, 0.0});
}

std::vector<fs::path> draw_figures(const PileSpec& spec, const Analysis& a,
                                   const std::optional<cycles::CyclicQuantities>& per_cycle,
                                   const fs::path& out) {
  io::StagedDirectory staged(out / "figures", "figures");
  comparison::PlotCurve head{"head", {}, {}}, shaft{"shaft", {}, {}}, base{"base", {}, {}};
  for (const auto& s : a.curve) {
    head.x.push_back(s.head_settlement_mm), head.y.push_back(s.head_load_kN);
    shaft.x.push_back(s.head_settlement_mm), shaft.y.push_back(s.shaft_load_kN);
    base.x.push_back(s.head_settlement_mm), base.y.push_back(s.base_load_kN);
  }
  std::vector<fs::path> svgs;
  const std::string model = spec.interface.model;
  svgs.push_back(comparison::draw(
      comparison::curves_figure("load_settlement", "Load-settlement (" + model + ")",
                                "head settlement (mm)", "load (kN)", {head, shaft, base}),
      staged.path()));
  for (const auto& [name, label, column] :
       std::vector<std::tuple<std::string, std::string, double ProfileRow::*>>{
           {"profile_tau", "shaft friction tau (kPa)", &ProfileRow::tau_kPa},
           {"profile_sigma_n", "normal stress sigma_n (kPa)", &ProfileRow::sigma_n_kPa},
           {"profile_axial", "axial force (kN)", &ProfileRow::axial_kN}}) {
    std::vector<comparison::PlotCurve> curves;
    for (const auto& [load, rows] : a.profiles) {
      comparison::PlotCurve c{fmt::format("{:g} kN", load), {}, {}};
      for (const auto& r : rows) c.x.push_back(r.*column), c.y.push_back(-r.z_m);
      curves.push_back(c);
    }
    svgs.push_back(comparison::draw(
        comparison::curves_figure(name, label + " along the shaft (" + model + ")", label,
                                  "depth below the head (m, negative)", curves),
        staged.path()));
  }
  if (per_cycle) {
    comparison::PlotCurve ratio{
        "sigma_n / sigma_n0 at the cycle's end", {}, {}, "with linespoints lw 2 pt 7"},
        peak{"peak tau / sigma_n towards +A", {}, {}, "with linespoints lw 2 pt 5"};
    for (const auto& c : per_cycle->cycles) {
      ratio.x.push_back(c.number), ratio.y.push_back(c.sigma_n_ratio);
      peak.x.push_back(c.number), peak.y.push_back(c.peak_friction_positive);
    }
    svgs.push_back(comparison::draw(
        comparison::curves_figure("shaft_cycles", "The shaft over the cycles (" + model + ")",
                                  "cycle N", "ratio", {ratio, peak}),
        staged.path()));
  }
  staged.commit();
  return svgs;
}

json summary_of(const PileSpec& spec, const Analysis& a,
                const std::optional<cycles::CyclicQuantities>& shaft, const json& convergence) {
  double capacity = 0.0;
  for (const auto& s : a.curve) capacity = std::max(capacity, s.head_load_kN);
  const auto& end = a.curve.back();
  json out = {{"status", a.status},
              {"model", spec.interface.model},
              {"elements", spec.pile.elements},
              {"largest_head_load_kN", capacity},
              {"end",
               {{"head_settlement_mm", end.head_settlement_mm},
                {"head_load_kN", end.head_load_kN},
                {"shaft_load_kN", end.shaft_load_kN},
                {"base_load_kN", end.base_load_kN}}},
              {"mesh_convergence", convergence}};
  if (shaft) {
    out["cycles"] = cycles::to_json(*shaft);
    out["cycles_definition"] =
        "the shaft as one interface: tau = shaft load / (pi D L), sigma_n the mean over the "
        "shaft's stress points, u_n = (sigma_n - sigma_n0) / K, u_x the head's settlement; per "
        "cycle as src/cycles/ measures the DEM's cyclic cells";
  }
  return out;
}

}  // namespace

int run_pile(const PileSpec& spec, const PileRunOptions& opt) {
  // the interface is made first: a model or parameter file it refuses leaves nothing written
  const ShaftMaterial material(spec.interface, spec.source + " [interface]");
  if (spec.loading.kind != LoadingKind::kSettlement && iwb_monotonic_only(material.get()))
    throw InputError(fmt::format(
        "{} [interface]: model '{}' builds only its monotonic part, and this loading reverses "
        "the shaft ([loading] kind = cyclic_load or cyclic_settlement); give a model that "
        "unloads (an -igs model for cycles)",
        spec.source, spec.interface.model));
  json m{{"kind", "pile"},
         {"status", "running"},
         {"source", spec.source},
         {"description", spec.description},
         {"command_line", opt.command_line},
         {"started", io::utc_timestamp()},
         {"interface_library", iwb_version()}};
  const io::OutputKind kind{"pile"};
  io::require_new_run_directory(opt.out, kind, opt.force);  // before the lock touches it
  const auto lock = io::DirectoryLock::take(opt.out, opt.command_line);
  io::prepare_run_directory(opt.out, kind, opt.force);
  io::write_manifest(opt.out, m);
  io::write_atomically(opt.out / "pile.toml", opt.spec_text);
  const int n = spec.pile.elements;
  const long steps = long(head_path(spec.loading).size());
  const std::vector<int> meshes{std::max(1, n / 2), n, 2 * n};
  long done = 0;
  std::vector<Analysis> runs;
  for (int elements : meshes)
    runs.push_back(analyse(spec, material, elements, opt, done, steps * 3));
  const Analysis& main = runs[1];
  const json convergence =
      mesh_convergence(spec, {{meshes[0], &runs[0]}, {meshes[1], &runs[1]}, {meshes[2], &runs[2]}});
  io::write_atomically(opt.out / "load_settlement.csv", curve_csv(main.curve));
  io::write_atomically(opt.out / "profiles.csv", profiles_csv(main));
  std::string mc = "elements,status,value\n";
  for (std::size_t i = 0; i < runs.size(); ++i)
    mc += fmt::format("{},{},{}\n", meshes[i], runs[i].status == "complete" ? "complete" : "failed",
                      runs[i].status == "complete" ? end_value(spec, runs[i]) : NAN);
  io::write_atomically(opt.out / "mesh_convergence.csv", mc);
  const auto shaft = shaft_cycles(spec, main);  // once, for the figures and the summary
  if (main.curve.size() > 1) draw_figures(spec, main, shaft, opt.out);
  io::write_atomically(opt.out / "summary.json",
                       summary_of(spec, main, shaft, convergence).dump(2) + "\n");
  m["status"] = main.status;
  m["finished"] = io::utc_timestamp();
  io::write_manifest(opt.out, m);
  return main.status == "complete" ? 0 : 1;
}

}  // namespace iwb::pile
