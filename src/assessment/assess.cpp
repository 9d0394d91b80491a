// `iwb assess MODEL PARAMS`: the total Sobol indices of an interface model's element test, or its
// parameter uncertainty (issue 17, seed 4.3.1-4.3.2), their files and tables; the league is
// league_run.cpp's.
#include "assessment/assess.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <map>

#include "assessment/distribution_file.hpp"
#include "assessment/element_sensitivity.hpp"
#include "common/errors.hpp"
#include "comparison/presentation/figure.hpp"
#include "io/parameter_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::assessment {

namespace {

// The Sobol indices and uncertainty of one model (the league has its own directories); each run
// replaces the last one's files, and those only (issue 60).
const io::OutputKind kSensitivityOutput{"assess-sensitivity", "sobol.md"};

// --cov-of KEY=COV, repeated: InputError naming the bad one.
std::map<std::string, double> own_covs(const std::vector<std::string>& given) {
  std::map<std::string, double> out;
  for (const auto& g : given) {
    const auto eq = g.find('=');
    double v = 0.0;
    try {
      if (eq == std::string::npos || eq == 0) throw std::invalid_argument(g);
      v = std::stod(g.substr(eq + 1));
    } catch (const std::exception&) {
      throw InputError(fmt::format("--cov-of {}: give KEY=COV, e.g. alpha_p=0.01", g));
    }
    if (!(v > 0.0 && v <= 1.0))
      throw InputError(fmt::format("--cov-of {}: the COV must be in (0, 1]", g));
    out[g.substr(0, eq)] = v;
  }
  return out;
}

// --tie KEY=FACTOR*OTHER, repeated: InputError naming the bad one.
std::map<std::string, std::pair<double, std::string>> tied(const std::vector<std::string>& given) {
  std::map<std::string, std::pair<double, std::string>> out;
  for (const auto& g : given) {
    const auto eq = g.find('='), star = g.find('*');
    double factor = 0.0;
    try {
      if (eq == std::string::npos || eq == 0 || star == std::string::npos || star < eq ||
          star + 1 == g.size())
        throw std::invalid_argument(g);
      factor = std::stod(g.substr(eq + 1, star - eq - 1));
    } catch (const std::exception&) {
      throw InputError(fmt::format("--tie {}: give KEY=FACTOR*OTHER, e.g. ei0=1.2*ec0", g));
    }
    if (!(factor > 0.0)) throw InputError(fmt::format("--tie {}: the factor must be positive", g));
    out[g.substr(0, eq)] = {factor, g.substr(star + 1)};
  }
  return out;
}

std::string sobol_markdown(const SobolResult& r, const AssessOptions& o) {
  std::string md = fmt::format(
      "# Total Sobol indices: {} ({})\n\nEvery material parameter normal about the file's value "
      "with COV {}{}; "
      "monotonic simple shear under {} from sigma_n0 = {} kPa to gamma = {} in {} increments. "
      "Saltelli's sampling, "
      "Jansen's estimator, N = {} ({} element tests, {} rows dropped for a failed run), 95 % "
      "bootstrap intervals.\n\n"
      "| quantity |",
      o.model, o.params, o.cov,
      (o.cov_of.empty() ? "" : fmt::format(" ({} their own)", fmt::join(o.cov_of, ", "))) +
          (o.ties.empty() ? "" : fmt::format("; tied, not varied: {}", fmt::join(o.ties, ", "))),
      o.boundary, o.sigma_n, o.gamma, o.increments, r.base_samples, r.evaluations, r.failed);
  for (const auto& p : r.parameters) md += " " + p + " |";
  md += "\n|---|";
  for (std::size_t i = 0; i < r.parameters.size(); ++i) md += "---|";
  md += "\n";
  for (std::size_t q = 0; q < r.quantities.size(); ++q) {
    md += "| " + r.quantities[q] + " |";
    for (const auto& t : r.total[q])
      md += fmt::format(" {:.3f} [{:.3f}, {:.3f}] |", t.value, t.low, t.high);
    md += "\n";
  }
  return md;
}

std::string sobol_csv(const SobolResult& r) {
  std::string out = "quantity,parameter,S_T,S_T_low,S_T_high\n";
  for (std::size_t q = 0; q < r.quantities.size(); ++q)
    for (std::size_t i = 0; i < r.parameters.size(); ++i)
      out += fmt::format("{},{},{:.6g},{:.6g},{:.6g}\n", r.quantities[q], r.parameters[i],
                         r.total[q][i].value, r.total[q][i].low, r.total[q][i].high);
  return out;
}

std::string uncertainty_markdown(const UncertaintyResult& r, const AssessOptions& o) {
  std::string md = fmt::format(
      "# Parameter uncertainty: {} ({}, distributions {})\n\nLatin hypercube, {} samples ({} "
      "failed and left out); "
      "monotonic simple shear under {} from sigma_n0 = {} kPa to gamma = {}.\n\n| quantity | mean "
      "| SD | CV_Y |\n"
      "|---|---|---|---|\n",
      o.model, o.params, o.uncertainty, r.samples, r.failed, o.boundary, o.sigma_n, o.gamma);
  for (const auto& q : r.quantities)
    md += fmt::format("| {} | {:.4g} | {:.4g} | {:.3f} |\n", q.name, q.mean, q.sd, q.cv);
  return md;
}

// The indices at N/16, N/8, N/4, N/2 and N (each its own samples): sobol_convergence.csv and .md,
// and a figure of the first quantity's indices with their intervals against N. Returns N's.
SobolResult sobol_convergence(const models::ModelSpec& spec, ElementSensitivityOptions opt,
                              const AssessOptions& o, const std::filesystem::path& dir) {
  std::string csv_text = "N,quantity,parameter,S_T,S_T_low,S_T_high\n";
  std::string md = fmt::format(
      "# Convergence of the total Sobol indices: {} ({}), COV {}\n\nThe first quantity's indices "
      "and their 95 % bootstrap intervals against the base sample size N (each N its own "
      "samples; every quantity in sobol_convergence.csv):\n\n| N |",
      o.model, o.params, o.cov);
  std::vector<comparison::PlotCurve> curves;
  SobolResult r;
  for (int k = 4; k >= 0; --k) {
    opt.samples = std::max(10, o.samples >> k);
    r = element_sensitivity(spec, opt);
    if (k == 4) {
      for (const auto& p : r.parameters) md += " " + p + " |", curves.push_back({p, {}, {}});
      md += "\n|---|";
      for (std::size_t i = 0; i < r.parameters.size(); ++i) md += "---|";
      md += "\n";
    }
    md += fmt::format("| {} |", opt.samples);
    for (std::size_t i = 0; i < r.parameters.size(); ++i) {
      const auto& t = r.total[0][i];
      md += fmt::format(" {:.3f} [{:.3f}, {:.3f}] |", t.value, t.low, t.high);
      curves[i].x.push_back(opt.samples), curves[i].y.push_back(t.value);
      for (std::size_t q = 0; q < r.quantities.size(); ++q)
        csv_text += fmt::format("{},{},{},{:.6g},{:.6g},{:.6g}\n", opt.samples, r.quantities[q],
                                r.parameters[i], r.total[q][i].value, r.total[q][i].low,
                                r.total[q][i].high);
    }
    md += "\n";
  }
  io::prepare_run_directory(dir, kSensitivityOutput, true);
  io::write_atomically(dir / "sobol_convergence.csv", csv_text);
  io::write_atomically(dir / "sobol_convergence.md", md);
  auto fig = comparison::curves_figure(
      "sobol_convergence",
      fmt::format("{}: total Sobol indices of {} against N", o.model, r.quantities.front()),
      "N, the base sample size", "S_T", curves);
  fig.extra += "set logscale x\n";
  comparison::draw(fig, dir);
  return r;
}

// The model's element test, its distributions' means and what is varied: InputError before
// anything runs.
ElementSensitivityOptions element_options(const models::ModelSpec& spec, const AssessOptions& o) {
  ElementSensitivityOptions opt;
  opt.inputs.tables = io::load_parameter_file(o.params);
  opt.inputs.source = o.params;
  spec.make(opt.inputs);  // the means must be a valid set, before anything runs
  opt.boundary = driver::parse_boundary_kind(o.boundary, "--bc");
  opt.cov = o.cov, opt.cov_of = own_covs(o.cov_of), opt.ties = tied(o.ties),
  opt.sigma_n_kPa = o.sigma_n, opt.e0 = o.e0, opt.K_kPa_per_unit_strain = o.K;
  opt.gamma = o.gamma, opt.increments = o.increments, opt.samples = o.samples, opt.seed = o.seed,
  opt.threads = o.threads;
  if (opt.boundary == driver::BoundaryKind::kCNS && !(o.K > 0.0))
    throw InputError("--bc CNS needs --K, the spring stiffness in kPa per unit normal strain");
  opt.progress = o.run_counter();
  return opt;
}

AssessOutcome assess_element(const AssessOptions& o) {
  if (o.model.empty() || o.params.empty())
    throw InputError(
        "iwb assess: give MODEL and PARAMS (the Sobol indices or --uncertainty of one model), or "
        "--reference RUN... (the league)");
  const auto& spec = models::find_model(o.model);
  const auto opt = element_options(spec, o);
  const auto dir = o.out.empty() ? std::filesystem::path("runs") / ("assess-" + o.model)
                                 : std::filesystem::path(o.out);
  io::require_output_directory(dir, kSensitivityOutput, true);  // before the samples' minutes
  if (!o.uncertainty.empty()) {
    const auto r = element_uncertainty(spec, opt, read_distributions(o.uncertainty));
    io::prepare_run_directory(dir, kSensitivityOutput, true);
    const auto md = uncertainty_markdown(r, o);
    io::write_atomically(dir / "uncertainty.md", md);
    return {md, {}};
  }
  const auto r =
      o.convergence ? sobol_convergence(spec, opt, o, dir) : element_sensitivity(spec, opt);
  if (!o.convergence) io::prepare_run_directory(dir, kSensitivityOutput, true);
  const auto md = sobol_markdown(r, o);
  io::write_atomically(dir / "sobol.csv", sobol_csv(r));
  io::write_atomically(dir / "sobol.md", md);
  return {md, dir / "sobol.md"};
}

}  // namespace

AssessOutcome run_assess(const AssessOptions& o) {
  return o.reference.empty() ? assess_element(o) : run_league(o);
}

}  // namespace iwb::assessment
