#pragma once
// `iwb report`: one self-contained HTML file (opens offline: figures are inline SVG, no scripts,
// no external resources) from one or more comparison directories: tau, u_n and sigma_n against
// u_x for the DEM and each continuum variant, the DEM's velocity profile with its band, the
// metrics, the DEM's derived quantities and the provenance. Figures are drawn by gnuplot and also
// written as SVG and PNG beside the HTML, each with the CSV of its data and its gnuplot script.
#include <filesystem>
#include <vector>

namespace iwb::comparison {

// `paths` are comparison directories, or sets of `iwb compare --runs` (their directory, or its
// files as `OUT/*` passes them): a set's hypothesis verdicts come first, as tables.
// Returns the figures written (paths of the SVG files).
std::vector<std::filesystem::path> write_report(const std::vector<std::filesystem::path>& paths,
                                                const std::filesystem::path& html);

}  // namespace iwb::comparison
