#include "studies/study.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "element/element_run.hpp"
#include "io/parameter_sets.hpp"
#include "io/run_directory.hpp"
#include "io/toml_override.hpp"
#include "io/toml_reader.hpp"

namespace iwb::studies {

namespace fs = std::filesystem;

namespace {

// The shipped sets the cases name, written into OUT/parameters/ for the run directories to name,
// and a copy with its changes for every case that changes keys of its set (keyed by
// parameter_file_name).
std::map<std::string, fs::path> study_parameters(const std::vector<ClayCase>& cases,
                                                 const fs::path& out) {
  std::map<std::string, fs::path> files;
  for (const auto& c : cases) files[c.parameters];
  for (const auto& set : io::parameter_sets({}))
    if (files.count(set.name)) files[set.name] = io::parameter_set_file(set, out / "parameters");
  for (const auto& [name, path] : files)
    if (path.empty())
      throw std::logic_error(
          fmt::format("{} is not among the parameter sets built into iwb", name));
  for (const auto& c : cases) {
    if (c.parameter_changes.empty()) continue;
    auto root = io::parse_toml_text(io::read_file(files.at(c.parameters)), c.parameters);
    std::string header = "# " + c.parameters + " with";
    for (const auto& [key, value] : c.parameter_changes) {
      io::set_dotted(root, key, value, c.parameters);
      header += fmt::format(" {} = {:g}", key, value);
    }
    const auto file = out / "parameters" / parameter_file_name(c);
    io::write_atomically(file, header + " (iwb run --study)\n" + io::serialise(root));
    files[parameter_file_name(c)] = file;
  }
  return files;
}

ClayCurve curve_of(const element::ElementRunOutcome& o, const models::Model& m) {
  ClayCurve c;
  c.status = o.result.status;
  c.warnings = o.manifest.value("warnings", std::vector<std::string>{});
  for (const auto& r : o.result.rows) {
    const auto s = m.stress(r.state);
    c.gamma.push_back(r.gamma_x);
    c.eps_n.push_back(r.eps_n);
    c.tau.push_back(s.tau_x);
    c.sigma_n.push_back(s.sigma_n);
  }
  return c;
}

ClayCurve run_case(const std::string& study, const ClayCase& c, const fs::path& parameters,
                   const StudyOptions& opt) {
  const std::string text = element_test_text(c, parameters.string());
  const std::string name = fmt::format("<study:{} {}>", study, c.name);
  auto spec = element::parse_element_test(io::parse_toml_text(text, name), name, ".");
  if (c.seed_start_outside) spec.initial.outside_boundary = models::OutsideBoundary::kWarn;
  element::ElementRunOptions run{opt.out / c.name, opt.force, opt.command_line, text,
                                 opt.interrupt};
  const auto outcome = element::run_element_to_directory(spec, run);
  return curve_of(outcome, *models::find_model(c.model).make(spec.inputs));
}

std::string markdown(const StudyDefinition& study, const std::vector<ClayClaim>& claims) {
  std::string md = fmt::format(
      "# {} (iwb run --study {})\n\n{} Figures: {}.html.\n\n| seed | claim | measured | verdict "
      "|\n|---|---|---|---|\n",
      study.title, study.name, study.setting, study.name);
  for (const auto& c : claims)
    md += fmt::format("| {} | {} | {} | {} |\n", c.section, c.claim, c.measured,
                      c.holds ? "holds" : "does not hold");
  return md;
}

nlohmann::json summary_json(const std::vector<ClayCase>& cases,
                            const std::map<std::string, ClayCurve>& curves,
                            const std::vector<ClayClaim>& claims) {
  nlohmann::json j;
  for (const auto& c : cases) {
    const auto& k = curves.at(c.name);
    j["cases"][c.name] = {{"model", c.model},       {"parameters", c.parameters},
                          {"boundary", c.boundary}, {"sigma_n0_kPa", c.sigma_n_kPa},
                          {"status", k.status},     {"end", k.end_values()}};
    if (!k.warnings.empty()) j["cases"][c.name]["warnings"] = k.warnings;
  }
  for (const auto& c : claims)
    j["claims"].push_back({{"section", c.section},
                           {"claim", c.claim},
                           {"measured", c.measured},
                           {"holds", c.holds},
                           {"values", c.values}});
  return j;
}

// Before anything is written: an earlier study, or any of its runs, stays unless --force.
void refuse_earlier_study(const std::vector<ClayCase>& cases, const StudyOptions& opt) {
  if (opt.force) return;
  std::vector<fs::path> earlier{opt.out / "study.json"};
  for (const auto& c : cases) earlier.push_back(opt.out / c.name / "manifest.json");
  for (const auto& f : earlier)
    if (fs::exists(f))
      throw InputError(
          fmt::format("{}: holds an earlier study ({}); choose another --out or pass --force to "
                      "replace it",
                      opt.out.string(), fs::relative(f, opt.out).string()));
}

}  // namespace

int run_study(const StudyDefinition& study, const StudyOptions& opt) {
  const auto& cases = study.cases;
  refuse_earlier_study(cases, opt);
  io::claim_output_directory(opt.out, {"study", "study.json"}, opt.force);
  const auto parameters = study_parameters(cases, opt.out);
  std::map<std::string, ClayCurve> curves;
  bool complete = true;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& c = cases[i];
    curves[c.name] = run_case(
        study.name, c,
        parameters.at(c.parameter_changes.empty() ? c.parameters : parameter_file_name(c)), opt);
    complete = complete && curves[c.name].status == "complete";
    fmt::print(stderr, "  case {}/{}: {} ({}) {}\n", i + 1, cases.size(), c.name, c.model,
               curves[c.name].status);
    for (const auto& w : curves[c.name].warnings) fmt::print(stderr, "    warning: {}\n", w);
    if (opt.interrupt && opt.interrupt->load()) return 1;
  }
  const auto claims = study.claims(curves);
  const auto figures = draw_figures(study.figures, curves, opt.out);
  io::write_atomically(opt.out / "study.json", summary_json(cases, curves, claims).dump(2) + "\n");
  const std::string md = markdown(study, claims);
  io::write_atomically(opt.out / "study.md", md);
  const auto page = opt.out / (study.name + ".html");
  io::write_atomically(page, study_page(study.title, "iwb run --study " + study.name, study.setting,
                                        claims, figures, opt.out));
  fmt::print("{}\n-> {} ({} figures), {}\n", md, page.string(), figures.size(),
             (opt.out / "study.json").string());
  return complete ? 0 : 1;
}

}  // namespace iwb::studies
