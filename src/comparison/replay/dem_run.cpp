#include "comparison/replay/dem_run.hpp"

#include <fmt/core.h>

#include "common/band_zone.hpp"
#include "common/errors.hpp"
#include "io/csv_table.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::comparison {

namespace fs = std::filesystem;

const std::vector<std::string>& required_timeseries_columns() {
  static const std::vector<std::string> c = {"t_s",         "u_x_mm",  "u_n_mm",
                                             "sigma_n_kPa", "tau_kPa", "e_band"};
  return c;
}

std::optional<double> DemRun::band_d50() const {
  if (summary.is_object() && summary.contains("wall_band_d50") &&
      summary["wall_band_d50"].is_number())
    return summary["wall_band_d50"].get<double>();
  return std::nullopt;
}

DemRun load_dem_run(const fs::path& dir, bool allow_partial) {
  DemRun r;
  r.dir = dir;
  const fs::path manifest_path = dir / "manifest.json";
  const auto m = io::read_json_file(manifest_path);
  r.status = io::json_field<std::string>(m, "/status", manifest_path);
  if (r.status != "complete" && !allow_partial)
    throw InputError(
        fmt::format("{}: run status is '{}'; pass --allow-partial to compare it anyway",
                    dir.string(), r.status));
  r.engine = m.value("/engine/name"_json_pointer, std::string("unknown"));
  r.boundary = driver::parse_boundary_kind(
      io::json_field<std::string>(m, "/scene/resolved/boundary/type", manifest_path),
      manifest_path.string() + ": /scene/resolved/boundary/type");
  r.sigma_n0_kPa = io::json_field<double>(m, "/scene/resolved/boundary/sigma_n_kPa", manifest_path);
  r.K_kPa_per_mm = m.value("/scene/resolved/boundary/K_kPa_per_mm"_json_pointer, 0.0);
  r.d50_mm = io::json_field<double>(m, "/scene/resolved/particles/d50_mm", manifest_path);
  r.R_n = io::json_field<double>(m, "/R_n", manifest_path);
  r.wall_zone_mm = wall_zone_thickness(
      r.d50_mm, io::json_field<double>(m, "/scene/resolved/specimen/height_mm", manifest_path));
  r.scene_but_seed = m.at("/scene/resolved"_json_pointer);
  r.scene_but_seed.erase("seed");
  r.scene_text = m.value("/scene/text"_json_pointer, std::string());

  const fs::path ts_path = dir / "timeseries.csv";
  if (!fs::exists(ts_path)) throw InputError(fmt::format("{}: missing", ts_path.string()));
  const auto ts = io::read_csv_table(ts_path);  // header, field count, finite numbers, by line
  for (const auto& c : required_timeseries_columns())
    if (ts.column(c) < 0) {
      std::string have;
      for (const auto& x : ts.columns) have += (have.empty() ? "" : ", ") + x;
      throw InputError(
          fmt::format("{}:1: missing column '{}' (the header has: {})", ts_path.string(), c, have));
    }
  if (ts.rows.size() < 2)
    throw InputError(fmt::format("{}: fewer than two rows", ts_path.string()));
  r.t_s = ts.values("t_s");
  for (std::size_t i = 1; i < r.t_s.size(); ++i)
    if (!(r.t_s[i] > r.t_s[i - 1]))
      throw InputError(fmt::format("{}:{}: t_s = {:g} after {:g}: time must increase",
                                   ts_path.string(), i + 2, r.t_s[i], r.t_s[i - 1]));
  r.u_x_mm = ts.values("u_x_mm");
  r.u_n_mm = ts.values("u_n_mm");
  r.sigma_n_kPa = ts.values("sigma_n_kPa");
  r.tau_kPa = ts.values("tau_kPa");
  r.e_band = ts.values("e_band");
  for (std::size_t i = 0; i < r.sigma_n_kPa.size(); ++i)
    if (!(r.sigma_n_kPa[i] > 0.0))
      throw InputError(
          fmt::format("{}:{}: sigma_n_kPa = {:g}; the contract's normal stress is compression "
                      "positive and must be > 0",
                      ts_path.string(), i + 2, r.sigma_n_kPa[i]));
  // the contract's profiles are the band the report draws: a run without them is refused here,
  // not by the report after a comparison was written (issue 37)
  if (!fs::exists(dir / "profiles.csv"))
    throw InputError(fmt::format("{}: missing (the run-directory contract's velocity profiles)",
                                 (dir / "profiles.csv").string()));
  if (fs::exists(dir / "summary.json")) r.summary = io::read_json_file(dir / "summary.json");
  if (r.summary.is_object())
    r.wall_mean_abs_slope =
        io::json_optional<double>(r.summary, "/wall_mean_abs_slope", dir / "summary.json");
  return r;
}

std::vector<double> cyclic_travel(const DemRun& dem) {
  return cycles::travel_at_speed(
      dem.t_s, dem.scene_but_seed.value("/shear/velocity_mm_s"_json_pointer, 0.0));
}

std::optional<cycles::Program> cyclic_program(const DemRun& dem) {
  if (!dem.scene_but_seed.is_object()) return std::nullopt;
  const auto& sh = dem.scene_but_seed.value("shear", nlohmann::json::object());
  const int n = sh.value("cycles", 0);
  if (n < 1) return std::nullopt;
  return cycles::Program{sh.value("amplitude_mm", 0.0), n, sh.value("post_cyclic_mm", 0.0)};
}

}  // namespace iwb::comparison
