#include "comparison/presentation/band_figures.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <regex>

#include "io/csv_table.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"
#include "io/vtk_files.hpp"

namespace iwb::comparison {

namespace fs = std::filesystem;

namespace {

constexpr int kMaps = 3;

std::vector<std::string> field_files(const fs::path& fields) {
  const std::string pvd = io::read_file(fields / "fields.pvd");
  const std::regex entry("file=\"(fields_[0-9]+\\.vti)\"");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), entry); it != std::sregex_iterator();
       ++it)
    out.push_back((*it)[1]);
  return out;
}

Figure shear_rate_map(const fs::path& vti, double u_x_mm, double wall_mean, double d50,
                      std::size_t k) {
  const io::ImageGrid im = io::read_image(vti);
  const io::VtkArray* rate = nullptr;
  for (const auto& a : im.arrays)
    if (a.name == "shear_rate_dvx_dz_1_s") rate = &a;
  if (!rate) throw std::runtime_error(vti.string() + ": no shear_rate_dvx_dz_1_s");
  Figure f{fmt::format("band_map_{}", k),
           fmt::format("|dV_x/dz| over x-z at u_x = {:.2f} mm (coarse-grained)", u_x_mm),
           "x / d50",
           "z / d50 (above the wall's mean surface)",
           {},
           {},
           "",
           ""};
  f.data.columns = {"x_over_d50", "z_over_d50", "shear_rate_1_s"};
  for (int j = 0; j < im.nz; ++j)
    for (int i = 0; i < im.nx; ++i)
      f.data.rows.push_back(
          {(im.origin.x() + i * im.spacing.x()) / d50,
           (im.origin.z() + j * im.spacing.z() - wall_mean) / d50,
           std::abs(rate->values[std::size_t(j) * std::size_t(im.nx) + std::size_t(i)])});
  f.extra =
      "set size ratio -1\nset palette rgbformulae 21,22,23\nset cblabel '1/s'\nunset key\nset tics "
      "out\n";
  f.plot = fmt::format("plot {} using 1:2:3 skip 1 with image", gnuplot_string(f.name + ".csv"));
  return f;
}

Figure profiles_figure(const io::CsvTable& p, const std::vector<ShearZoneMark>& marks,
                       double v_wall, double sigma_n) {
  const auto z = p.values("z_over_d50");
  const auto scaled = [&](const char* name, double by) {
    auto v = p.values(name);
    for (double& x : v) x /= by;
    return v;
  };
  auto rate = scaled("shear_rate_dvx_dz_1_s", 1.0);
  double peak = 1e-30;
  for (double r : rate) peak = std::max(peak, std::abs(r));
  for (double& r : rate) r = std::abs(r) / peak;
  Figure f = curves_figure("band_profiles", "Coarse-grained profiles, second half of the travel",
                           "value (normalised)", "z / d50 (above the wall's mean surface)",
                           {{"solid fraction", p.values("solid_fraction"), z},
                            {"V_x / v_wall", scaled("velocity_x_m_s", v_wall), z},
                            {"|dV_x/dz| / its peak", rate, z},
                            {"sigma_xz / sigma_n", scaled("stress_xz_Pa", sigma_n), z},
                            {"sigma_zz / sigma_n", scaled("stress_zz_Pa", sigma_n), z}});
  f.extra += "set xrange [-0.1:1.3]\n";
  const char* colours[] = {"#cc0000", "#0055cc", "#228833"};
  for (std::size_t i = 0; i < marks.size(); ++i)
    f.extra += fmt::format(
        "set arrow from -0.1,{0} to 1.3,{0} nohead dt 2 lw 2 lc rgb '{1}'\n"
        "set label {2} at 0.95,{0} offset 0,0.7 tc rgb '{1}'\n",
        marks[i].d_s_d50, colours[i % 3], gnuplot_string(marks[i].label));
  return f;
}

// The void ratio's change since the start of shear inside each marked shear zone: where the DEM's
// dilation happens against where the model puts it.
Figure void_ratio_figure(const fs::path& fields, const std::vector<std::string>& profiles,
                         const std::vector<double>& u, const std::vector<ShearZoneMark>& marks,
                         double d50_mm) {
  std::vector<PlotCurve> curves;
  for (const auto& m : marks) {
    PlotCurve dem{
        fmt::format("DEM, coarse-grained, z <= {} ({:.1f} d50)", m.label, m.d_s_d50), {}, {}};
    double e_start = NAN;
    for (std::size_t i = 0; i < profiles.size(); ++i) {
      const auto p = io::read_csv_table(fields / profiles[i]);
      const auto z = p.values("z_over_d50"), nu = p.values("solid_fraction");
      double sum = 0.0;
      int n = 0;
      for (std::size_t j = 0; j < z.size(); ++j)
        if (z[j] >= 0.0 && z[j] <= m.d_s_d50) sum += nu[j], ++n;
      const double e = double(n) / sum - 1.0;
      if (i == 0) e_start = e;
      dem.x.push_back(u[i]), dem.y.push_back(e - e_start);
    }
    PlotCurve model{fmt::format("model, (1 + e0) u_n / d_s ({})", m.label), m.u_x_mm, {}};
    for (double un : m.u_n_mm) model.y.push_back((1.0 + m.e0) * un / (m.d_s_d50 * d50_mm));
    curves.push_back(std::move(dem));
    curves.push_back(std::move(model));
  }
  return curves_figure("band_void_ratio", "Void ratio change inside the shear zone", "u_x (mm)",
                       "e - e(start of shear)", curves);
}

}  // namespace

std::vector<Figure> band_figures(const fs::path& dem_dir, const std::vector<ShearZoneMark>& marks) {
  const fs::path fields = dem_dir / "fields";
  if (!fs::exists(fields / "fields.pvd") || !fs::exists(dem_dir / "summary.json")) return {};
  const auto summary = io::read_json_file(dem_dir / "summary.json");
  if (!summary.contains("coarse_graining")) return {};
  const auto& cg = summary["coarse_graining"];
  const double d50 = cg.value("d50_m", 0.0), wall_mean = cg.value("wall_mean_height_m", 0.0);
  const auto files = field_files(fields);
  const auto band = io::read_csv_table(fields / "band.csv");
  const auto u = band.values("u_x_mm");
  std::vector<Figure> out;
  if (d50 <= 0.0 || files.size() != u.size()) return out;
  // up to three maps spread over the travel after its start, the last snapshot always among them
  std::vector<std::size_t> shown;
  for (int j = 1; j <= kMaps; ++j) {
    const auto i = std::size_t(std::lround(double(files.size() - 1) * j / kMaps));
    if (i > 0 && (shown.empty() || shown.back() != i)) shown.push_back(i);
  }
  for (std::size_t k = 0; k < shown.size(); ++k)
    out.push_back(shear_rate_map(fields / files[shown[k]], u[shown[k]], wall_mean, d50, k + 1));
  const auto mean = io::read_csv_table(fields / "band_profile.csv");
  if (!mean.rows.empty()) {
    const auto sigma = band.values("sigma_n_kPa");
    const double v_wall = cg.value("wall_speed_m_s", 0.0);
    const auto vx = mean.values("velocity_x_m_s");
    const double v = v_wall > 0.0 ? v_wall : *std::max_element(vx.begin(), vx.end());
    out.push_back(profiles_figure(mean, marks, v, 1e3 * sigma.back()));
  }
  if (!marks.empty()) {
    std::vector<std::string> profiles;
    for (const auto& f : files)
      profiles.push_back(
          std::regex_replace(f, std::regex("fields_([0-9]+)\\.vti"), "profile_$1.csv"));
    out.push_back(void_ratio_figure(fields, profiles, u, marks, 1e3 * d50));
  }
  return out;
}

}  // namespace iwb::comparison
