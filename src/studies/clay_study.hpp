#pragma once
// `iwb run --study clay`: the seed's section 6.4 comparisons of the clay interface models, which the
// granular DEM cannot check, reproduced as element tests with figures, a table of the seed's
// claims against what the models do, and one HTML page (README.md in this folder).
#include <atomic>
#include <filesystem>
#include <string>

namespace iwb::studies {

struct ClayStudyOptions {
  std::filesystem::path out = "runs/clay";
  bool force = false;  // replace earlier run directories in `out`
  std::string command_line;
  const std::atomic<bool>* interrupt = nullptr;
};

// Runs every case into OUT/<case>/ (element run directories), then writes OUT/study.json (the
// claims with their numbers), OUT/study.md and OUT/clay.html with its figures in OUT/figures/.
// Exit code: 0 when every case completed, 1 otherwise (the table says which).
int run_clay_study(const ClayStudyOptions& options);

}  // namespace iwb::studies
