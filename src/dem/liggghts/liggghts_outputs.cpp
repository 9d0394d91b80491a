#include "dem/liggghts/liggghts_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "common/errors.hpp"
#include "io/run_directory.hpp"

namespace iwb::dem {

namespace fs = std::filesystem;

namespace {

std::vector<std::vector<double>> numeric_lines(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(fmt::format("{}: missing engine output", path.string()));
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || std::isalpha(static_cast<unsigned char>(line[0]))) continue;
    std::istringstream is(line);
    std::vector<double> row;
    for (double x; is >> x;) row.push_back(x);
    if (!row.empty()) rows.push_back(std::move(row));
  }
  return rows;
}

io::CsvTable timeseries(const StageContext& ctx, const Numerics& n, double z0) {
  const Scene& s = ctx.scene;
  const double area = s.area_m2();
  io::CsvTable t;
  t.columns = {"t_s", "u_x_mm", "u_n_mm", "sigma_n_kPa", "tau_kPa", "e_specimen", "e_band",
               "coordination", "sigma_plate_kPa", "particles"};
  // raw: t ux zplate sigma_wall tau_wall sigma_plate vsolid vband coordination atoms ke
  for (const auto& r : numeric_lines(ctx.work_dir / "timeseries.raw")) {
    if (r.size() < 11) continue;
    const double height = (r[2] - s.plate.mean_height_m()) - s.wall.mean_height_m();
    t.rows.push_back({r[0], r[1] * 1e3, (r[2] - z0) * 1e3, r[3] / 1e3, r[4] / 1e3,
                      area * height / r[6] - 1.0, area * (n.band_zhi - n.band_zlo) / r[7] - 1.0, r[8],
                      r[5] / 1e3, r[9]});
  }
  return t;
}

struct Bin {
  double z, count, vx, solid, szz, sxz;  // solid fraction and stresses are per bin volume
};

// Particles are binned by their centres, but they are thicker than a bin: a bin's solid fraction
// can exceed 1 next to an empty one. Porosity and stresses are therefore averaged over a window of
// one d50 around each bin (empty bins included); velocities are per-particle means and stay as
// they are.
std::vector<Bin> smoothed(const std::vector<Bin>& bins, double window) {
  std::vector<Bin> out = bins;
  for (std::size_t i = 0; i < bins.size(); ++i) {
    double solid = 0, szz = 0, sxz = 0;
    int n = 0;
    for (const auto& b : bins)
      if (std::abs(b.z - bins[i].z) <= 0.5 * window + 1e-12) solid += b.solid, szz += b.szz, sxz += b.sxz, ++n;
    out[i].solid = solid / n;
    out[i].szz = szz / n;
    out[i].sxz = sxz / n;
  }
  return out;
}

io::CsvTable profiles(const StageContext& ctx, const Numerics& n, long step0) {
  const Scene& s = ctx.scene;
  io::CsvTable t;
  t.columns = {"u_x_mm_window", "z_over_d50", "vx_over_vwall", "porosity", "sigma_zz_kPa", "tau_zx_kPa"};
  std::ifstream in(ctx.work_dir / "profiles.raw");
  if (!in) return t;
  std::map<long, std::vector<Bin>> blocks;
  std::string line;
  long step = -1;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream is(line);
    std::vector<double> v;
    for (double x; is >> x;) v.push_back(x);
    if (v.size() == 2) {  // block header: step, number of bins
      step = long(v[0]);
      continue;
    }
    // bin, z, count, vx, mean particle volume, mean s_zz*V, mean s_xz*V, number density
    if (v.size() < 8 || step <= step0) continue;
    const double density = v[7];
    blocks[step].push_back({(v[1] - s.wall.mean_height_m()) / n.d50, v[2], v[3], density * v[4],
                            -density * v[5], -density * v[6]});
  }
  for (const auto& [st, bins] : blocks) {
    const double u = s.shear.displacement_at(double(st - step0) * n.dt) * 1e3;
    for (const auto& b : smoothed(bins, 1.0))
      if (b.count > 0 && b.z >= 0.0)
        t.rows.push_back({u, b.z, b.vx / s.shear.velocity_m_s, 1.0 - b.solid, b.szz / 1e3, b.sxz / 1e3});
  }
  return t;
}

// vtk/particles.pvd and vtk/walls.pvd indexing the engine's snapshots by shear time.
void write_pvd(const fs::path& dir, const std::string& stem, long step0, double dt) {
  const std::regex pattern(stem + "_([0-9]+)\\.vtk");
  std::map<long, std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    std::smatch m;
    const std::string name = e.path().filename().string();
    if (std::regex_match(name, m, pattern)) files[std::stol(m[1])] = name;
  }
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [step, name] : files)
    xml += fmt::format("  <DataSet timestep=\"{:.9g}\" file=\"{}\"/>\n", double(step - step0) * dt, name);
  xml += "</Collection>\n</VTKFile>\n";
  io::write_atomically(dir / (stem + ".pvd"), xml);
}

}  // namespace

ContractTables assemble_liggghts_outputs(const StageContext& ctx, const nlohmann::json& facts,
                                         const Numerics& n) {
  const long step0 = facts.at("shear").at("step0").get<long>();
  const double z0 = facts.at("shear").at("z0_m").get<double>();
  ContractTables out;
  out.timeseries = timeseries(ctx, n, z0);
  out.profiles = profiles(ctx, n, step0);
  write_pvd(ctx.run_dir / "vtk", "particles", step0, n.dt);
  write_pvd(ctx.run_dir / "vtk", "walls", step0, n.dt);

  // How well the plate did what the boundary condition asks, measured on the plate itself.
  const Scene& s = ctx.scene;
  const double target0 = s.boundary.sigma_n_Pa / 1e3, K = s.boundary.K_Pa_per_m * 1e-3 / 1e3;
  double worst = 0.0, plate_move = 0.0;
  for (const auto& r : out.timeseries.rows) {
    const double target = target0 + (s.boundary.kind == driver::BoundaryKind::kCNS ? K * r[2] : 0.0);
    worst = std::max(worst, std::abs(r[8] / target - 1.0));
    plate_move = std::max(plate_move, std::abs(r[2]));
  }
  out.facts = {{"timestep_s", n.dt}, {"shear_start_step", step0}, {"plate_max_displacement_mm", plate_move}};
  if (s.boundary.kind != driver::BoundaryKind::kCV)  // under CV the plate stress is free
    out.facts["plate_stress_max_relative_deviation_from_target"] = worst;
  return out;
}

}  // namespace iwb::dem
