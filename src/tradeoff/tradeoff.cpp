#include "tradeoff/tradeoff.hpp"

#include <fmt/core.h>

#include "campaign/pool.hpp"
#include "common/errors.hpp"
#include "dem/run/crosscheck.hpp"
#include "dem/scene/numerics.hpp"
#include "dem/scene/requirements.hpp"
#include "dem/scene/scene_content.hpp"
#include "io/directory_lock.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"
#include "tradeoff/knobs.hpp"
#include "tradeoff/tradeoff_output.hpp"

namespace iwb::tradeoff {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path default_out(const fs::path& scene_file) {
  return fs::path("runs") / ("tradeoff-" + scene_file.stem().string());
}

Reference parse_reference(const std::string& text) {
  if (text == "refined") return Reference::kRefined;
  if (text == "base") return Reference::kBase;
  throw InputError(fmt::format("--reference {}: refined or base", text));
}

const char* to_string(Reference r) {
  return r == Reference::kBase ? "base" : "refined";
}

std::string dem_scene_sha256(const std::string& scene_text, const std::string& scene_file_name) {
  return io::sha256_hex(derived_scene(scene_text, scene_file_name, {}, "base_s1"));
}

namespace {

std::string factor_name(double f) {
  return f < 1.0 ? "x0.5" : "x2";
}

Variant make_variant(const dem::Scene& base, const std::string& text, const std::string& source,
                     std::string name, std::string kind,
                     const std::vector<std::pair<std::string, double>>& knob_factors, int seed) {
  auto settings = knob_settings(base, text, knob_factors);
  if (seed != base.seed) settings.push_back({"seed", std::int64_t(seed)});
  Variant v{{name, "liggghts", settings, derived_scene(text, source, settings, name)},
            std::move(kind),
            "",
            1.0,
            seed};
  if (v.kind == "knob") v.knob = knob_factors.front().first, v.factor = knob_factors.front().second;
  return v;
}

// Particle-steps to expect, for the order of the jobs only: the shear steps plus a typical
// consolidation (the multi-window servo of the shipped scenes takes some 40 windows).
double estimated_cost(const Variant& v) {
  constexpr double kTypicalWindows = 40.0;
  const auto s = dem::parse_scene(v.job.scene_text, v.job.name);
  return double(s.particle_count) *
         (double(dem::derive(s).shear_steps) + kTypicalWindows * s.consolidation.window_steps);
}

std::vector<std::pair<std::string, double>> all_at(const std::vector<std::string>& knobs,
                                                   bool refined) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& k : knobs) {
    const double f = find_knob(k).refining_factor;
    out.push_back({k, refined ? f : 1.0 / f});
  }
  return out;
}

}  // namespace

std::vector<Variant> expand_variants(const TradeoffOptions& opt) {
  if (opt.seeds < 2)
    throw InputError(fmt::format("--seeds {}: the noise floor needs at least 2 seeds", opt.seeds));
  if (opt.knobs.empty()) throw InputError("--knobs: name at least one knob");
  const std::string text = io::read_file(opt.scene_file);
  const std::string source = opt.scene_file.filename().string();
  const dem::Scene base = dem::parse_scene(text, opt.scene_file.string());
  if (base.shear.cyclic())
    throw InputError(
        fmt::format("{}: a cyclic scene; the tradeoff measures monotonic shear (peak, residual, "
                    "dilation, band)",
                    opt.scene_file.string()));
  const bool refine = opt.reference == Reference::kRefined;
  std::vector<Variant> v;
  v.push_back(make_variant(base, text, source, "base_s1", "base", {}, base.seed));
  if (refine)
    v.push_back(
        make_variant(base, text, source, "refined", "refined", all_at(opt.knobs, true), base.seed));
  for (int s = 2; s <= opt.seeds; ++s)
    v.push_back(make_variant(base, text, source, fmt::format("base_s{}", s), "base", {},
                             base.seed + s - 1));
  const std::size_t first_knob = v.size();
  for (const auto& k : opt.knobs)
    for (const double f : {0.5, 2.0})
      if (refine || f != find_knob(k).refining_factor)
        v.push_back(
            make_variant(base, text, source, k + factor_name(f), "knob", {{k, f}}, base.seed));
  v.push_back(make_variant(base, text, source, "coarsened", "coarsened", all_at(opt.knobs, false),
                           base.seed));
  // The rest cheapest first: a tradeoff stopped early then lacks the fewest settings.
  std::stable_sort(v.begin() + long(first_knob), v.end(), [](const Variant& a, const Variant& b) {
    return estimated_cost(a) < estimated_cost(b);
  });
  return v;
}

namespace {

double stage_sum(const json& manifest, const char* key, bool fact) {
  double s = 0.0;
  const json stages =
      manifest.value("stages", json::object());  // named: items() must not outlive it
  for (const auto& [name, stage] : stages.items())
    s += fact ? stage.value("facts", json::object()).value(key, 0.0) : stage.value(key, 0.0);
  return s;
}

// One run's row: what it varies, its status, cost and quantities of interest.
json row_of(const Variant& v, const fs::path& dir) {
  json r = {{"name", v.job.name}, {"kind", v.kind}, {"knob", v.knob},
            {"factor", v.factor}, {"seed", v.seed}, {"settings", campaign::describe(v.job.values)},
            {"status", "not run"}};
  if (!fs::exists(dir / "manifest.json")) return r;
  const auto m = io::read_json_file(dir / "manifest.json");
  r["status"] = m.value("status", "?");
  if (r["status"] != "complete") return r;
  const auto s = io::read_json_file(dir / "summary.json");
  r["particles"] = m.value("particle_count", 0);
  r["timestep_s"] = m.value("/numerics/timestep_s"_json_pointer, 0.0);
  r["stiffness_level"] = m.value("stiffness_level", 0.0);
  r["inertial_number"] = m.value("inertial_number", 0.0);
  r["particle_steps"] = stage_sum(m, "particle_steps", true);
  r["wall_seconds"] = stage_sum(m, "wall_seconds", false);
  // the shear stage alone: its steps follow from dt and the wall speed (consolidation runs fixed
  // windows)
  r["shear_particle_steps"] = m.value("/stages/shear/facts/particle_steps"_json_pointer, 0.0);
  r["shear_steps"] = m.value("/numerics/shear_steps"_json_pointer, 0);
  r["qoi"] = {{"peak_friction", s["peak_friction"]},
              {"residual_friction", s["residual_friction"]},
              {"dilation_rate", std::tan(s.value("dilatancy_angle_deg", 0.0) * M_PI / 180.0)},
              {"total_dilation", s.value("dilation_mm", json())},
              {"band_thickness", s["wall_band_d50"]}};
  return r;
}

}  // namespace

json run_tradeoff(const TradeoffOptions& opt) {
  const auto variants = expand_variants(opt);  // refuses a bad variant before anything runs
  const fs::path out = opt.out.empty() ? default_out(opt.scene_file) : opt.out;
  io::require_output_directory(out, kTradeoffOutput, false);  // before the lock touches it
  const auto lock =
      io::DirectoryLock::take(out, opt.command_line);       // each variant's run locks its own
  io::claim_output_directory(out, kTradeoffOutput, false);  // a tradeoff resumes
  std::vector<campaign::Job> jobs;
  fs::create_directories(out / "scenes");
  for (const auto& v : variants) {
    jobs.push_back(v.job);
    io::write_atomically(out / campaign::scene_path(v.job), v.job.scene_text);
  }
  campaign::SweepSpec spec;  // the pool's record names the scene the variants derive from
  spec.file = opt.scene_file;
  spec.text = io::read_file(opt.scene_file);
  spec.scene_file = opt.scene_file;
  const json record = campaign::run_jobs(spec, jobs,
                                         {out, opt.jobs, opt.processes, opt.stop_after,
                                          opt.command_line, opt.interrupt, opt.progress});
  json rows = json::array();
  for (const auto& v : variants) rows.push_back(row_of(v, out / campaign::run_path(v.job)));
  json result = analyse(rows, opt.reference);
  result["kind"] = "dem-tradeoff";
  result["scene"] = opt.scene_file.string();
  result["dem_scene"] = dem::scene_content(spec.text, opt.scene_file.string());
  result["dem_scene_sha256"] = dem_scene_sha256(spec.text, opt.scene_file.filename().string());
  result["seeds"] = opt.seeds;
  result["knobs"] = opt.knobs;
  result["reference_mode"] = to_string(opt.reference);
  result["status"] = record.value("status", "?");
  result["command_line"] = opt.command_line;
  write_tradeoff(result, out);
  return result;
}

}  // namespace iwb::tradeoff
