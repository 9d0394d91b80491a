#include "dem/analysis/run_fields.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <map>
#include <regex>

#include "coarse_graining/fields.hpp"
#include "common/errors.hpp"
#include "dem/analysis/band_checks.hpp"
#include "dem/scene/numerics.hpp"
#include "dem/scene/scene.hpp"
#include "io/csv_table.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"
#include "io/vtk_files.hpp"

namespace iwb::dem {

namespace fs = std::filesystem;

namespace {

constexpr double kPlaneSpacingPerWidth = 0.5;  // the .vti's spacing: the kernel is smooth on it
constexpr double kProfileSpacingPerWidth = 0.25;
constexpr double kPlaneMarginWidths =
    2.0;  // the image shows the kernel's smear this far past the grains

struct SnapshotFile {
  long step;
  double time_s;
};

// The snapshots of the run's particles.pvd (dem/engines/snapshots.hpp writes it by shear time).
std::vector<SnapshotFile> snapshot_files(const fs::path& vtk) {
  const fs::path pvd = vtk / "particles.pvd";
  if (!fs::exists(pvd))
    throw InputError(
        fmt::format("{}: no particle series (vtk/particles.pvd)", vtk.parent_path().string()));
  const std::string text = io::read_file(pvd);
  const std::regex entry("timestep=\"([^\"]+)\" file=\"particles_([0-9]+)\\.vtp\"");
  std::vector<SnapshotFile> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry);
       it != std::sregex_iterator(); ++it)
    out.push_back({std::stol((*it)[2]), std::stod((*it)[1])});
  if (out.empty())
    throw InputError(fmt::format(
        "{}: no .vtp snapshots listed (a run from before issue 21 has legacy .vtk only)",
        pvd.string()));
  return out;
}

Eigen::Vector3d vec3(const io::VtkArray& a, std::size_t i) {
  return {a.values[3 * i], a.values[3 * i + 1], a.values[3 * i + 2]};
}

const io::VtkArray& array_in(const io::VtkArray* a, const fs::path& file, const char* name) {
  if (!a) throw InputError(fmt::format("{}: no array '{}'", file.string(), name));
  return *a;
}

coarse_graining::Snapshot read_snapshot(const fs::path& vtk, long step) {
  const fs::path pf = vtk / fmt::format("particles_{}.vtp", step),
                 cf = vtk / fmt::format("contacts_{}.vtp", step);
  const io::PointCloud p = io::read_points(pf);
  const auto& r = array_in(p.find("radius_m"), pf, "radius_m");
  const auto& m = array_in(p.find("mass_kg"), pf, "mass_kg");
  const auto& v = array_in(p.find("velocity_m_s"), pf, "velocity_m_s");
  const auto& w = array_in(p.find("angular_velocity_rad_s"), pf, "angular_velocity_rad_s");
  coarse_graining::Snapshot s;
  for (std::size_t i = 0; i < p.points.size(); ++i)
    s.grains.push_back({p.points[i], vec3(v, i), vec3(w, i), r.values[i], m.values[i]});
  const io::Segments c = io::read_segments(cf);
  const auto& f = array_in(c.find("force_N"), cf, "force_N");
  const auto& b = array_in(c.find("boundary"), cf, "boundary");
  for (std::size_t i = 0; i < c.from.size(); ++i)
    s.contacts.push_back({c.from[i], c.to[i], vec3(f, i), b.values[i] > 0.5});
  return s;
}

std::pair<double, double> height_range(const coarse_graining::Snapshot& s) {
  double lo = 1e300, hi = -1e300;
  for (const auto& g : s.grains)
    lo = std::min(lo, g.position.z()), hi = std::max(hi, g.position.z());
  return {lo, hi};
}

io::ImageGrid image_of(const coarse_graining::PlaneGrid& grid, const coarse_graining::FieldSet& f,
                       double width_y) {
  io::ImageGrid im{
      grid.nx(), 1, grid.nz(), {0.0, 0.5 * width_y, grid.z_lo()}, {grid.hx(), grid.hx(), grid.hz()},
      {}};
  for (const auto& field : f.fields) im.arrays.push_back({field.name, 1, field.values});
  return im;
}

io::CsvTable profile_table(const coarse_graining::HeightProfile& grid,
                           const coarse_graining::FieldSet& f, double wall_mean, double d50) {
  io::CsvTable t;
  t.columns = {"z_over_d50"};
  for (const auto& field : f.fields) t.columns.push_back(field.name);
  for (std::size_t j = 0; j < grid.size(); ++j) {
    std::vector<double> row{(grid.z(j) - wall_mean) / d50};
    for (const auto& field : f.fields) row.push_back(field.values[j]);
    t.rows.push_back(std::move(row));
  }
  return t;
}

struct RunContext {
  dem::Scene scene;
  dem::Numerics numerics;
  io::CsvTable timeseries;
  nlohmann::json summary;
  double width;
  std::string manifest_kind;  // the run directory's (a scene's run, a soil cell's)
};

RunContext open_run(const fs::path& dir, const RunFieldsOptions& opt) {
  const fs::path manifest = dir / "manifest.json";
  if (!fs::exists(manifest))
    throw InputError(fmt::format("{}: not a run directory (no manifest.json)", dir.string()));
  const auto m = io::read_json_file(manifest);
  RunContext c{dem::parse_scene(io::json_field<std::string>(m, "/scene/text", manifest),
                                io::json_field<std::string>(m, "/scene/source", manifest)),
               {},
               io::read_csv_table(dir / "timeseries.csv"),
               fs::exists(dir / "summary.json") ? io::read_json_file(dir / "summary.json")
                                                : nlohmann::json::object(),
               0.0,
               m.value("kind", "dem-run")};
  c.numerics = dem::derive(c.scene);
  const double w = opt.width_d50.value_or(c.scene.coarse_graining.width_d50);
  if (!(w > 0.0) || w > 0.5 * c.scene.height_m / c.numerics.d50)
    throw InputError(
        fmt::format("coarse-graining width {} d50 outside (0, {:.3g}] (half the specimen's height)",
                    w, 0.5 * c.scene.height_m / c.numerics.d50));
  c.width = w * c.numerics.d50;
  return c;
}

// One snapshot's height profile: computed (and its .vti written), or read back.
io::CsvTable profile_of(const RunContext& c, const fs::path& dir, const SnapshotFile& f,
                        bool force) {
  const fs::path vti = dir / "fields" / fmt::format("fields_{}.vti", f.step);
  const fs::path csv = dir / "fields" / fmt::format("profile_{}.csv", f.step);
  if (!force && fs::exists(vti) && fs::exists(csv)) return io::read_csv_table(csv);
  const coarse_graining::Snapshot s = read_snapshot(dir / "vtk", f.step);
  const coarse_graining::GaussianKernel kernel(c.width);
  const coarse_graining::PeriodicCell cell{c.scene.length_m, c.scene.width_m};
  const auto [lo, hi] = height_range(s);
  const coarse_graining::PlaneGrid plane(kernel, cell, kPlaneSpacingPerWidth * c.width,
                                         lo - kPlaneMarginWidths * c.width,
                                         hi + kPlaneMarginWidths * c.width);
  io::write_image(vti, image_of(plane, coarse_graining::coarse_grain(s, plane), c.scene.width_m));
  // the profile spans the kernel's whole reach, so that its integrals conserve mass
  const coarse_graining::HeightProfile profile(kernel, cell, kProfileSpacingPerWidth * c.width,
                                               lo - kernel.reach(), hi + kernel.reach());
  const io::CsvTable t = profile_table(profile, coarse_graining::coarse_grain(s, profile),
                                       c.scene.wall.mean_height_m(), c.numerics.d50);
  io::write_atomically(csv, t.to_csv());
  return t;
}

// The snapshot's grains: their volume (the mass balance's reference) and their v_x / v_wall binned
// by centre (the band check's kernel-free profile).
struct GrainsOfSnapshot {
  double volume_m3 = 0.0;
  coarse_graining::BinnedProfile velocity;
};

GrainsOfSnapshot grains_of(const RunContext& c, const fs::path& vtk, long step) {
  const fs::path pf = vtk / fmt::format("particles_{}.vtp", step);
  const io::PointCloud p = io::read_points(pf);
  const auto& r = array_in(p.find("radius_m"), pf, "radius_m");
  const auto& v = array_in(p.find("velocity_m_s"), pf, "velocity_m_s");
  const double d50 = c.numerics.d50, base = c.scene.wall.mean_height_m(),
               speed = c.scene.shear.velocity_m_s;
  GrainsOfSnapshot g;
  std::vector<double> z, vx;
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    g.volume_m3 += 4.0 / 3.0 * M_PI * std::pow(r.values[i], 3);
    z.push_back((p.points[i].z() - base) / d50);
    vx.push_back(speed > 0.0 ? v.values[3 * i] / speed : 0.0);
  }
  g.velocity = coarse_graining::bin_means(z, vx, 0.0, c.scene.outputs.profile_bin_d50);
  return g;
}

}  // namespace

nlohmann::json coarse_grain_run(const fs::path& dir, const RunFieldsOptions& opt) {
  RunContext c = open_run(dir, opt);
  io::claim_output_directory(dir, {c.manifest_kind}, false);  // its run's, or refused
  const auto files = snapshot_files(dir / "vtk");
  fs::create_directories(dir / "fields");
  std::vector<SnapshotProfile> profiles;
  std::vector<io::TimedFile> series;
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < files.size(); ++k) {
    const auto& f = files[k];
    const GrainsOfSnapshot grains = grains_of(c, dir / "vtk", f.step);
    profiles.push_back(
        {f.time_s, profile_of(c, dir, f, opt.force), grains.volume_m3, grains.velocity});
    series.push_back({f.time_s, fmt::format("fields_{}.vti", f.step)});
    if (opt.progress) {
      const double spent =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      opt.progress(fmt::format("  coarse-graining: snapshot {} of {}, ETA {:.0f} s", k + 1,
                               files.size(), spent / double(k + 1) * double(files.size() - k - 1)));
    }
  }
  io::write_collection(dir / "fields" / "fields.pvd", series);
  const BandChecks checks = band_checks(c.scene, c.numerics, c.timeseries, profiles, c.width);
  io::write_atomically(dir / "fields" / "band.csv", checks.per_snapshot.to_csv());
  io::write_atomically(dir / "fields" / "band_profile.csv", checks.mean_profile.to_csv());
  c.summary["coarse_graining"] = checks.json;
  io::write_atomically(dir / "summary.json", c.summary.dump(2) + "\n");
  return checks.json;
}

}  // namespace iwb::dem
