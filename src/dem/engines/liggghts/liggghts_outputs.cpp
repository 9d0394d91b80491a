#include "dem/engines/liggghts/liggghts_outputs.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "dem/engines/contract_outputs.hpp"
#include "dem/engines/liggghts/shear_checkpoint.hpp"
#include "dem/engines/snapshots.hpp"

namespace iwb::dem {

namespace fs = std::filesystem;

namespace {

// fix ave/spatial blocks: a header "step bins", then per bin: bin, z, count, vx, mean particle
// volume, mean s_zz*V, mean s_xz*V, number density (stress/atom is compression negative).
ProfileBlocks profile_blocks_of(const fs::path& raw, const Scene& s, const Numerics& n) {
  ProfileBlocks blocks;
  std::ifstream in(raw);
  long step = -1;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream is(line);
    std::vector<double> v;
    for (double x; is >> x;) v.push_back(x);
    if (v.size() == 2) {
      step = long(v[0]);
      continue;
    }
    if (v.size() < 8) continue;
    const double density = v[7];
    blocks[step].push_back({(v[1] - s.wall.mean_height_m()) / n.d50, v[2], v[3], density * v[4],
                            -density * v[5], -density * v[6]});
  }
  return blocks;
}

// The files of a resumed stage in the order written (shear_checkpoint.hpp): a block of a step an
// earlier file has too replaces it (the stopped attempt wrote it past its checkpoint, or half).
ProfileBlocks liggghts_profile_blocks(const std::vector<fs::path>& files, const Scene& s,
                                      const Numerics& n) {
  ProfileBlocks blocks;
  for (const auto& raw : files) {
    ProfileBlocks file = profile_blocks_of(raw, s, n);
    for (auto& [step, bins] : file) blocks[step] = std::move(bins);
  }
  return blocks;
}

}  // namespace

ContractTables assemble_liggghts_outputs(const StageContext& ctx, const nlohmann::json& facts,
                                         const Numerics& n) {
  const long step0 = facts.at("shear").at("step0").get<long>();
  const double z0 = facts.at("shear").at("z0_m").get<double>();
  const Scene& s = ctx.scene;
  ContractTables out;
  out.timeseries = timeseries_table(s, n, ctx.work_dir / "timeseries.raw", z0);
  out.profiles =
      profile_table(s, n, liggghts_profile_blocks(shear_profile_files(ctx.work_dir), s, n), step0);
  write_snapshot_series(s, ctx.work_dir / "dumps",
                        {"particles_([0-9]+)\\.vtk", "walls_([0-9]+)\\.vtk"},
                        {Eigen::Vector3d::Zero(), step0, n.dt}, ctx.run_dir / "vtk");
  out.facts = plate_facts(s, out.timeseries);
  out.facts["timestep_s"] = n.dt;
  out.facts["shear_start_step"] = step0;
  return out;
}

}  // namespace iwb::dem
