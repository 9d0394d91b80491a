#pragma once
// One gnuplot figure written beside its data and script: NAME.csv, NAME.gp, NAME.svg, NAME.png.
// Shared by the HTML report, the stability map and the benchmarks, so that every figure of the
// workbench is drawn the same way and can be redrawn from its directory with `gnuplot NAME.gp`.
#include <filesystem>
#include <string>
#include <vector>

#include "io/csv_table.hpp"

namespace iwb::comparison {

struct Figure {
  std::string name, title, xlabel, ylabel;
  io::CsvTable data;                // column 0 is x, the others are series
  std::vector<std::string> titles;  // one per series
  std::string extra;                // gnuplot commands before the plot (e.g. the band marker)
  // The plot command, for figures that are not lines of each series against column 0 (scatter
  // maps, log-log fronts); it reads NAME.csv. Empty: one line per series.
  std::string plot;
};

// A curve with its own abscissae: the curves of one figure need not share x (stress paths, runs of
// different lengths).
struct PlotCurve {
  std::string title;
  std::vector<double> x, y;
  std::string style = "with lines lw 2";  // gnuplot's "with ..." and its line style
};

// The style of the reference curve a figure draws last (the DEM): thick and black.
inline const char* kReferenceStyle = "with lines lw 3 lc rgb '#000000'";

// A figure of such curves: its CSV holds an x and a y column per curve (shorter curves padded with
// nan, which the plot skips), each drawn in its style.
Figure curves_figure(const std::string& name, const std::string& title, const std::string& xlabel,
                     const std::string& ylabel, const std::vector<PlotCurve>& curves);

// A single-quoted gnuplot string.
std::string gnuplot_string(const std::string& s);

// Writes NAME.csv, NAME.gp, runs gnuplot for NAME.svg and NAME.png; returns the SVG's path.
// Throws std::runtime_error with gnuplot's output if gnuplot fails.
std::filesystem::path draw(const Figure& f, const std::filesystem::path& dir);

}  // namespace iwb::comparison
