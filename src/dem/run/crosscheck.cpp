#include "dem/run/crosscheck.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <map>
#include <regex>

#include "common/errors.hpp"
#include "dem/engines/engines.hpp"
#include "dem/run/consolidation_cache.hpp"
#include "dem/run/run.hpp"
#include "dem/scene/scene.hpp"
#include "io/directory_lock.hpp"
#include "io/json_file.hpp"
#include "io/output_path.hpp"
#include "io/run_directory.hpp"

namespace iwb::dem {

namespace fs = std::filesystem;

bool reusable_seed_run(const fs::path& dir, const Scene& scene, const std::string& scene_text,
                       const Engine& engine) {
  const auto manifest = dir / "manifest.json";
  if (!fs::exists(manifest)) return false;
  const auto m = io::read_json_file(manifest);
  return m.value("status", "") == "complete" &&
         m.value("/scene/sha256"_json_pointer, std::string()) == scene_sha256(scene, scene_text) &&
         m.value("numerics", nlohmann::json()) == engine.numerics(scene);
}

std::string with_seed(const std::string& text, int seed) {
  const std::regex line(R"(^seed[ \t]*=.*$)", std::regex::multiline);
  if (std::regex_search(text, line))
    return std::regex_replace(text, line, fmt::format("seed = {}", seed));
  return fmt::format("seed = {}\n", seed) + text;
}

Scatter scatter_of(const std::vector<double>& v) {
  Scatter s;
  s.n = int(v.size());
  if (v.empty()) return s;
  for (double x : v) s.mean += x;
  s.mean /= double(v.size());
  if (v.size() > 1) {
    for (double x : v) s.sd += (x - s.mean) * (x - s.mean);
    s.sd = std::sqrt(s.sd / double(v.size() - 1));
  }
  return s;
}

Agreement agreement_of(const Scatter& a, const Scatter& b) {
  Agreement g;
  g.difference = b.mean - a.mean;
  if (a.n < 2 || b.n < 2) return g;
  g.judged = true;
  g.standard_error = std::sqrt(a.sd * a.sd / a.n + b.sd * b.sd / b.n);
  g.agree = std::abs(g.difference) <= kAgreementStandardErrors * g.standard_error;
  return g;
}

namespace {

// The quantities compared, read from each run's summary.json.
const std::vector<std::pair<std::string, std::string>> kQuantities = {
    {"peak_friction", "peak tau/sigma_n"},
    {"residual_friction", "residual tau/sigma_n"},
    {"dilation_mm", "total dilation u_n, mm"},
    {"dilation_rate", "dilation rate du_n/du_x (last fifth)"},
    {"wall_band_d50", "wall band thickness / d50"},
};

struct SeedRun {
  nlohmann::json summary;
  double wall_seconds = 0.0;
};

SeedRun run_or_reuse(const Scene& scene, const std::string& text, const std::string& engine_name,
                     const fs::path& dir, const CrosscheckOptions& opt) {
  const auto manifest = dir / "manifest.json";
  const auto engine = make_engine(engine_name);
  const bool complete = reusable_seed_run(dir, scene, text, *engine);
  if (!complete) {
    const auto outcome =
        run_scene(scene, text, *engine,
                  {dir, opt.processes, false, true, opt.command_line, opt.interrupt, opt.progress,
                   consolidation_cache_dir(opt.out / "consolidated")});
    if (!outcome.complete())
      throw std::runtime_error(fmt::format("{}: {} (crosscheck stopped; run it again to continue)",
                                           dir.string(), outcome.status));
  }
  const auto m = io::read_json_file(manifest);
  SeedRun r{io::read_json_file(dir / "summary.json"), 0.0};
  for (const auto& [name, stage] : m["stages"].items())
    r.wall_seconds += stage.value("wall_seconds", 0.0);
  r.summary["dilation_rate"] = std::tan(r.summary.value("dilatancy_angle_deg", 0.0) * M_PI / 180.0);
  return r;
}

std::string cell(const nlohmann::json& q) {
  if (q.value("n", 0) == 0) return "n/a";
  return fmt::format("{:.3f} +- {:.3f} (n={})", q["mean"].get<double>(), q["sd"].get<double>(),
                     q["n"].get<int>());
}

// Verdicts of issue 5: residual friction within 10 %, dilation of the same sign and order of
// magnitude. Each names the numbers.
nlohmann::json verdicts(const nlohmann::json& engines, const std::vector<std::string>& names) {
  nlohmann::json v = nlohmann::json::array();
  if (names.size() < 2) return v;
  const auto& a = engines[names[0]];
  const auto& b = engines[names[1]];
  const double ra = a["residual_friction"]["mean"], rb = b["residual_friction"]["mean"];
  const double rel = std::abs(ra - rb) / (0.5 * (ra + rb));
  v.push_back(
      {{"check", "residual tau/sigma_n within 10 %"},
       {"holds", rel <= 0.10},
       {"text",
        fmt::format(
            "residual friction {} {:.3f} +- {:.3f}, {} {:.3f} +- {:.3f}: {:.1f} % apart ({})",
            names[0], ra, a["residual_friction"]["sd"].get<double>(), names[1], rb,
            b["residual_friction"]["sd"].get<double>(), 100 * rel,
            rel <= 0.10 ? "within 10 %" : "more than 10 %")}});
  const double da = a["dilation_rate"]["mean"], db = b["dilation_rate"]["mean"];
  const bool same_sign = da * db > 0;
  const double ratio = (da != 0 && db != 0) ? std::abs(da / db) : INFINITY;
  const bool same_order = ratio > 0.1 && ratio < 10.0;
  v.push_back(
      {{"check", "dilation: same sign and order of magnitude"},
       {"holds", same_sign && same_order},
       {"text", fmt::format("dilation rate {} {:.3f}, {} {:.3f}: {} sign, ratio {:.2f}", names[0],
                            da, names[1], db, same_sign ? "same" : "opposite", ratio)}});
  return v;
}

Scatter scatter_in(const nlohmann::json& q) {
  if (q.value("n", 0) == 0) return {};
  return {q["mean"].get<double>(), q["sd"].get<double>(), q["n"].get<int>()};
}

// |difference| in standard errors; seeds without scatter give none unless the means are equal.
double standard_errors(const Agreement& g) {
  if (g.standard_error > 0.0) return std::abs(g.difference) / g.standard_error;
  return g.difference == 0.0 ? 0.0 : INFINITY;
}

// Per quantity, whether the first two engines agree within their seed scatter (issue 20).
nlohmann::json agreement(const nlohmann::json& engines, const std::vector<std::string>& names) {
  nlohmann::json a = nlohmann::json::object();
  if (names.size() < 2) return a;
  for (const auto& [key, label] : kQuantities) {
    const Agreement g =
        agreement_of(scatter_in(engines[names[0]][key]), scatter_in(engines[names[1]][key]));
    a[key] = {
        {"difference", g.difference},
        {"standard_error", g.standard_error},
        {"judged", g.judged},
        {"agree", g.agree},
        {"text", !g.judged ? std::string("not judged (fewer than 2 seeds measured it in an engine)")
                           : fmt::format("{} - {} = {:+.3f}, {:.1f} standard errors: {}", names[1],
                                         names[0], g.difference, standard_errors(g),
                                         g.agree ? "agree within the seed scatter" : "apart")}};
  }
  return a;
}

std::string markdown(const nlohmann::json& j, const std::vector<std::string>& names) {
  std::string md = fmt::format("# Cross-engine check: {} ({} seeds per engine)\n\n| quantity |",
                               j["scene"].get<std::string>(), j["seeds"].get<int>());
  for (const auto& e : names) md += " " + e + " |";
  if (names.size() >= 2) md += " agreement (within 2 standard errors of the difference) |";
  md += "\n|---|";
  for (std::size_t i = 0; i < names.size() + (names.size() >= 2 ? 1 : 0); ++i) md += "---|";
  md += "\n";
  for (const auto& [key, label] : kQuantities) {
    md += "| " + label + " |";
    for (const auto& e : names) md += " " + cell(j["engines"][e][key]) + " |";
    if (names.size() >= 2) md += " " + j["agreement"][key]["text"].get<std::string>() + " |";
    md += "\n";
  }
  const std::string blank = names.size() >= 2 ? " |" : "";
  md += "| wall-clock per run, s |";
  for (const auto& e : names) md += " " + cell(j["engines"][e]["wall_seconds"]) + " |";
  md += blank + "\n| shear modes |";
  for (const auto& e : names) md += " " + j["engines"][e]["shear_modes"].dump() + " |";
  md += blank;
  md += "\n\n";
  for (const auto& v : j["verdicts"]) md += "- " + v["text"].get<std::string>() + "\n";
  return md;
}

}  // namespace

nlohmann::json run_crosscheck(const CrosscheckOptions& opt) {
  if (opt.seeds < 1) throw InputError(fmt::format("--seeds {}: need at least one seed", opt.seeds));
  for (const auto& e : opt.engines) make_engine(e);  // unknown engines are refused before any run
  const std::string text = io::read_file(opt.scene_file);
  parse_scene(text, opt.scene_file.string());  // every value checked before the lock creates OUT
  const io::OutputKind kind{"dem-crosscheck", "crosscheck.json"};
  io::require_output_directory(opt.out, kind, false);  // before the lock touches it
  const auto lock =
      io::DirectoryLock::take(opt.out, opt.command_line);  // each seed's run locks its own
  io::claim_output_directory(opt.out, kind, false);
  nlohmann::json out = {{"kind", "dem-crosscheck"},
                        {"scene", opt.scene_file.string()},
                        {"seeds", opt.seeds},
                        {"engines", nlohmann::json::object()}};
  for (const auto& engine : opt.engines) {
    std::map<std::string, std::vector<double>> values;
    nlohmann::json modes = nlohmann::json::array(), runs = nlohmann::json::array();
    for (int seed = 1; seed <= opt.seeds; ++seed) {
      const std::string seeded = with_seed(text, seed);
      const Scene scene = parse_scene(seeded, opt.scene_file.string());
      const fs::path dir = opt.out / fmt::format("{}-seed{}", engine, seed);
      if (opt.progress)
        opt.progress(fmt::format("{} seed {} of {} -> {}", engine, seed, opt.seeds, dir.string()));
      const SeedRun r = run_or_reuse(scene, seeded, engine, dir, opt);
      for (const auto& [key, label] : kQuantities)
        if (r.summary.contains(key) && r.summary[key].is_number())
          values[key].push_back(r.summary[key].get<double>());
      values["wall_seconds"].push_back(r.wall_seconds);
      modes.push_back(r.summary.value("shear_mode", "?"));
      runs.push_back(dir.string());
    }
    auto& e = out["engines"][engine];
    for (const auto& [key, v] : values) {
      const Scatter s = scatter_of(v);
      e[key] = {{"mean", s.mean}, {"sd", s.sd}, {"n", s.n}, {"values", v}};
    }
    for (const auto& [key, label] : kQuantities)
      if (!e.contains(key))
        e[key] = {{"n", 0}, {"why", "no run measured it (e.g. distributed shear: no wall band)"}};
    e["shear_modes"] = modes;
    e["runs"] = runs;
  }
  out["agreement"] = agreement(out["engines"], opt.engines);
  out["verdicts"] = verdicts(out["engines"], opt.engines);
  io::StagedDirectory staged(opt.out);  // both or neither
  io::write_atomically(staged.path() / "crosscheck.json", out.dump(2) + "\n");
  io::write_atomically(staged.path() / "crosscheck.md", markdown(out, opt.engines));
  staged.commit_into();
  return out;
}

}  // namespace iwb::dem
