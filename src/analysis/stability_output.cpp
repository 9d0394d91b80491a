#include "analysis/stability_output.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "comparison/presentation/figure.hpp"
#include "io/output_path.hpp"
#include "io/run_directory.hpp"

namespace iwb::analysis {

namespace fs = std::filesystem;

namespace {

std::string csv_text(std::string s) {  // quoted CSV field
  std::replace(s.begin(), s.end(), '"', '\'');
  std::replace(s.begin(), s.end(), '\n', ' ');
  return "\"" + s + "\"";
}

const char* path_name(PathKind k) {
  return k == PathKind::kCyclic ? "cyclic" : "monotonic";
}

bool cut_back(const StabilityResult& r) {
  return r.rejected_substeps > 0;
}

}  // namespace

std::map<Outcome, long> count_outcomes(const std::vector<StabilityResult>& results) {
  std::map<Outcome, long> n;
  for (auto o : kAllOutcomes) n[o] = 0;
  for (const auto& r : results) ++n[r.outcome];
  return n;
}

std::string stability_csv(const std::vector<StabilityResult>& results, DensityAxis axis) {
  std::string out =
      "boundary,path,sigma_n0_kPa," + std::string(column_of(axis)) +
      ",e0,e_d,e_c,e_i,kappa_r,d_gamma,outcome,reason,"
      "increments,increments_planned,rate_evaluations,rejected_substeps,domain_cutbacks,seconds,"
      "sigma_n_end_kPa,tau_end_kPa,e_end,message\n";
  for (const auto& r : results) {
    const auto& p = r.point;
    out += fmt::format(
        "{},{},{:g},{:g},{:.6g},{:.6g},{:.6g},{:.6g},{:g},{:g},{},{},{},{},{},{},{},{:.4g},"
        "{:.8g},{:.8g},{:.8g},{}\n",
        driver::to_string(p.boundary), path_name(p.path), p.sigma_n_kPa, p.density, r.e0, r.e_d,
        r.e_c, r.e_i, p.kappa_r, p.d_gamma, to_string(r.outcome), csv_text(r.reason), r.increments,
        r.increments_planned, r.rate_evaluations, r.rejected_substeps, r.domain_cutbacks, r.seconds,
        r.sigma_n_end_kPa, r.tau_end_kPa, r.e_end, csv_text(r.message));
  }
  return out;
}

namespace {

std::string outcome_table(const std::vector<StabilityResult>& results,
                          const StabilitySweep& sweep) {
  std::string md = "| outcome |";
  for (auto bc : sweep.boundaries) md += fmt::format(" {} |", driver::to_string(bc));
  md += " all |\n|---|";
  for (std::size_t i = 0; i <= sweep.boundaries.size(); ++i) md += "---:|";
  md += "\n";
  for (auto o : kAllOutcomes) {
    md += fmt::format("| {} |", to_string(o));
    for (auto bc : sweep.boundaries)
      md += fmt::format(" {} |", std::count_if(results.begin(), results.end(), [&](const auto& r) {
                          return r.outcome == o && r.point.boundary == bc;
                        }));
    md += fmt::format(" {} |\n", count_outcomes(results).at(o));
  }
  return md;
}

std::string reason_table(const std::vector<StabilityResult>& results, DensityAxis axis) {
  std::map<std::string, std::pair<long, const StabilityResult*>> reasons;
  for (const auto& r : results)
    if (r.outcome != Outcome::kComplete) {
      auto& [n, example] = reasons[fmt::format("{}: {}", to_string(r.outcome), r.reason)];
      if (n++ == 0) example = &r;
    }
  if (reasons.empty()) return "Every point completed.\n";
  std::string md = "| outcome: reason | points | example (first point) |\n|---|---:|---|\n";
  for (const auto& [why, v] : reasons) {
    const auto& p = v.second->point;
    std::string msg = v.second->message.substr(0, 300);
    std::replace(msg.begin(), msg.end(), '|', '/');
    md += fmt::format(
        "| {} | {} | {} {} sigma_n0 = {:g} kPa, {} = {:g}, kappa_r = {:g}, d gamma = {:g}: {} |\n",
        why, v.first, driver::to_string(p.boundary), path_name(p.path), p.sigma_n_kPa,
        axis == DensityAxis::kOverconsolidationRatio ? "OCR"
        : axis == DensityAxis::kStateParameter       ? "psi"
                                                     : "I",
        p.density, p.kappa_r, p.d_gamma, msg);
  }
  return md;
}

std::string cutback_summary(const std::vector<StabilityResult>& results) {
  long points = 0, rejected = 0, domain = 0, evals = 0;
  for (const auto& r : results) {
    points += cut_back(r);
    rejected += r.rejected_substeps;
    domain += r.domain_cutbacks;
    evals += r.rate_evaluations;
  }
  return fmt::format(
      "The adaptive integrator cut back (rejected at least one substep) at {} of {} points: "
      "{} rejected substeps in all, {} of them because the trial state left the domain; "
      "{} rate evaluations in all.\n",
      points, results.size(), rejected, domain, evals);
}

}  // namespace

std::string stability_markdown(const std::vector<StabilityResult>& results,
                               const StabilitySweep& sw, const StabilityMapInfo& info) {
  std::string md = fmt::format("# Stability map: {} ({} form)\n\nParameters: `{}`. {} points.\n\n",
                               info.model, info.form, info.parameter_file, results.size());
  md += fmt::format(
      "Axes: sigma_n0 {} kPa; {} at sigma_n0 {}; kappa_r {}; "
      "shear strain per increment {} (monotonic shear to gamma = {:g} or {} increments, whichever "
      "comes "
      "first); cyclic: {} cycles of amplitude {:g} in {} increments per quarter at kappa_r = 1. "
      "CNS "
      "stiffness {:g} sigma_n0 per unit normal strain. Budget {:g} s per point, {} substeps per "
      "increment. "
      "Adaptive rk32, rtol 1e-6.\n\n",
      fmt::join(sw.sigma_n_kPa, ", "), label_of(info.axis),
      fmt::join(sw.densities(info.axis), ", "), fmt::join(sw.kappa_r, ", "),
      fmt::join(sw.d_gamma, ", "), sw.gamma_total, sw.max_increments, sw.cycles,
      sw.cyclic_amplitude, sw.cyclic_per_quarter, kCnsStiffnessPerSigma, sw.budget_seconds,
      sw.max_substeps);
  md += "## Outcomes\n\n" + outcome_table(results, sw) + "\n## Why points stopped\n\n" +
        reason_table(results, info.axis);
  md += "\n## Integrator cut-backs\n\n" + cutback_summary(results);
  return md;
}

namespace {

// One figure per boundary condition: a cell per (sigma_n0, I), coloured by the worst outcome of
// its points (kappa_r, increment sizes, cyclic), labelled completed/points, crossed where the
// integrator cut back.
comparison::Figure boundary_map(const std::vector<StabilityResult>& results,
                                driver::BoundaryKind bc, const std::string& model,
                                DensityAxis axis) {
  struct Cell {
    int worst = 0;
    long done = 0, all = 0, cut = 0;
  };
  std::map<std::pair<double, double>, Cell> cells;
  for (const auto& r : results) {
    if (r.point.boundary != bc) continue;
    auto& c = cells[{r.point.sigma_n_kPa, r.point.density}];
    c.worst = std::max(c.worst, int(r.outcome));
    c.done += r.outcome == Outcome::kComplete;
    c.all += 1;
    c.cut += cut_back(r);
  }
  comparison::Figure f{
      fmt::format("stability_{}", driver::to_string(bc)),
      fmt::format("{} under {}: worst outcome per cell (label: completed/points; x: cut back)",
                  model, driver::to_string(bc)),
      "sigma_n0 (kPa)",
      label_of(axis),
      {},
      {},
      "",
      ""};
  f.data.columns = {"sigma_n0_kPa", column_of(axis), "worst_outcome",
                    "completed",    "points",        "cut_back"};
  for (const auto& [key, c] : cells)
    f.data.rows.push_back(
        {key.first, key.second, double(c.worst), double(c.done), double(c.all), double(c.cut)});
  static const char* kColours[] = {"#2ca02c", "#d62728", "#ff7f0e", "#9467bd",
                                   "#7f7f7f", "#000000", "#8c564b"};
  for (std::size_t i = 0; i < kAllOutcomes.size(); ++i)
    f.extra += fmt::format("set linetype {} lc rgb '{}'\n", i + 1, kColours[i]);
  f.extra +=
      "set logscale x\nset xrange [*:*] noextend\nset offsets graph 0.08, graph 0.08, 0.08, 0.08\n";
  // OCR spans decades: logarithmic, with margins in graph units like x's
  if (axis == DensityAxis::kOverconsolidationRatio)
    f.extra +=
        "set logscale y\nset yrange [*:*] noextend\nset offsets graph 0.08, graph 0.08, graph 0.1, "
        "graph 0.1\n";
  const std::string csv = comparison::gnuplot_string(f.name + ".csv");
  f.plot = fmt::format(
      "plot {0} using 1:2:($3+1) skip 1 with points pt 5 ps 5 lc variable notitle, "
      "{0} using 1:($6>0?$2:1/0) skip 1 with points pt 2 ps 2 lc rgb 'white' notitle, "
      "{0} using 1:2:(sprintf('%d/%d',$4,$5)) skip 1 with labels offset 0,2 notitle",
      csv);
  for (std::size_t i = 0; i < kAllOutcomes.size(); ++i)
    f.plot += fmt::format(", NaN with points pt 5 ps 2 lc {} title '{}'", i + 1,
                          to_string(kAllOutcomes[i]));
  return f;
}

}  // namespace

std::vector<fs::path> write_stability_map(const std::vector<StabilityResult>& results,
                                          const StabilitySweep& sweep, const StabilityMapInfo& info,
                                          const fs::path& dir) {
  // the table, its summary and its maps together or not at all
  io::StagedDirectory staged(dir, kStabilityOutput.kind);
  io::write_atomically(staged.path() / "stability.csv", stability_csv(results, info.axis));
  io::write_atomically(staged.path() / "stability.md", stability_markdown(results, sweep, info));
  std::vector<fs::path> figures;
  for (auto bc : sweep.boundaries)
    figures.push_back(
        dir / comparison::draw(boundary_map(results, bc, info.model, info.axis), staged.path())
                  .filename());
  staged.commit_into();
  return figures;
}

}  // namespace iwb::analysis
