#include "dem/engines/contract_outputs.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "io/run_directory.hpp"

namespace iwb::dem {

namespace fs = std::filesystem;

std::vector<std::vector<double>> numeric_lines(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(fmt::format("{}: missing engine output", path.string()));
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || std::isalpha(static_cast<unsigned char>(line[0])))
      continue;
    std::istringstream is(line);
    std::vector<double> row;
    for (double x; is >> x;) row.push_back(x);
    if (!row.empty()) rows.push_back(std::move(row));
  }
  return rows;
}

io::CsvTable timeseries_table(const Scene& s, const Numerics& n, const fs::path& raw, double z0) {
  const double area = s.area_m2();
  io::CsvTable t;
  t.columns = {"t_s",        "u_x_mm", "u_n_mm",       "sigma_n_kPa",     "tau_kPa",
               "e_specimen", "e_band", "coordination", "sigma_plate_kPa", "particles"};
  for (const auto& r : numeric_lines(raw)) {
    if (r.size() < 11) continue;
    // A time that goes back is a resumed attempt's (liggghts/shear_checkpoint.hpp): it supersedes
    // the rows the stopped attempt wrote from that time on.
    while (!t.rows.empty() && t.rows.back()[0] >= r[0]) t.rows.pop_back();
    const double height = (r[2] - s.plate.mean_height_m()) - s.wall.mean_height_m();
    t.rows.push_back({r[0], r[1] * 1e3, (r[2] - z0) * 1e3, r[3] / 1e3, r[4] / 1e3,
                      area * height / r[6] - 1.0, area * (n.band_zhi - n.band_zlo) / r[7] - 1.0,
                      r[8], r[5] / 1e3, r[9]});
  }
  return t;
}

namespace {

// Particles are binned by their centres, but they are thicker than a bin: a bin's solid fraction
// can exceed 1 next to an empty one. Porosity and stresses are therefore averaged over a window of
// one d50 around each bin (empty bins included); velocities are per-particle means and stay as
// they are.
std::vector<ProfileBin> smoothed(const std::vector<ProfileBin>& bins, double window) {
  std::vector<ProfileBin> out = bins;
  for (std::size_t i = 0; i < bins.size(); ++i) {
    double solid = 0, szz = 0, sxz = 0;
    int n = 0;
    for (const auto& b : bins)
      if (std::abs(b.z_over_d50 - bins[i].z_over_d50) <= 0.5 * window + 1e-12)
        solid += b.solid, szz += b.szz, sxz += b.sxz, ++n;
    out[i].solid = solid / n;
    out[i].szz = szz / n;
    out[i].sxz = sxz / n;
  }
  return out;
}

}  // namespace

io::CsvTable profile_table(const Scene& s, const Numerics& n, const ProfileBlocks& blocks,
                           long step0) {
  io::CsvTable t;
  t.columns = {"u_x_mm_window", "z_over_d50",   "vx_over_vwall",
               "porosity",      "sigma_zz_kPa", "tau_zx_kPa"};
  for (const auto& [step, bins] : blocks) {
    if (step <= step0) continue;
    const double time = double(step - step0) * n.dt;
    const double u = s.shear.displacement_at(time) * 1e3;
    const double v_wall = s.shear.speed_at(time);  // below v while the start-up ramp lasts
    for (const auto& b : smoothed(bins, 1.0))
      if (b.count > 0 && b.z_over_d50 >= 0.0)
        t.rows.push_back({u, b.z_over_d50, b.vx / v_wall, 1.0 - b.solid, b.szz / 1e3, b.sxz / 1e3});
  }
  return t;
}

nlohmann::json plate_facts(const Scene& s, const io::CsvTable& timeseries) {
  const double target0 = s.boundary.sigma_n_Pa / 1e3, K = s.boundary.K_Pa_per_m * 1e-3 / 1e3;
  double worst = 0.0, plate_move = 0.0;
  for (const auto& r : timeseries.rows) {
    const double target =
        target0 + (s.boundary.kind == driver::BoundaryKind::kCNS ? K * r[2] : 0.0);
    worst = std::max(worst, std::abs(r[8] / target - 1.0));
    plate_move = std::max(plate_move, std::abs(r[2]));
  }
  nlohmann::json f = {{"plate_max_displacement_mm", plate_move}};
  if (s.boundary.kind != driver::BoundaryKind::kCV)  // under CV the plate stress is free
    f["plate_stress_max_relative_deviation_from_target"] = worst;
  return f;
}

}  // namespace iwb::dem
