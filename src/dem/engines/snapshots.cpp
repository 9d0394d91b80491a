#include "dem/engines/snapshots.hpp"

#include <fmt/core.h>

#include <cmath>
#include <map>
#include <optional>
#include <regex>
#include <unordered_map>

#include "common/errors.hpp"
#include "dem/engines/contract_outputs.hpp"
#include "io/vtk_files.hpp"

namespace iwb::dem {

namespace fs = std::filesystem;

namespace {

constexpr int kGluedType = 2;  // LIGGGHTS's type of the glued wall spheres (consolidate.in)
constexpr std::size_t kContactColumns = 15;

struct RawFiles {
  fs::path particles, walls;
};

std::map<long, RawFiles> raw_files(const fs::path& dumps, const DumpNames& names) {
  std::map<long, RawFiles> out;
  if (!fs::exists(dumps)) return out;
  const std::regex particles(names.particles), walls(names.walls);
  for (const auto& e : fs::directory_iterator(dumps)) {
    const std::string name = e.path().filename().string();
    std::smatch m;
    if (std::regex_match(name, m, particles)) out[std::stol(m[1])].particles = e.path();
    if (std::regex_match(name, m, walls)) out[std::stol(m[1])].walls = e.path();
  }
  return out;
}

const io::VtkArray& required(const io::PointCloud& c, const std::string& name,
                             const fs::path& file) {
  const auto* a = c.find(name);
  if (!a)
    throw std::runtime_error(
        fmt::format("{}: the engine's dump lacks the point array '{}'", file.string(), name));
  return *a;
}

// One snapshot's grains in the scene frame: positions wrapped into the cell, and as the engine
// gives them (unwrapped by LIGGGHTS's image flags; YADE's may be wrapped) for the displacement.
struct Grains {
  io::PointCloud wrapped;
  std::unordered_map<long, Eigen::Vector3d> unwrapped;  // by id, see above
  std::unordered_map<long, int> type;  // every particle of the dump, glued ones too
};

double wrap(double x, double length) {
  return x - length * std::floor(x / length);
}

Grains read_grains(const Scene& s, const fs::path& file, const SnapshotFrame& frame) {
  const io::PointCloud raw = io::read_points(file);
  const auto &id = required(raw, "id", file), &radius = required(raw, "radius", file),
             &mass = required(raw, "mass", file);
  const auto &v = required(raw, "v", file), &omega = required(raw, "omega", file);
  const io::VtkArray *image = raw.find("i"), *type = raw.find("type");
  Grains g;
  io::VtkArray ids{"id", 1, {}}, radii{"radius_m", 1, {}}, masses{"mass_kg", 1, {}},
      vel{"velocity_m_s", 3, {}}, spin{"angular_velocity_rad_s", 3, {}};
  for (std::size_t i = 0; i < raw.points.size(); ++i) {
    const long key = std::lround(id.values[i]);
    g.type[key] = type ? int(std::lround(type->values[i])) : 1;
    if (g.type[key] == kGluedType) continue;
    Eigen::Vector3d r = raw.points[i] + frame.shift;
    if (image)
      r += Eigen::Vector3d(image->values[3 * i] * s.length_m, image->values[3 * i + 1] * s.width_m,
                           0.0);
    g.unwrapped[key] = r;
    g.wrapped.points.emplace_back(wrap(r.x(), s.length_m), wrap(r.y(), s.width_m), r.z());
    ids.values.push_back(double(key)), radii.values.push_back(radius.values[i]),
        masses.values.push_back(mass.values[i]);
    for (int c = 0; c < 3; ++c)
      vel.values.push_back(v.values[3 * i + c]), spin.values.push_back(omega.values[3 * i + c]);
  }
  g.wrapped.arrays = {ids, radii, masses, vel, spin};
  return g;
}

double nearest_image(double d, double length) {
  return d - length * std::round(d / length);
}

// Contacts as branch segments (coarse_graining/particles.hpp: force on `from`; a boundary branch
// ends at the contact point).
io::Segments read_contacts(const Scene& s, const fs::path& pairs, const fs::path& walls,
                           const Grains& g, const SnapshotFrame& frame) {
  io::Segments out;
  io::VtkArray force{"force_N", 3, {}}, boundary{"boundary", 1, {}};
  const auto add = [&](const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                       const Eigen::Vector3d& f, bool on_boundary) {
    out.from.push_back(from), out.to.push_back(to);
    for (int c = 0; c < 3; ++c) force.values.push_back(f[c]);
    boundary.values.push_back(on_boundary ? 1.0 : 0.0);
  };
  const auto glued = [&](double id) {
    const auto it = g.type.find(std::lround(id));
    return it != g.type.end() && it->second == kGluedType;
  };
  for (const auto& r : numeric_lines(pairs)) {
    if (r.size() != kContactColumns) continue;  // the dump's header lines
    const Eigen::Vector3d x1(r[0], r[1], r[2]), x2(r[3], r[4], r[5]), f(r[9], r[10], r[11]),
        c(r[12], r[13], r[14]);
    const bool g1 = glued(r[6]), g2 = glued(r[7]);
    if (g1 && g2) continue;
    if (g1 ||
        g2) {  // a glued sphere is the wall: the branch runs from the grain to the contact point
      add((g1 ? x2 : x1) + frame.shift, c + frame.shift, g1 ? Eigen::Vector3d(-f) : f, true);
      continue;
    }
    const Eigen::Vector3d d(nearest_image(x2.x() - x1.x(), s.length_m),
                            nearest_image(x2.y() - x1.y(), s.width_m), x2.z() - x1.z());
    add(x1 + frame.shift, x1 + d + frame.shift, f, false);
  }
  for (const auto& r : numeric_lines(walls))
    if (r.size() == kContactColumns)
      add(Eigen::Vector3d(r[3], r[4], r[5]) + frame.shift,
          Eigen::Vector3d(r[0], r[1], r[2]) + frame.shift, Eigen::Vector3d(r[9], r[10], r[11]),
          true);
  out.arrays = {force, boundary};
  return out;
}

// Where each grain was at the previous snapshot and how far it had moved since the start of shear.
// Displacements are summed snapshot to snapshot over the nearest periodic image: LIGGGHTS's
// positions unwrap with its image flags, but YADE wraps a grain that crosses the cell (its smoke
// runs had grains 24 mm "behind" the others), and the increment's nearest image is right for both
// while no grain moves half a cell between snapshots (the wall moves vtk_every_mm: 0.5 mm against
// cells of 24 mm and more).
struct Track {
  std::unordered_map<long, std::pair<Eigen::Vector3d, Eigen::Vector3d>>
      at;  // id -> (position, displacement)
};

Track track_of(const io::PointCloud& cloud) {
  Track t;
  const auto& ids = *cloud.find("id");
  const io::VtkArray* d = cloud.find("displacement_m");
  for (std::size_t i = 0; i < cloud.points.size(); ++i)
    t.at[std::lround(ids.values[i])] = {
        cloud.points[i],
        d ? Eigen::Vector3d(d->values[3 * i], d->values[3 * i + 1], d->values[3 * i + 2])
          : Eigen::Vector3d(Eigen::Vector3d::Zero())};
  return t;
}

io::VtkArray displacement(const Scene& s, const Grains& now, Track& track, const fs::path& file) {
  io::VtkArray d{"displacement_m", 3, {}};
  Track next;
  for (const auto& [id, r] : now.unwrapped) {
    const auto it = track.at.find(id);
    if (it == track.at.end())
      throw std::runtime_error(
          fmt::format("{}: grain {} is not in the previous snapshot", file.string(), id));
    const Eigen::Vector3d step = r - it->second.first;
    const Eigen::Vector3d moved =
        it->second.second + Eigen::Vector3d(nearest_image(step.x(), s.length_m),
                                            nearest_image(step.y(), s.width_m), step.z());
    next.at[id] = {r, moved};
  }
  for (double id : now.wrapped.find("id")->values) {
    const Eigen::Vector3d& moved = next.at.at(std::lround(id)).second;
    for (int c = 0; c < 3; ++c) d.values.push_back(moved[c]);
  }
  track = std::move(next);
  return d;
}

std::string stem_file(const char* stem, long step) {
  return fmt::format("{}_{}.vtp", stem, step);
}

}  // namespace

int write_snapshot_series(const Scene& s, const fs::path& dumps, const DumpNames& names,
                          const SnapshotFrame& frame, const fs::path& vtk_dir) {
  const auto raw = raw_files(dumps, names);
  std::optional<Track> track;  // from the first dump on: a snapshot converted earlier is read back
  for (const auto& [step, files] : raw) {
    if (files.particles.empty()) continue;
    const fs::path vtp = vtk_dir / stem_file("particles", step);
    if (fs::exists(vtp)) {
      track = track_of(io::read_points(vtp));
      continue;
    }
    Grains g = read_grains(s, files.particles, frame);
    if (!track) track = track_of(g.wrapped);  // the first dump: displacement zero
    g.wrapped.arrays.push_back(displacement(s, g, *track, files.particles));
    io::write_segments(vtk_dir / stem_file("contacts", step),
                       read_contacts(s, dumps / fmt::format("pairs_{}.txt", step),
                                     dumps / fmt::format("wall_contacts_{}.txt", step), g, frame));
    if (!files.walls.empty())
      io::convert_to_polydata(files.walls, vtk_dir / stem_file("walls", step), frame.shift);
    io::write_points(vtp, g.wrapped);  // last: it marks the snapshot done
  }
  std::vector<io::TimedFile> series[3];
  const char* stems[] = {"particles", "contacts", "walls"};
  const std::regex done("particles_([0-9]+)\\.vtp");
  std::map<long, bool> steps;
  for (const auto& e : fs::directory_iterator(vtk_dir)) {
    std::smatch m;
    const std::string name = e.path().filename().string();
    if (std::regex_match(name, m, done)) steps[std::stol(m[1])] = true;
  }
  for (const auto& [step, _] : steps)
    for (int k = 0; k < 3; ++k)
      if (fs::exists(vtk_dir / stem_file(stems[k], step)))
        series[k].push_back({double(step - frame.step0) * frame.dt, stem_file(stems[k], step)});
  for (int k = 0; k < 3; ++k)
    io::write_collection(vtk_dir / fmt::format("{}.pvd", stems[k]), series[k]);
  if (!steps.empty() && fs::exists(dumps)) fs::remove_all(dumps);  // every snapshot is in vtk/ now
  return int(steps.size());
}

}  // namespace iwb::dem
