// `iwb assess MODEL PARAMS`: the total Sobol indices of an interface model's element test (issue 17,
// seed 4.3.1). The parameter and model uncertainty and the league table of the issue are to come.
#include <fmt/core.h>
#include <fmt/ranges.h>

#include <map>

#include <filesystem>
#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"
#include "assessment/element_sensitivity.hpp"
#include "common/errors.hpp"
#include "io/parameter_file.hpp"
#include "io/run_directory.hpp"
#include "io/toml_reader.hpp"

namespace iwb::app {

namespace {

struct AssessOptions {
  std::string model, params, out, boundary = "CNL", uncertainty;
  double cov = 0.1, sigma_n = 100.0, e0 = 0.0, K = 0.0, gamma = 0.1;
  int samples = 1000, increments = 200;
  unsigned seed = 1;
  std::vector<std::string> cov_of;  // KEY=COV
};

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
    if (!(v > 0.0 && v <= 1.0)) throw InputError(fmt::format("--cov-of {}: the COV must be in (0, 1]", g));
    out[g.substr(0, eq)] = v;
  }
  return out;
}

std::string markdown(const assessment::SobolResult& r, const AssessOptions& o) {
  std::string md = fmt::format(
      "# Total Sobol indices: {} ({})\n\nEvery material parameter normal about the file's value with COV {}{}; "
      "monotonic simple shear under {} from sigma_n0 = {} kPa to gamma = {} in {} increments. Saltelli's sampling, "
      "Jansen's estimator, N = {} ({} element tests, {} rows dropped for a failed run), 95 % bootstrap intervals.\n\n"
      "| quantity |",
      o.model, o.params, o.cov, o.cov_of.empty() ? "" : fmt::format(" ({} their own)", fmt::join(o.cov_of, ", ")),
      o.boundary, o.sigma_n, o.gamma, o.increments, r.base_samples, r.evaluations, r.failed);
  for (const auto& p : r.parameters) md += " " + p + " |";
  md += "\n|---|";
  for (std::size_t i = 0; i < r.parameters.size(); ++i) md += "---|";
  md += "\n";
  for (std::size_t q = 0; q < r.quantities.size(); ++q) {
    md += "| " + r.quantities[q] + " |";
    for (const auto& t : r.total[q]) md += fmt::format(" {:.3f} [{:.3f}, {:.3f}] |", t.value, t.low, t.high);
    md += "\n";
  }
  return md;
}

std::string csv(const assessment::SobolResult& r) {
  std::string out = "quantity,parameter,S_T,S_T_low,S_T_high\n";
  for (std::size_t q = 0; q < r.quantities.size(); ++q)
    for (std::size_t i = 0; i < r.parameters.size(); ++i)
      out += fmt::format("{},{},{:.6g},{:.6g},{:.6g}\n", r.quantities[q], r.parameters[i], r.total[q][i].value,
                         r.total[q][i].low, r.total[q][i].high);
  return out;
}

// A distribution file (data/assessment/distributions/): [[parameter]] key, distribution
// ("normal", "lognormal", "uniform"), mean, cov.
std::vector<assessment::Distribution> read_distributions(const std::string& file) {
  const auto root = io::parse_toml_file(file);  // a syntax error is bad input (exit 2), naming the file
  io::TableReader top(root, file);
  std::vector<assessment::Distribution> out;
  for (auto& p : top.array_of_tables("parameter")) {
    const std::string kind = p.text("distribution");
    const auto k = kind == "normal"      ? assessment::Distribution::Kind::kNormal
                   : kind == "lognormal" ? assessment::Distribution::Kind::kLognormal
                   : kind == "uniform"   ? assessment::Distribution::Kind::kUniform
                                         : throw InputError(fmt::format("{} = \"{}\"; allowed \"normal\", \"lognormal\", \"uniform\"",
                                                                        p.where("distribution"), kind));
    out.push_back({p.text("key"), k, p.positive("mean"), p.positive("cov", 1.0)});
    p.finish();
  }
  top.finish();
  return out;
}

std::string uncertainty_markdown(const assessment::UncertaintyResult& r, const AssessOptions& o) {
  std::string md = fmt::format(
      "# Parameter uncertainty: {} ({}, distributions {})\n\nLatin hypercube, {} samples ({} failed and left out); "
      "monotonic simple shear under {} from sigma_n0 = {} kPa to gamma = {}.\n\n| quantity | mean | SD | CV_Y |\n"
      "|---|---|---|---|\n",
      o.model, o.params, o.uncertainty, r.samples, r.failed, o.boundary, o.sigma_n, o.gamma);
  for (const auto& q : r.quantities) md += fmt::format("| {} | {:.4g} | {:.4g} | {:.3f} |\n", q.name, q.mean, q.sd, q.cv);
  return md;
}

int run_assess(const AssessOptions& o) {
  const auto& spec = models::find_model(o.model);
  assessment::ElementSensitivityOptions opt;
  opt.inputs.tables = io::load_parameter_file(o.params);
  opt.inputs.source = o.params;
  spec.make(opt.inputs);  // the means must be a valid set, before anything runs
  opt.boundary = driver::parse_boundary_kind(o.boundary, "--bc");
  opt.cov = o.cov, opt.cov_of = own_covs(o.cov_of), opt.sigma_n_kPa = o.sigma_n, opt.e0 = o.e0, opt.K_kPa_per_unit_strain = o.K;
  opt.gamma = o.gamma, opt.increments = o.increments, opt.samples = o.samples, opt.seed = o.seed;
  if (opt.boundary == driver::BoundaryKind::kCNS && !(o.K > 0.0))
    throw InputError("--bc CNS needs --K, the spring stiffness in kPa per unit normal strain");
  const auto dir = o.out.empty() ? std::filesystem::path("runs") / ("assess-" + o.model) : std::filesystem::path(o.out);
  const auto tick = increment_progress();
  opt.progress = [&](long done, long total) { tick(done, total); };
  if (!o.uncertainty.empty()) {
    const auto r = assessment::element_uncertainty(spec, opt, read_distributions(o.uncertainty));
    io::prepare_run_directory(dir, true);
    const auto md = uncertainty_markdown(r, o);
    io::write_atomically(dir / "uncertainty.md", md);
    fmt::print("{}", md);
    return 0;
  }
  const auto r = assessment::element_sensitivity(spec, opt);
  io::prepare_run_directory(dir, true);
  io::write_atomically(dir / "sobol.csv", csv(r));
  io::write_atomically(dir / "sobol.md", markdown(r, o));
  fmt::print("{}", markdown(r, o));
  fmt::print(stderr, "-> {}\n", (dir / "sobol.md").string());
  return 0;
}

}  // namespace

void add_assess_command(CLI::App& app, CommandList& commands) {
  auto o = std::make_shared<AssessOptions>();
  auto* cmd = app.add_subcommand(
      "assess",
      "Global sensitivity of an interface model (seed 4.3.1, Tables 4.3-4.7): every material parameter of its "
      "tables normal about the parameter file's value with one coefficient of variation (--cov; the seed takes 0.05 "
      "and 0.1), a monotonic simple-shear element test per sample, and the total Sobol index of each parameter for "
      "the peak and end friction, the end normal strain and the end normal stress (Saltelli's sampling, Jansen's "
      "estimator, 95 % bootstrap intervals; N (k + 2) runs for k parameters). Writes sobol.csv and sobol.md.\n\n"
      "Example: iwb assess mc data/params/table_4_3_mohr_coulomb.toml --cov 0.1 --samples 2000");
  cmd->add_option("model", o->model, "model name (iwb models)")->required();
  cmd->add_option("params", o->params, "parameter file: the distributions' means")->required()->check(input_file());
  cmd->add_option("--cov", o->cov, "coefficient of variation of every parameter")->check(number_in(positive(1.0)));
  cmd->add_option("--cov-of", o->cov_of,
                  "KEY=COV: this parameter's own coefficient of variation instead of --cov (repeat; the seed takes 0.01 "
                  "for the sensitive parameters it stars, e.g. Mortara's alpha_p, alpha_c, omega)");
  cmd->add_option("--bc", o->boundary, "CNL, CNS or CV")->check(CLI::IsMember({"CNL", "CNS", "CV"}));
  cmd->add_option("--sigma-n", o->sigma_n, "initial normal stress, kPa")->check(number_in(positive(1e5), "kPa"));
  cmd->add_option("--e0", o->e0, "initial void ratio, for a model that has one")->check(number_in(positive(10.0)));
  cmd->add_option("--K", o->K, "CNS spring stiffness, kPa per unit normal strain")->check(number_in(positive(1e9)));
  cmd->add_option("--gamma", o->gamma, "shear strain of the test")->check(number_in(positive(10.0)));
  cmd->add_option("--increments", o->increments, "increments of the test")->check(whole_in(10, 100000));
  cmd->add_option("--samples", o->samples, "N, the base sample size")->check(whole_in(10, 1000000));
  cmd->add_option("--seed", o->seed, "random seed of the samples");
  cmd->add_option("--uncertainty", o->uncertainty,
                  "instead of the Sobol indices: the CV of each quantity when the parameters follow the distributions of "
                  "this file ([[parameter]] key, distribution, mean, cov; data/assessment/distributions/, seed Table 4.8), "
                  "from --samples Latin hypercube samples")
      ->check(input_file());
  cmd->add_option("--out,-o", o->out, "output directory (default runs/assess-<model>)")->check(output_directory());
  commands.add(cmd, [o](const CommandContext&) { return run_assess(*o); });
}

}  // namespace iwb::app
