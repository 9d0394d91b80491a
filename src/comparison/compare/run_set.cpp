#include "comparison/compare/run_set.hpp"

#include <fmt/core.h>

#include <limits>
#include <set>

#include "common/errors.hpp"
#include "comparison/replay/seed_scatter.hpp"
#include "comparison/verdicts/form_limit_causes.hpp"
#include "io/json_file.hpp"
#include "io/output_path.hpp"
#include "io/run_directory.hpp"

namespace iwb::comparison {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

enum class Earlier { kNone, kSameInputs, kOtherInputs, kIncomplete };

// Whether OUT/<run> holds a complete comparison of exactly these inputs (DEM manifest and
// parameter file by hash, and the model), so that its fit can be reused.
Earlier earlier_comparison(const fs::path& dir, const CompareOptions& opt) {
  if (!fs::exists(dir / "manifest.json")) return Earlier::kNone;
  const auto m = io::read_json_file(dir / "manifest.json");
  if (m.value("status", "") != "complete" || !fs::exists(dir / "compare.json"))
    return Earlier::kIncomplete;
  json seeds = json::array();
  for (const auto& d : opt.seed_dirs) seeds.push_back(d.string());
  const bool same =
      m.value("/inputs/dem_manifest_sha256"_json_pointer, std::string()) ==
          io::sha256_hex(io::read_file(opt.dem_dir / "manifest.json")) &&
      m.value("/inputs/seed_runs"_json_pointer, json()) == seeds &&
      m.value("/inputs/predicted_d_s_over_d50"_json_pointer, json()) ==
          json(opt.predicted_ds_d50) &&
      m.value("/inputs/roughness_scheme"_json_pointer, std::string()) == opt.roughness_scheme &&
      m.value("/inputs/f_c"_json_pointer, std::string()) == opt.f_c &&
      m.value("/inputs/pooled_scatter"_json_pointer, json()) ==
          (opt.pooled ? to_json(*opt.pooled) : json()) &&
      m.value("/inputs/form_limit_sha256"_json_pointer, json()) ==
          (opt.form_limit.empty() ? json() : json(io::sha256_hex(io::read_file(opt.form_limit)))) &&
      m.value("/inputs/parameters_sha256"_json_pointer, std::string()) ==
          io::sha256_hex(io::read_file(opt.params)) &&
      io::read_json_file(dir / "compare.json").value("model", "") == opt.model;
  return same ? Earlier::kSameInputs : Earlier::kOtherInputs;
}

// Runs or reuses the comparison of one DEM run; returns whether it was reused.
bool compare_or_reuse(CompareOptions opt) {
  switch (earlier_comparison(opt.out, opt)) {
    case Earlier::kSameInputs:
      return true;
    case Earlier::kOtherInputs:
      if (!opt.force)
        throw InputError(
            fmt::format("{}: holds a complete comparison of other inputs (DEM run, parameters or "
                        "model); pass --force to replace it",
                        opt.out.string()));
      break;
    case Earlier::kIncomplete:
      opt.force = true;
      break;  // an interrupted comparison is no result
    case Earlier::kNone:
      break;
  }
  run_comparison(opt);
  return false;
}

std::vector<std::string> run_names(const std::vector<fs::path>& dirs) {
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const auto& d : dirs) {
    auto p = fs::path(d).lexically_normal();
    if (p.filename().empty()) p = p.parent_path();  // "dir/" names dir
    const std::string name = p.filename().string();
    if (!seen.insert(name).second)
      throw InputError(
          fmt::format("--runs: two runs are named '{}' ({}); their comparisons would share "
                      "OUT/{}",
                      name, d.string(), name));
    names.push_back(name);
  }
  return names;
}

}  // namespace

RunRecord load_run_record(const fs::path& compare_dir) {
  const fs::path cf = compare_dir / "compare.json";
  const auto cmp = io::read_json_file(cf);
  const fs::path dem_dir = io::json_field<std::string>(cmp, "/dem/dir", cf);
  const fs::path sf = dem_dir / "summary.json";
  const auto s = io::read_json_file(sf);
  RunRecord r;
  r.name = compare_dir.filename().string();
  r.R_n = io::json_field<double>(cmp, "/dem/R_n", cf);
  r.d50_mm = io::json_field<double>(cmp, "/dem/d50_mm", cf);
  r.kappa_r_fit = io::json_field<double>(cmp, "/fit/kappa_r", cf);
  // null where the fit's Jacobian was singular (a flat objective): no sigma, not a bad file
  const nlohmann::json::json_pointer sigma("/fit/sigma_kappa_r");
  r.sigma_kappa_r_fit = cmp.contains(sigma) && cmp.at(sigma).is_null()
                            ? std::numeric_limits<double>::quiet_NaN()
                            : io::json_field<double>(cmp, sigma.to_string(), cf);
  r.d_s_fit_d50 = io::json_field<double>(cmp, "/fit/d_s_over_d50", cf);
  r.peak_friction = io::json_field<double>(s, "/peak_friction", sf);
  r.residual_friction = io::json_field<double>(s, "/residual_friction", sf);
  r.dilation_mm = io::json_field<double>(s, "/dilation_mm", sf);
  r.shear_mode = io::json_field<std::string>(s, "/shear_mode", sf);
  if (s.contains("wall_band_d50") && s["wall_band_d50"].is_number())
    r.band_d50 = s["wall_band_d50"].get<double>();
  return r;
}

namespace {
// One seed scatter per cell of the set (runs of one scene but for the seed), for the pooling.
std::vector<SeedScatter> cell_scatters(const std::vector<DemRun>& dems) {
  std::vector<SeedScatter> out;
  std::vector<bool> done(dems.size(), false);
  for (std::size_t i = 0; i < dems.size(); ++i) {
    if (done[i]) continue;
    std::vector<DemRun> seeds;
    for (std::size_t j = i + 1; j < dems.size(); ++j)
      if (!done[j] && same_scene_but_seed(dems[i], dems[j]))
        seeds.push_back(dems[j]), done[j] = true;
    out.push_back(seed_scatter(dems[i], seeds));
  }
  return out;
}
}  // namespace

RunSetOutcome run_hypothesis_set(const RunSetOptions& opt) {
  if (opt.dem_dirs.empty()) throw InputError("--runs: no DEM run directories given");
  const auto names = run_names(opt.dem_dirs);
  // every input read and checked before OUT is created: a bad one leaves nothing behind
  std::vector<DemRun> dems;
  for (const auto& d : opt.dem_dirs) dems.push_back(load_dem_run(d, opt.allow_partial));
  const auto parameters = validated_parameters(opt.model, opt.params);
  for (const auto& dem : dems)
    require_startable(dem,
                      standard_variants(dem, opt.model, parameters, opt.predicted_ds_d50).front(),
                      opt.params);
  if (!opt.form_limit.empty()) read_form_limit(opt.form_limit, opt.model);
  if (!opt.roughness_scheme.empty() || !opt.f_c.empty()) {
    CompareOptions c;
    c.model = opt.model, c.roughness_scheme = opt.roughness_scheme, c.f_c = opt.f_c;
    models::Roughness r{models::find_model(opt.model).declaration.roughness.default_scheme, 1.0};
    chosen_roughness(c, r);  // refused here, before OUT is made
  }
  // a set's comparisons are reused or redone one by one (--force: redone); its files stay ours
  io::claim_output_directory(opt.out, {"hypothesis set"}, false);
  json manifest = {
      {"kind", "hypothesis set"}, {"command_line", opt.command_line}, {"model", opt.model},
      {"parameters", opt.params}, {"started", io::utc_timestamp()},   {"status", "running"}};
  io::write_manifest(opt.out, manifest);
  const PooledScatter pooled = pool_scatter(cell_scatters(dems));
  io::write_atomically(opt.out / "pooled_scatter.json", to_json(pooled).dump(2) + "\n");
  RunSetOutcome outcome;
  std::vector<RunRecord> records;
  try {
    // the other seeds of each run's scene in the set: their scatter weighs its fit and verdicts
    for (std::size_t i = 0; i < names.size(); ++i) {
      CompareOptions c;
      c.dem_dir = opt.dem_dirs[i], c.model = opt.model, c.params = opt.params;
      c.out = opt.out / names[i];
      c.allow_partial = opt.allow_partial, c.force = opt.force, c.command_line = opt.command_line;
      c.predicted_ds_d50 = opt.predicted_ds_d50;
      c.form_limit = opt.form_limit;
      c.roughness_scheme = opt.roughness_scheme, c.f_c = opt.f_c;
      if (opt.pool_scatter) c.pooled = pooled;
      for (const auto& seed : seeds_of(dems[i], dems)) c.seed_dirs.push_back(seed.dir);
      if (compare_or_reuse(c)) outcome.reused.push_back(names[i]);
      outcome.compare_dirs.push_back(c.out);
      records.push_back(load_run_record(c.out));
    }
  } catch (
      const std::exception& e) {  // the manifest never stays "running" (CONVENTIONS.md "Results")
    manifest["status"] = fmt::format("failed: {}", e.what());
    manifest["finished"] = io::utc_timestamp();
    io::write_manifest(opt.out, manifest);
    throw;
  }
  outcome.hypotheses = to_json(check_hypotheses(records), records);
  io::StagedDirectory staged(opt.out);  // both or neither, then the manifest says complete
  io::write_atomically(staged.path() / "hypotheses.json", outcome.hypotheses.dump(2) + "\n");
  io::write_atomically(staged.path() / "hypotheses.md", to_markdown(outcome.hypotheses));
  staged.commit_into();
  manifest["runs"] = names;
  manifest["reused"] = outcome.reused;
  manifest["files"] = {"hypotheses.json", "hypotheses.md"};
  manifest["finished"] = io::utc_timestamp();
  manifest["status"] = "complete";
  io::write_manifest(opt.out, manifest);
  return outcome;
}

}  // namespace iwb::comparison
