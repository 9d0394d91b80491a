#pragma once
// The jobs of a sweep: the cartesian product of its engines and axes, each job's scene being the
// base scene with the [set] keys and the job's axis values set. Every job's scene is validated
// (parse_scene) when the jobs are expanded, so a bad value refuses the whole sweep before anything
// runs.
#include <string>
#include <vector>

#include "campaign/sweep_file.hpp"

namespace iwb::campaign {

struct Job {
  std::string name;  // readable and unique: rn0.5_d2_cnl_s1 (engine first when there are several)
  std::string engine;
  std::vector<Setting> values;  // this job's axis values, in axis order
  std::string scene_text;       // what the job runs; its sha256 decides reuse
};

// InputError naming the sweep file, the job, its values and the scene's complaint when any job's
// scene is invalid, or when two jobs would get the same name.
std::vector<Job> expand_jobs(const SweepSpec& spec);

// Where a job's scene and run live inside the campaign directory.
std::string scene_path(const Job& job);  // scenes/<name>.toml
std::string run_path(const Job& job);    // runs/<name>

// "wall.height_d50 = 0.5, seed = 2"
std::string describe(const std::vector<Setting>& settings);

}  // namespace iwb::campaign
