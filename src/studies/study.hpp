#pragma once
// A study of the continuum models (`iwb run --study NAME`): the seed's comparisons as element tests
// (cases), its claims put to their curves, its figures redrawn, one HTML page (README.md here).
// Everything that makes one study differ from another is data of a StudyDefinition.
#include <atomic>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "studies/clay_cases.hpp"
#include "studies/clay_claims.hpp"
#include "studies/study_figures.hpp"

namespace iwb::studies {

struct StudyOptions {
  std::filesystem::path out;
  bool force = false;  // replace earlier run directories in `out`
  std::string command_line;
  const std::atomic<bool>* interrupt = nullptr;
};

struct StudyDefinition {
  std::string name;     // `iwb run --study NAME`, and NAME.html
  std::string title;    // the page's and study.md's heading
  std::string setting;  // one paragraph: the parameter sets, starts and paths (plain text)
  std::vector<ClayCase> cases;
  std::function<std::vector<ClayClaim>(const std::map<std::string, ClayCurve>&)> claims;
  std::vector<FigureSpec> figures;
};

// Runs every case into OUT/<case>/ (element run directories), then writes OUT/study.json (the
// claims with their numbers), OUT/study.md and OUT/<name>.html with its figures in OUT/figures/.
// An earlier study in OUT is refused before anything is written unless `force`. Exit code: 0 when
// every case completed, 1 otherwise (the table says which).
int run_study(const StudyDefinition& study, const StudyOptions& options);

}  // namespace iwb::studies
