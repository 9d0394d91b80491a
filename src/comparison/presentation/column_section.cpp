#include "comparison/presentation/column_section.hpp"

#include <fmt/core.h>

#include <map>
#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "comparison/presentation/figure.hpp"
#include "comparison/presentation/html.hpp"
#include "io/csv_table.hpp"
#include "io/json_file.hpp"

namespace iwb::comparison {

namespace fs = std::filesystem;

namespace {

// The last window of a profiles.csv: its travel and the named columns' values there.
struct LastWindow {
  double u_mm = 0.0;
  std::map<std::string, std::vector<double>> columns;
  const std::vector<double>& operator[](const std::string& name) const { return columns.at(name); }
};

LastWindow last_window(const fs::path& csv, const std::vector<std::string>& names) {
  const auto t = io::read_csv_table(csv);
  const auto w = t.values("u_x_mm_window", csv.string());
  LastWindow out;
  out.u_mm = w.empty() ? 0.0 : w.back();
  for (const auto& name : names) {
    const auto all = t.values(name, csv.string());
    auto& kept = out.columns[name];
    for (std::size_t k = 0; k < w.size(); ++k)
      if (w[k] == out.u_mm) kept.push_back(all[k]);
  }
  return out;
}

std::vector<double> void_ratios(const std::vector<double>& porosity) {
  std::vector<double> e;
  for (double n : porosity) e.push_back(n / (1.0 - n));
  return e;
}

// A run's time series as (u_x, y) for a y of its columns (tau/sigma_n when `ratio`).
PlotCurve series(const fs::path& csv, const std::string& title, const std::string& y, bool ratio,
                 const std::string& style) {
  const auto t = io::read_csv_table(csv);
  PlotCurve c{title, t.values("u_x_mm", csv.string()), {}, style};
  if (ratio) {
    const auto tau = t.values("tau_kPa", csv.string());
    const auto sigma = t.values("sigma_n_kPa", csv.string());
    for (std::size_t k = 0; k < tau.size(); ++k) c.y.push_back(tau[k] / sigma[k]);
  } else {
    c.y = t.values(y, csv.string());
  }
  return c;
}

std::vector<fs::path> dem_runs(const nlohmann::json& manifest, const fs::path& run) {
  std::vector<fs::path> runs;
  if (!manifest.contains("dem_runs")) return runs;
  for (const auto& r : manifest["dem_runs"]) {
    const fs::path p = (run / r.get<std::string>()).lexically_normal();
    if (!fs::exists(p / "profiles.csv") || !fs::exists(p / "timeseries.csv"))
      throw InputError(
          fmt::format("{}: the DEM run {} its manifest names has no profiles.csv "
                      "and timeseries.csv",
                      run.string(), p.string()));
    runs.push_back(p);
  }
  return runs;
}

// A DEM run's grain spin over the height from its coarse-grained band profile (fields/,
// the last snapshot), scaled as the column's (w d50 / v_wall) and turned into the column's sense:
// the column's w turns from x1 to x2 (up), the DEM's rotation about y from z to x, so w = -omega_y.
// Empty where the run has no coarse-grained fields.
PlotCurve dem_spin(const fs::path& dem, const std::string& title, double top,
                   const std::string& style) {
  PlotCurve c{title, {}, {}, style};
  const fs::path csv = dem / "fields" / "band_profile.csv";
  if (!fs::exists(csv)) return c;
  const auto scene = io::read_json_file(dem / "manifest.json")["scene"]["resolved"];
  const double scale =
      scene["particles"]["d50_mm"].get<double>() / scene["shear"]["velocity_mm_s"].get<double>();
  const auto t = io::read_csv_table(csv);
  const auto z = t.values("z_over_d50", csv.string());
  const auto spin = t.values("grain_spin_y_rad_s", csv.string());
  for (std::size_t k = 0; k < z.size(); ++k)
    if (z[k] >= 0.0 && z[k] <= top) {
      c.x.push_back(-spin[k] * scale);
      c.y.push_back(z[k]);
    }
  return c;
}

// A run's band width (FWHM of the shear rate, d50) along the travel: the column's band.csv, or a
// DEM run's coarse-grained fields/band.csv at its snapshots after the start. Empty where absent.
PlotCurve band_along(const fs::path& csv, const std::string& title, const std::string& style) {
  PlotCurve c{title, {}, {}, style};
  if (!fs::exists(csv)) return c;
  const auto t = io::read_csv_table(csv);
  const auto u = t.values("u_x_mm", csv.string()), w = t.values("band_fwhm_d50", csv.string());
  for (std::size_t k = 0; k < u.size(); ++k)
    if (u[k] > 0.0) {
      c.x.push_back(u[k]);
      c.y.push_back(w[k]);
    }
  return c;
}

// A DEM run's velocity and void ratio over the column's height `top` (d50), the bins whose grains'
// centres thin out at the wall (solid fraction below 0.4, e above 1.5) left out of the void ratio.
std::pair<PlotCurve, PlotCurve> dem_profiles(const fs::path& dem, const std::string& name,
                                             double top, const std::string& style) {
  const auto w = last_window(dem / "profiles.csv", {"z_over_d50", "vx_over_vwall", "porosity"});
  const auto& z = w["z_over_d50"];
  const auto e = void_ratios(w["porosity"]);
  PlotCurve v{name, {}, {}, style}, ex{name, {}, {}, style};
  for (std::size_t k = 0; k < z.size(); ++k) {
    if (z[k] > top) continue;
    v.x.push_back(w["vx_over_vwall"][k]);
    v.y.push_back(z[k]);
    if (e[k] > 1.5) continue;
    ex.x.push_back(e[k]);
    ex.y.push_back(z[k]);
  }
  return {v, ex};
}

std::vector<Figure> figures(const fs::path& run, const std::vector<fs::path>& dems) {
  const auto col =
      last_window(run / "profiles.csv", {"z_over_d50", "vx_over_vwall", "e", "spin_d50_over_vwall",
                                         "tau_zx_kPa", "tau_xz_kPa", "m_kPa_mm"});
  const auto& z = col["z_over_d50"];
  const double top = z.back() + z.front();  // the column's height in d50
  std::vector<PlotCurve> v, e, friction, u_n, spin, band;
  const std::string dem_style = "with lines lw 1 dt 2";
  for (const auto& d : dems) {
    const auto name = "DEM " + d.filename().string();
    const auto [dv, de] = dem_profiles(d, name, top, dem_style);
    v.push_back(dv);
    e.push_back(de);
    if (auto c = dem_spin(d, name, top, dem_style); !c.x.empty()) spin.push_back(c);
    if (auto c = band_along(d / "fields" / "band.csv", name, "with linespoints lw 1 dt 2");
        !c.x.empty())
      band.push_back(c);
    friction.push_back(series(d / "timeseries.csv", name, "", true, dem_style));
    u_n.push_back(series(d / "timeseries.csv", name, "u_n_mm", false, dem_style));
  }
  const auto label = fmt::format("column at {:.3g} mm", col.u_mm);
  v.push_back({label, col["vx_over_vwall"], z, kReferenceStyle});
  spin.push_back({label, col["spin_d50_over_vwall"], z, kReferenceStyle});
  e.push_back({label, col["e"], z, kReferenceStyle});
  friction.push_back(series(run / "timeseries.csv", "column", "", true, kReferenceStyle));
  band.push_back(band_along(run / "band.csv", "column", "with linespoints lw 3 lc rgb '#000000'"));
  u_n.push_back(series(run / "timeseries.csv", "column", "u_n_mm", false, kReferenceStyle));
  const std::vector<PlotCurve> stresses = {{"tau_zx (on horizontal planes)", col["tau_zx_kPa"], z},
                                           {"tau_xz (on vertical planes)", col["tau_xz_kPa"], z},
                                           {"m (kPa mm)", col["m_kPa_mm"], z}};
  return {curves_figure("column_velocity", "Velocity over the height at the end", "v_x / v_wall",
                        "z / d50", v),
          curves_figure("column_void_ratio", "Void ratio over the height at the end", "e",
                        "z / d50", e),
          curves_figure("column_spin",
                        "Grain spin over the height at the end (the DEM's at its last snapshot)",
                        "w d50 / v_wall", "z / d50", spin),
          curves_figure("column_stresses", "The column's shear and couple stresses at the end",
                        "kPa, kPa mm", "z / d50", stresses),
          curves_figure("column_band", "The band's width along the travel (FWHM of the shear rate)",
                        "u_x (mm)", "band FWHM / d50", band),
          curves_figure("column_friction", "tau / sigma_n along the travel", "u_x (mm)",
                        "tau / sigma_n", friction),
          curves_figure("column_u_n", "u_n along the travel", "u_x (mm)", "u_n (mm)", u_n)};
}

}  // namespace

bool is_column_run(const fs::path& dir) {
  if (!fs::is_directory(dir) || !fs::exists(dir / "manifest.json")) return false;
  const auto m = io::read_json_file(dir / "manifest.json");
  return m.value("kind", "") == "column";
}

void require_column_run(const fs::path& run) {
  dem_runs(io::read_json_file(run / "manifest.json"), run);
  for (const char* f : {"profiles.csv", "timeseries.csv"})
    if (!fs::exists(run / f))
      throw InputError(fmt::format("{}: a column run without {} (stopped before it was written?)",
                                   run.string(), f));
}

ColumnSection column_section(const fs::path& run, const fs::path& fig_dir,
                             const std::string& data_prefix) {
  const auto manifest = io::read_json_file(run / "manifest.json");
  const auto dems = dem_runs(manifest, run);
  const auto& spec = manifest["spec"];
  ColumnSection out;
  out.html = fmt::format(
      "<section><h2>Micro-polar column {}</h2>\n<p>{} column of {:.3g} mm in {} elements, d50 "
      "{:g} mm, e0 {:.3f}, sigma_n0 {:g} kPa, wall rotation {}, wall friction {}; {}. Beside it "
      "{} DEM run(s) (dashed; their last window of profiles.csv over the column's height, z from "
      "the wall's mean height; their void ratio without the bins where the grains' centres thin "
      "out at the wall, e above 1.5).</p>\n<div "
      "class=\"figures\">\n",
      escape_html(run.string()), spec["polar"].get<bool>() ? "A micro-polar" : "A plain",
      spec["height_mm"].get<double>(), spec["elements"].get<int>(), spec["d50_mm"].get<double>(),
      spec["e0"].get<double>(), spec["sigma_n0_kPa"].get<double>(),
      escape_html(spec["wall_rotation"].get<std::string>()),
      escape_html(spec["wall_friction"].dump()), escape_html(manifest.value("status", "")),
      dems.size());
  fs::create_directories(fig_dir);
  for (const auto& f : figures(run, dems)) {
    const auto svg = draw(f, fig_dir);
    out.figures.push_back(svg);
    out.html += fmt::format("<figure>{}<figcaption>{} (data: {}/{}.csv)</figcaption></figure>\n",
                            inline_svg(svg), escape_html(f.title), escape_html(data_prefix),
                            escape_html(f.name));
  }
  out.html += "</div></section>\n";
  return out;
}

}  // namespace iwb::comparison
