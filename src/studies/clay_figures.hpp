#pragma once
// The clay study's figures (the seed's Figures 6.3-6.7 and 6.11, redrawn from the study's runs)
// and its page, in the style of the validation report (comparison/html.hpp).
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "studies/clay_cases.hpp"
#include "studies/clay_claims.hpp"

namespace iwb::studies {

struct StudyFigure {
  std::filesystem::path svg;  // OUT/figures/NAME.svg, beside NAME.png, .csv, .gp
  std::string caption;
};

// Draws every figure into OUT/figures/ (staged: all or none).
std::vector<StudyFigure> draw_clay_figures(const std::map<std::string, ClayCurve>& curves,
                                           const std::filesystem::path& out);

// The HTML page: the claims table first, then the figures inline.
std::string clay_page(const std::vector<ClayClaim>& claims, const std::vector<StudyFigure>& figures,
                      const std::filesystem::path& out);

}  // namespace iwb::studies
