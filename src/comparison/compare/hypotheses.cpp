#include "comparison/compare/hypotheses.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "comparison/compare/compare.hpp"

namespace iwb::comparison {

Scatter scatter_of(const std::vector<double>& x) {
  Scatter s{int(x.size()), 0.0, 0.0};
  if (x.empty()) return s;
  s.mean = std::accumulate(x.begin(), x.end(), 0.0) / double(x.size());
  if (x.size() < 2) return s;
  double ss = 0.0;
  for (double v : x) ss += (v - s.mean) * (v - s.mean);
  s.sd = std::sqrt(ss / double(x.size() - 1));
  return s;
}

std::vector<std::vector<std::size_t>> group_close(const std::vector<double>& values,
                                                  double relative, double absolute) {
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](auto a, auto b) { return values[a] < values[b]; });
  std::vector<std::vector<std::size_t>> groups;
  for (auto i : order) {
    const bool joins = !groups.empty() && [&] {
      const double first = values[groups.back().front()];
      return values[i] - first <= std::max(absolute, relative * std::abs(values[i]));
    }();
    if (joins)
      groups.back().push_back(i);
    else
      groups.push_back({i});
  }
  return groups;
}

namespace {

std::string pm(const Scatter& s, int digits) {
  return s.n > 1 ? fmt::format("{:.{}f} +- {:.{}f}", s.mean, digits, s.sd, digits)
                 : fmt::format("{:.{}f} (one run)", s.mean, digits);
}

std::string rn_label(double R_n) {
  return R_n > 0.0 ? fmt::format("R_n = {:.3g}", R_n) : "R_n = 0 (flat)";
}

template <class F>
std::vector<double> collect(const std::vector<RunRecord>& runs, const std::vector<std::size_t>& idx,
                            F f) {
  std::vector<double> out;
  for (auto i : idx) out.push_back(f(runs[i]));
  return out;
}

std::vector<std::vector<std::size_t>> by_R_n(const std::vector<RunRecord>& runs) {
  std::vector<double> R_n;
  for (const auto& r : runs) R_n.push_back(r.R_n);
  return group_close(R_n, kSameRnRelative, kSameRnAbsolute);
}

// ---- 1. kappa_r

KappaAgainstFormula against_formula(const KappaGroup& g, double base) {
  KappaAgainstFormula k;
  k.base = base;
  k.formula = gutjahr_kappa_r(g.R_n, base);
  k.difference = g.fit.mean - k.formula;
  if (g.fit.n > 1 && g.scatter > 0.0) {
    k.in_scatter = k.difference / g.scatter;
    k.follows =
        std::abs(*k.in_scatter) <= kWithinScatter || std::abs(k.difference) <= kKappaResolution;
  } else {
    k.follows = std::abs(k.difference) <= kKappaSingleRunTolerance;
  }
  return k;
}

std::string base_name(double base) {
  return base == 10.0 ? "log base 10" : "log base e";
}

std::string kappa_miss(const KappaGroup& g, const KappaAgainstFormula& k) {
  const std::string how = k.in_scatter ? fmt::format("{:+.1f} SD", *k.in_scatter)
                                       : fmt::format("{:+.3f}, one run", k.difference);
  return fmt::format("{} ({}formula gives {:.3f}, fit {}; {})", rn_label(g.R_n),
                     g.R_n > 0.0 ? "" : "floor: ", k.formula, pm(g.fit, 3), how);
}

std::string kappa_verdict(const KappaCheck& c, std::size_t b) {
  int follows = 0;
  std::string misses;
  for (const auto& g : c.groups) {
    if (g.bases[b].follows)
      ++follows;
    else
      misses += (misses.empty() ? "" : "; ") + kappa_miss(g, g.bases[b]);
  }
  std::string v = fmt::format("{}: follows within scatter at {} of {} R_n",
                              base_name(kGutjahrLogBases[b]), follows, c.groups.size());
  return misses.empty() ? v : v + "; misses at " + misses;
}

}  // namespace

KappaCheck check_kappa_r(const std::vector<RunRecord>& runs) {
  KappaCheck c;
  for (const auto& idx : by_R_n(runs)) {
    KappaGroup g;
    g.R_n = scatter_of(collect(runs, idx, [](const RunRecord& r) { return r.R_n; })).mean;
    for (auto i : idx) g.runs.push_back(runs[i].name);
    g.fit = scatter_of(collect(runs, idx, [](const RunRecord& r) { return r.kappa_r_fit; }));
    // a fit without a sigma (NaN: its Jacobian was singular) adds no fit uncertainty; left in, it
    // would turn the group's scatter into NaN and the group into a single run's test
    std::vector<double> sigmas;
    for (double x : collect(runs, idx, [](const RunRecord& r) { return r.sigma_kappa_r_fit; }))
      if (std::isfinite(x)) sigmas.push_back(x);
    const double fit_sigma = sigmas.empty() ? 0.0 : scatter_of(sigmas).mean;
    g.scatter = std::hypot(g.fit.sd, fit_sigma);
    for (std::size_t b = 0; b < kGutjahrLogBases.size(); ++b)
      g.bases[b] = against_formula(g, kGutjahrLogBases[b]);
    c.groups.push_back(g);
  }
  std::array<double, 2> rms{0.0, 0.0};
  for (std::size_t b = 0; b < 2; ++b) {
    int follows = 0;
    for (const auto& g : c.groups) {
      follows += g.bases[b].follows;
      rms[b] += g.bases[b].difference * g.bases[b].difference;
    }
    rms[b] = c.groups.empty() ? 0.0 : std::sqrt(rms[b] / double(c.groups.size()));
    c.outcome[b] = c.groups.empty()                  ? "not testable"
                   : follows == int(c.groups.size()) ? "follows"
                   : follows > 0                     ? "partly follows"
                                                     : "misses";
    c.verdict[b] = c.groups.empty() ? "not testable: no runs" : kappa_verdict(c, b);
  }
  if (!c.groups.empty())
    c.verdict_overall = fmt::format(
        "RMS difference fit - formula over {} R_n: {:.3f} (log base 10), {:.3f} "
        "(log base e); the data favour log base {}",
        c.groups.size(), rms[0], rms[1], rms[0] <= rms[1] ? "10" : "e");
  return c;
}

namespace {

// The runs of one R_n group split by d50 (scene inputs: equal within kSameD50Relative).
std::vector<std::vector<std::size_t>> split_by_d50(const std::vector<RunRecord>& runs,
                                                   const std::vector<std::size_t>& idx) {
  std::vector<std::vector<std::size_t>> sets;
  for (const auto& local :
       group_close(collect(runs, idx, [](const RunRecord& r) { return r.d50_mm; }),
                   kSameD50Relative, 0.0)) {
    sets.push_back({});
    for (auto k : local) sets.back().push_back(idx[k]);
  }
  return sets;
}

// ---- 2. band thickness

bool has_wall_band(const RunRecord& r) {
  return r.shear_mode != "distributed shear" && r.band_d50.has_value();
}

BandGroup band_group(const std::vector<RunRecord>& runs, const std::vector<std::size_t>& idx) {
  BandGroup g;
  g.R_n = scatter_of(collect(runs, idx, [](const RunRecord& r) { return r.R_n; })).mean;
  g.d50_mm = runs[idx.front()].d50_mm;
  std::vector<double> bands;
  for (auto i : idx) {
    g.runs.push_back(runs[i].name);
    if (!has_wall_band(runs[i])) {
      ++g.without_band;
      continue;
    }
    bands.push_back(*runs[i].band_d50);
    g.inside += bands.back() >= kBandMinD50 && bands.back() <= kBandMaxD50;
  }
  g.band = scatter_of(bands);
  return g;
}

std::string band_groups_text(const std::vector<BandGroup>& groups) {
  std::string s;
  for (const auto& g : groups)
    s += fmt::format(
        "{}{}, d50 {:g} mm: {}", s.empty() ? "" : "; ", rn_label(g.R_n), g.d50_mm,
        g.band.n == 0 ? std::string("no band")
                      : fmt::format("{} d50, {} of {} inside", pm(g.band, 2), g.inside, g.band.n));
  return s;
}

}  // namespace

BandCheck check_band_thickness(const std::vector<RunRecord>& runs) {
  BandCheck c;
  std::vector<double> bands, d_s;
  for (const auto& r : runs) {
    d_s.push_back(r.d_s_fit_d50);
    if (r.shear_mode == "distributed shear")
      c.distributed.push_back(r.name);
    else if (!r.band_d50)
      c.without_wall_band.push_back(r.name + " (" + r.shear_mode + ")");
    else {
      c.bands.push_back({r.name, *r.band_d50});
      bands.push_back(*r.band_d50);
      c.inside += *r.band_d50 >= kBandMinD50 && *r.band_d50 <= kBandMaxD50;
    }
  }
  c.band = scatter_of(bands);
  c.d_s_fit_d50 = scatter_of(d_s);
  const bool mean_inside = c.band.mean >= kBandMinD50 && c.band.mean <= kBandMaxD50;
  c.outcome = bands.empty()                   ? "not testable"
              : c.inside == int(bands.size()) ? "holds"
              : mean_inside                   ? "holds on average"
                                              : "does not hold";
  std::string v =
      bands.empty()
          ? "not testable: no run localised a band at the wall"
          : fmt::format(
                "{}: wall band {} d50 over {} localised run(s), {} of {} inside [{:g}, {:g}]",
                c.outcome, pm(c.band, 2), bands.size(), c.inside, bands.size(), kBandMinD50,
                kBandMaxD50);
  if (!c.distributed.empty())
    v += fmt::format("; {} run(s) with distributed shear (no band, not counted)",
                     c.distributed.size());
  if (!c.without_wall_band.empty())
    v += fmt::format("; {} run(s) without a wall band", c.without_wall_band.size());
  if (!runs.empty())
    v += fmt::format("; fitted d_s {} d50 over all {} run(s)", pm(c.d_s_fit_d50, 1), runs.size());
  for (const auto& idx : by_R_n(runs))
    for (const auto& set : split_by_d50(runs, idx)) c.groups.push_back(band_group(runs, set));
  if (!c.bands.empty()) v += ". Per R_n and d50: " + band_groups_text(c.groups);
  c.verdict = v;
  return c;
}

// ---- 3. collapse across d50

namespace {

// u_n at the end over d50: if the band scales with d50 and its void ratio reaches the same
// critical state, u_n / d50 = (band / d50) * volumetric strain is the same for every d50, and it
// does not depend on how many mm each run was sheared once the volume is steady. (The dilatancy
// angle over the last fifth is ~0 at the critical state for every run, so it cannot tell.)
double final_u_n_over_d50(const RunRecord& r) {
  return r.dilation_mm / r.d50_mm;
}

QuantityCollapse compare_sets(const std::string& quantity, const std::vector<RunRecord>& runs,
                              const std::vector<std::vector<std::size_t>>& sets,
                              double (*value)(const RunRecord&), double resolution) {
  QuantityCollapse q{quantity, {}, 0.0, 0.0, 0, std::nullopt, resolution, false};
  double ss = 0.0;
  for (const auto& idx : sets) {
    const auto x = collect(runs, idx, value);
    q.sets.push_back({runs[idx.front()].d50_mm, scatter_of(x)});
    ss += q.sets.back().value.sd * q.sets.back().value.sd * double(x.size() - 1);
    q.dof += int(x.size()) - 1;
  }
  const auto [lo, hi] = std::minmax_element(
      q.sets.begin(), q.sets.end(),
      [](const D50Set& a, const D50Set& b) { return a.value.mean < b.value.mean; });
  q.difference = hi->value.mean - lo->value.mean;
  q.pooled_sd = q.dof > 0 ? std::sqrt(ss / q.dof) : 0.0;
  const double se = q.pooled_sd * std::sqrt(1.0 / hi->value.n + 1.0 / lo->value.n);
  if (se > 0.0) {
    q.in_scatter = q.difference / se;
    q.collapses = *q.in_scatter <= kWithinScatter || q.difference <= resolution;
  } else {
    q.collapses = q.difference <= resolution;
  }
  return q;
}

CollapseGroup collapse_group(const std::vector<RunRecord>& runs,
                             const std::vector<std::size_t>& idx) {
  CollapseGroup g;
  g.R_n = scatter_of(collect(runs, idx, [](const RunRecord& r) { return r.R_n; })).mean;
  const auto sets = split_by_d50(runs, idx);
  for (const auto& set : sets) g.d50s_mm.push_back(runs[set.front()].d50_mm);
  if (sets.size() < 2) return g;
  g.quantities = {
      compare_sets(
          "peak friction", runs, sets, [](const RunRecord& r) { return r.peak_friction; },
          kFrictionResolution),
      compare_sets(
          "residual friction", runs, sets, [](const RunRecord& r) { return r.residual_friction; },
          kFrictionResolution),
      compare_sets("final u_n / d50", runs, sets, final_u_n_over_d50, kDilationResolutionD50)};
  g.collapses = std::all_of(g.quantities.begin(), g.quantities.end(),
                            [](const auto& q) { return q.collapses; });
  return g;
}

std::string quantity_text(const QuantityCollapse& q) {
  std::string sets;
  for (const auto& s : q.sets)
    sets += fmt::format("{}d50 {:g} mm: {}", sets.empty() ? "" : ", ", s.d50_mm, pm(s.value, 3));
  const std::string how = q.in_scatter
                              ? fmt::format(
                                    "{:.1f} x the standard error of the pooled seed scatter "
                                    "(SD {:.3f}, {} dof)",
                                    *q.in_scatter, q.pooled_sd, q.dof)
                              : fmt::format("no seed scatter, resolution {:g}", q.resolution);
  return fmt::format("{} differs by {:.3f} ({}; {})", q.quantity, q.difference, sets, how);
}

}  // namespace

CollapseCheck check_d50_collapse(const std::vector<RunRecord>& runs) {
  CollapseCheck c;
  int testable = 0, collapsing = 0;
  std::string detail;
  for (const auto& idx : by_R_n(runs)) {
    c.groups.push_back(collapse_group(runs, idx));
    const auto& g = c.groups.back();
    if (g.quantities.empty()) continue;
    ++testable;
    collapsing += g.collapses;
    std::string parts;
    for (const auto& q : g.quantities) parts += (parts.empty() ? "" : "; ") + quantity_text(q);
    detail += fmt::format(" At {}: {} ({}).", rn_label(g.R_n),
                          g.collapses ? "collapses" : "does not collapse", parts);
  }
  if (testable == 0) {
    c.outcome = "not testable";
    c.verdict = fmt::format(
        "not testable: need runs with two d50 at equal R_n ({} R_n group(s), each with one d50)",
        c.groups.size());
    return c;
  }
  c.outcome = collapsing == testable ? "collapses" : "does not collapse";
  c.verdict = fmt::format("{} at {} of {} R_n with two or more d50.{}", c.outcome, collapsing,
                          testable, detail);
  return c;
}

Hypotheses check_hypotheses(const std::vector<RunRecord>& runs) {
  return {check_kappa_r(runs), check_band_thickness(runs), check_d50_collapse(runs)};
}

}  // namespace iwb::comparison
