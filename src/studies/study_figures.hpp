#pragma once
// The figures of a study (the seed's figures redrawn from the study's runs) and its page, in the
// style of the validation report (comparison/presentation/html.hpp).
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "studies/clay_cases.hpp"
#include "studies/clay_claims.hpp"

namespace iwb::studies {

enum class Axis { kGamma, kEpsN, kTau, kSigmaN };

// One figure: curves of named cases, `y` against `x`.
struct FigureSpec {
  std::string name, title;
  Axis x, y;
  std::vector<std::pair<std::string, std::string>> curves;  // case, title
  double gamma_limit = 1.0;  // rows beyond this shear strain are left out
};

struct StudyFigure {
  std::filesystem::path svg;  // OUT/figures/NAME.svg, beside NAME.png, .csv, .gp
  std::string caption;
};

// Draws every figure into OUT/figures/ (staged: all or none).
std::vector<StudyFigure> draw_figures(const std::vector<FigureSpec>& specs,
                                      const std::map<std::string, ClayCurve>& curves,
                                      const std::filesystem::path& out);

// The HTML page: `setting`, the claims table first, then the figures inline.
std::string study_page(const std::string& title, const std::string& command,
                       const std::string& setting, const std::vector<ClayClaim>& claims,
                       const std::vector<StudyFigure>& figures, const std::filesystem::path& out);

}  // namespace iwb::studies
