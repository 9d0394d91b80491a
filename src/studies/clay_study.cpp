#include "studies/clay_study.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "common/errors.hpp"
#include "io/element_run.hpp"
#include "io/parameter_sets.hpp"
#include "io/run_directory.hpp"
#include "io/toml_reader.hpp"
#include "studies/clay_cases.hpp"
#include "studies/clay_claims.hpp"
#include "studies/clay_figures.hpp"

namespace iwb::studies {

namespace fs = std::filesystem;

namespace {

// The shipped sets the cases name, written into OUT/parameters/ for the run directories to name.
std::map<std::string, fs::path> study_parameters(const std::vector<ClayCase>& cases, const fs::path& out) {
  std::map<std::string, fs::path> files;
  for (const auto& c : cases) files[c.parameters];
  for (const auto& set : io::parameter_sets({}))
    if (files.count(set.name)) files[set.name] = io::parameter_set_file(set, out / "parameters");
  for (const auto& [name, path] : files)
    if (path.empty()) throw std::logic_error(fmt::format("{} is not among the parameter sets built into iwb", name));
  return files;
}

ClayCurve curve_of(const io::ElementRunOutcome& o, const models::Model& m) {
  ClayCurve c;
  c.status = o.result.status;
  for (const auto& r : o.result.rows) {
    const auto s = m.stress(r.state);
    c.gamma.push_back(r.gamma_x);
    c.eps_n.push_back(r.eps_n);
    c.tau.push_back(s.tau_x);
    c.sigma_n.push_back(s.sigma_n);
  }
  return c;
}

ClayCurve run_case(const ClayCase& c, const fs::path& parameters, const ClayStudyOptions& opt) {
  const std::string text = element_test_text(c, parameters.string());
  const std::string name = fmt::format("<study:clay {}>", c.name);
  const auto spec = io::parse_element_test(io::parse_toml_text(text, name), name, ".");
  io::ElementRunOptions run{opt.out / c.name, opt.force, opt.command_line, text, opt.interrupt};
  const auto outcome = io::run_element_to_directory(spec, run);
  return curve_of(outcome, *models::find_model(c.model).make(spec.inputs));
}

std::string markdown(const std::vector<ClayClaim>& claims) {
  std::string md =
      "# Clay interface models: the seed's 6.4 comparisons (iwb run --study clay)\n\n"
      "Seed Table 6.1 (lambda* 0.1, kappa* 0.01, nu 0.2, phi_c 25 deg, N 1.0) and Table 6.4 for the intergranular "
      "strain; normally consolidated starts (OCR 1) at K0 = 1 - sin phi_c, d_s = 1 mm. Figures: clay.html.\n\n"
      "| seed | claim | measured | verdict |\n|---|---|---|---|\n";
  for (const auto& c : claims)
    md += fmt::format("| {} | {} | {} | {} |\n", c.section, c.claim, c.measured, c.holds ? "holds" : "does not hold");
  return md;
}

nlohmann::json summary_json(const std::vector<ClayCase>& cases, const std::map<std::string, ClayCurve>& curves,
                            const std::vector<ClayClaim>& claims) {
  nlohmann::json j;
  for (const auto& c : cases) {
    const auto& k = curves.at(c.name);
    j["cases"][c.name] = {{"model", c.model}, {"parameters", c.parameters}, {"boundary", c.boundary},
                          {"sigma_n0_kPa", c.sigma_n_kPa}, {"status", k.status}, {"end", k.end_values()}};
  }
  for (const auto& c : claims)
    j["claims"].push_back({{"section", c.section}, {"claim", c.claim}, {"measured", c.measured}, {"holds", c.holds},
                           {"values", c.values}});
  return j;
}

// Before anything is written: an earlier study, or any of its runs, stays unless --force.
void refuse_earlier_study(const std::vector<ClayCase>& cases, const ClayStudyOptions& opt) {
  if (opt.force) return;
  std::vector<fs::path> earlier{opt.out / "study.json"};
  for (const auto& c : cases) earlier.push_back(opt.out / c.name / "manifest.json");
  for (const auto& f : earlier)
    if (fs::exists(f))
      throw InputError(fmt::format("{}: holds an earlier clay study ({}); choose another --out or pass --force to "
                                   "replace it", opt.out.string(), fs::relative(f, opt.out).string()));
}

}  // namespace

int run_clay_study(const ClayStudyOptions& opt) {
  const auto cases = clay_cases();
  refuse_earlier_study(cases, opt);
  const auto parameters = study_parameters(cases, opt.out);
  std::map<std::string, ClayCurve> curves;
  bool complete = true;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& c = cases[i];
    curves[c.name] = run_case(c, parameters.at(c.parameters), opt);
    complete = complete && curves[c.name].status == "complete";
    fmt::print(stderr, "  case {}/{}: {} ({}) {}\n", i + 1, cases.size(), c.name, c.model, curves[c.name].status);
    if (opt.interrupt && opt.interrupt->load()) return 1;
  }
  const auto claims = clay_claims(curves);
  const auto figures = draw_clay_figures(curves, opt.out);
  io::write_atomically(opt.out / "study.json", summary_json(cases, curves, claims).dump(2) + "\n");
  const std::string md = markdown(claims);
  io::write_atomically(opt.out / "study.md", md);
  io::write_atomically(opt.out / "clay.html", clay_page(claims, figures, opt.out));
  fmt::print("{}\n-> {} ({} figures), {}\n", md, (opt.out / "clay.html").string(), figures.size(),
             (opt.out / "study.json").string());
  return complete ? 0 : 1;
}

}  // namespace iwb::studies
