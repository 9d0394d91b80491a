#include "comparison/compare.hpp"

#include <fmt/core.h>

#include "comparison/fit.hpp"
#include "comparison/metrics.hpp"
#include "io/parameter_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::comparison {

namespace {

// kappa_r from the wall's R_n by eq. 5.35; a flat wall (R_n = 0) gets the floor.
std::pair<double, std::string> gutjahr_kappa(double R_n) {
  if (!(R_n > 0.0))
    return {models::kKappaRFloor, fmt::format("kappa_r = {} (flat wall: eq. 5.35's floor)", models::kKappaRFloor)};
  const double k = gutjahr_kappa_r(R_n);
  return {k, fmt::format("kappa_r = {:.3f} (eq. 5.35, R_n = {:.3g})", k, R_n)};
}

std::string curves_csv(const DemRun& dem, const std::vector<Replay>& replays) {
  std::string s = "variant,u_x_mm,tau_dem_kPa,tau_model_kPa,sigma_n_dem_kPa,sigma_n_model_kPa,u_n_dem_mm,u_n_model_mm\n";
  for (std::size_t v = 0; v < replays.size(); ++v) {
    const auto& r = replays[v];
    for (std::size_t i = 0; i < r.u_x_mm.size(); ++i)
      s += fmt::format("{},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g}\n", v, r.u_x_mm[i], dem.tau_kPa[i],
                       r.tau_kPa[i], dem.sigma_n_kPa[i], r.sigma_n_kPa[i], dem.u_n_mm[i], r.u_n_mm[i]);
  }
  return s;
}

}  // namespace

double gutjahr_kappa_r(double R_n, double log_base) {
  if (!(R_n > 0.0)) return models::kKappaRFloor;
  return models::kappa_r_from_normalized_roughness(R_n, log_base).value;
}

std::vector<Variant> standard_variants(const DemRun& dem, const std::string& model,
                                       const models::ModelInputs& parameters) {
  const auto [kappa, kappa_label] = gutjahr_kappa(dem.R_n);
  std::vector<std::pair<double, std::string>> thicknesses = {{5.0 * dem.d50_mm, "d_s = 5 d50"},
                                                             {10.0 * dem.d50_mm, "d_s = 10 d50"}};
  if (const auto band = dem.band_d50())
    thicknesses.push_back({*band * dem.d50_mm, fmt::format("d_s = measured wall band ({:.2g} d50)", *band)});
  std::vector<Variant> out;
  for (const auto& [d_s, label] : thicknesses) {
    Variant v{fmt::format("{}, {}", kappa_label, label), model, parameters, d_s};
    v.inputs.roughness = {models::RoughnessScheme::kGutjahr, kappa};
    out.push_back(v);
  }
  return out;
}

nlohmann::json run_comparison(const CompareOptions& opt) {
  const DemRun dem = load_dem_run(opt.dem_dir, opt.allow_partial);
  models::ModelInputs params;
  params.tables = io::load_parameter_file(opt.params);
  params.source = opt.params;
  models::find_model(opt.model).make(params);  // parameters validated before anything runs
  io::prepare_run_directory(opt.out, opt.force);
  nlohmann::json manifest = {{"kind", "comparison"},
                             {"workbench", {{"name", "iwb"}, {"version", IWB_VERSION}}},
                             {"command_line", opt.command_line},
                             {"inputs", {{"dem_run", opt.dem_dir.string()},
                                         {"dem_manifest_sha256", io::sha256_hex(io::read_file(opt.dem_dir / "manifest.json"))},
                                         {"parameters", opt.params},
                                         {"parameters_sha256", io::sha256_hex(io::read_file(opt.params))}}},
                             {"started", io::utc_timestamp()},
                             {"status", "running"}};
  io::write_manifest(opt.out, manifest);

  std::vector<Replay> replays;
  nlohmann::json variants = nlohmann::json::array();
  auto candidates = standard_variants(dem, opt.model, params);
  // the fitted variant, started from the first standard one
  const FitResult fit = fit_kappa_and_ds(dem, candidates.front());
  Variant fitted = candidates.front();
  fitted.inputs.roughness.kappa_r = fit.kappa_r;
  fitted.d_s_mm = fit.d_s_mm;
  fitted.label = fmt::format("fitted: kappa_r = {:.3f} +- {:.3f}, d_s = {:.2f} +- {:.2f} mm ({:.1f} d50)", fit.kappa_r,
                             fit.sigma_kappa_r, fit.d_s_mm, fit.sigma_d_s_mm, fit.d_s_mm / dem.d50_mm);
  candidates.push_back(fitted);
  for (const auto& v : candidates) {
    replays.push_back(replay(dem, v));
    variants.push_back({{"index", replays.size() - 1},
                        {"label", v.label},
                        {"kappa_r", v.inputs.roughness.kappa_r},
                        {"d_s_mm", v.d_s_mm},
                        {"status", replays.back().status},
                        {"metrics", to_json(compare(dem, replays.back()))}});
  }
  const nlohmann::json result = {
      {"dem", {{"dir", opt.dem_dir.string()}, {"engine", dem.engine}, {"status", dem.status},
               {"boundary", driver::to_string(dem.boundary)}, {"R_n", dem.R_n}, {"d50_mm", dem.d50_mm},
               {"sigma_n0_kPa", dem.sigma_n_kPa.front()}, {"e0_band", dem.e_band.front()}}},
      {"model", opt.model},
      {"variants", variants},
      {"fit", {{"kappa_r", fit.kappa_r}, {"sigma_kappa_r", fit.sigma_kappa_r}, {"d_s_mm", fit.d_s_mm},
               {"sigma_d_s_mm", fit.sigma_d_s_mm}, {"d_s_over_d50", fit.d_s_mm / dem.d50_mm},
               {"rmse_tau_kPa", fit.rmse_tau_kPa}, {"evaluations", fit.evaluations},
               {"algorithm", fit.algorithm}, {"stop", fit.stop_reason},
               {"kappa_r_gutjahr", candidates.front().inputs.roughness.kappa_r}}},
      {"replay", {{"normal_control", "the DEM's boundary condition: CNL with its measured sigma_n(t), CNS with its K, CV"},
                  {"initial_state", "DEM sigma_n and band void ratio of the first row; K0 = 1 - sin(phi_c)"},
                  {"strain_increment", kReplayStrainIncrement}}}};
  io::write_atomically(opt.out / "compare.json", result.dump(2) + "\n");
  io::write_atomically(opt.out / "compare.csv", curves_csv(dem, replays));
  manifest["finished"] = io::utc_timestamp();
  manifest["status"] = "complete";
  manifest["files"] = {"compare.json", "compare.csv"};
  io::write_manifest(opt.out, manifest);
  return result;
}

}  // namespace iwb::comparison
