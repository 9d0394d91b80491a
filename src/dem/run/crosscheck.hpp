#pragma once
// `iwb dem crosscheck`: one scene in several engines with K seeds each, side by side (issue 5):
// peak and residual friction, total dilation, dilation rate and band thickness with their seed
// scatter, whether the engines agree on each within it (issue 20), and each engine's wall-clock
// cost. Runs that are already complete in the output directory are reused,
// so an interrupted crosscheck continues where it stopped.
#include <atomic>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dem/engines/engine.hpp"
#include "dem/scene/scene.hpp"

namespace iwb::dem {

struct CrosscheckOptions {
  std::filesystem::path scene_file;
  std::vector<std::string> engines = {"liggghts", "yade"};
  int seeds = 3;
  int processes = 1;
  std::filesystem::path out;
  std::string command_line;
  const std::atomic<bool>* interrupt = nullptr;
  std::function<void(const std::string&)> progress;
};

// The scene text with its top-level `seed` set to `seed` (replaced, or added at the top).
std::string with_seed(const std::string& scene_text, int seed);

// One quantity over the seeds of one engine.
struct Scatter {
  double mean = 0.0, sd = 0.0;
  int n = 0;
};
Scatter scatter_of(const std::vector<double>& values);

// Whether two engines agree on a quantity within their seed scatter: the difference of the means
// against the standard error of that difference, sqrt(sd_a^2 / n_a + sd_b^2 / n_b) (Welch),
// agreeing within kAgreementStandardErrors of it. With fewer than two seeds in either engine there
// is no scatter to judge by: not judged.
inline constexpr double kAgreementStandardErrors = 2.0;
struct Agreement {
  double difference = 0.0, standard_error = 0.0;
  bool judged = false, agree = false;
};
Agreement agreement_of(const Scatter& a, const Scatter& b);

// Whether the complete run in dir can stand for scene_text (its parsed scene) in engine: the same
// scene, and the same mapping of it onto the engine (its numerics: timestep, contact law, servo),
// so that a corrected mapping makes older runs stale.
bool reusable_seed_run(const std::filesystem::path& dir, const Scene& scene,
                       const std::string& scene_text, const Engine& engine);

// Runs (or reuses) every engine x seed, writes crosscheck.json and crosscheck.md into out and
// returns the JSON.
nlohmann::json run_crosscheck(const CrosscheckOptions& options);

}  // namespace iwb::dem
