#include "walls/measured_surface.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"
#include "common/input_file.hpp"
#include "walls/gauge_windows.hpp"

namespace iwb::walls {

namespace {

constexpr double kMetresPerMillimetre = 1e-3;
constexpr double kMinSamplesPerD50 = 4.0;    // R_max over d50 needs a few samples in every window
constexpr double kFineSamplesPerD50 = 10.0;  // below, a warning: peaks between samples are cut

struct Row {
  int line;
  std::vector<double> values;
};

// The file's data rows (comments after '#' and blank lines dropped), each a list of finite numbers.
std::vector<Row> read_rows(const std::string& path, bool header) {
  if (const auto why = unreadable_input_file(path); !why.empty())
    throw InputError(fmt::format("{}: {}", path, why));
  // a mesh has no height per (x, y) to read until it is sampled onto a grid, and one with holes
  // has none to sample: profilometers export grids, which is what is read
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension == ".stl")
    throw InputError(fmt::format(
        "{}: an STL mesh; a measured surface is read as a line profile (x_mm,z_mm) or a height "
        "map (CSV grid): sample the mesh onto a grid first (data/walls/README.md)",
        path));
  std::ifstream in(path);
  std::vector<Row> rows;
  std::string text;
  bool header_seen = !header;
  for (int line = 1; std::getline(in, text); ++line) {
    if (const auto c = text.find('#'); c != std::string::npos) text.erase(c);
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (!header_seen) {
      std::string compact;
      for (char ch : text)
        if (ch != ' ' && ch != '\t' && ch != '\r') compact += ch;
      if (compact != "x_mm,z_mm")
        throw InputError(
            fmt::format("{}:{}: the header is \"{}\"; a line profile starts with \"x_mm,z_mm\"",
                        path, line, compact));
      header_seen = true;
      continue;
    }
    Row r{line, {}};
    std::stringstream fields(text);
    std::string field;
    for (int column = 1; std::getline(fields, field, ','); ++column) {
      char* end = nullptr;
      const double v = std::strtod(field.c_str(), &end);
      const bool number =
          end != field.c_str() && std::string(end).find_first_not_of(" \t\r") == std::string::npos;
      if (!number || !std::isfinite(v))
        throw InputError(
            fmt::format("{}:{}: column {} is \"{}\", not a finite number (heights in mm)", path,
                        line, column, field));
      r.values.push_back(v);
    }
    rows.push_back(std::move(r));
  }
  if (rows.empty()) throw InputError(fmt::format("{}: no data rows", path));
  return rows;
}

// A line profile resampled at its mean spacing over [offset, offset + length], the x of the last
// sample one spacing before the window's far edge.
std::vector<double> line_window(const std::vector<Row>& rows, const MeasuredSurfaceSpec& spec,
                                double length, double& spacing) {
  std::vector<double> x, z;
  for (const auto& r : rows) {
    if (r.values.size() != 2)
      throw InputError(fmt::format("{}:{}: {} columns; a line profile has two (x_mm, z_mm)",
                                   spec.path, r.line, r.values.size()));
    if (!x.empty() && !(r.values[0] * kMetresPerMillimetre > x.back()))
      throw InputError(fmt::format("{}:{}: x_mm = {:g} does not increase (the row before has {:g})",
                                   spec.path, r.line, r.values[0],
                                   x.back() / kMetresPerMillimetre));
    x.push_back(r.values[0] * kMetresPerMillimetre),
        z.push_back(r.values[1] * kMetresPerMillimetre * spec.scale);
  }
  if (x.size() < 2)
    throw InputError(fmt::format("{}: one row; a line profile needs two or more", spec.path));
  const double start = x.front() + spec.offset_m;
  if (start + length > x.back() * (1 + 1e-12))
    throw InputError(fmt::format(
        "{}: the profile spans {:g} mm; from offset_mm = {:g} the box needs {:g} mm of it",
        spec.path, (x.back() - x.front()) / kMetresPerMillimetre,
        spec.offset_m / kMetresPerMillimetre, length / kMetresPerMillimetre));
  spacing = (x.back() - x.front()) / double(x.size() - 1);
  const int n = std::max(2, int(std::lround(length / spacing)));
  spacing = length / n;
  std::vector<double> out(n + 1);
  std::size_t k = 0;
  for (int i = 0; i <= n; ++i) {
    const double xi = start + i * spacing;
    while (k + 2 < x.size() && x[k + 1] < xi) ++k;
    const double t = std::clamp((xi - x[k]) / (x[k + 1] - x[k]), 0.0, 1.0);
    out[i] = z[k] + t * (z[k + 1] - z[k]);
  }
  return out;  // n + 1 samples: the far edge is kept for detrending
}

// The largest R_max over windows of d50 within one row that do not wrap.
double window_r_max(const std::vector<double>& z, double spacing, double d50) {
  const int w = std::max(1, int(std::lround(d50 / spacing)));
  GaugeRanges r;
  add_gauge_ranges(z, w, std::max(0, int(z.size()) - w), r);
  return r.largest;
}

// The samples z_0 .. z_n (spacing h) averaged over m + 1 cells centred on k n/m samples (the two
// end cells half as wide), so that the ends stay the ends.
std::vector<double> averaged(const std::vector<double>& z, int m) {
  const int n = int(z.size()) - 1;
  std::vector<double> out(m + 1, 0.0);
  for (int k = 0; k <= m; ++k) {
    const double centre = double(k) * n / m, half = 0.5 * double(n) / m;
    double sum = 0.0;
    int count = 0;
    for (int i = std::max(0, int(std::ceil(centre - half)));
         i <= std::min(n, int(std::floor(centre + half))); ++i)
      sum += z[i], ++count;
    out[k] = sum / count;
  }
  return out;
}

// Rows (and, for a map, columns) averaged down to cells of about `resample` where finer.
void resample(std::vector<std::vector<double>>& grid, double& spacing, double resample) {
  const int n = int(grid.front().size()) - 1;
  if (!(resample > spacing)) return;
  const int m = std::max(2, int(std::lround(n * spacing / resample)));
  for (auto& row : grid) row = averaged(row, m);
  if (grid.size() > 2) {
    const int rows = int(grid.size()) - 1,
              rows_after = std::max(2, int(std::lround(rows * spacing / resample)));
    std::vector<std::vector<double>> out(rows_after + 1, std::vector<double>(m + 1));
    for (int i = 0; i <= m; ++i) {
      std::vector<double> column;
      for (const auto& row : grid) column.push_back(row[i]);
      const auto c = averaged(column, rows_after);
      for (int j = 0; j <= rows_after; ++j) out[j][i] = c[j];
    }
    grid = std::move(out);
  }
  spacing = spacing * n / m;
}

// Subtracts the line through a row's end values: the row then starts and ends at the same height.
void detrend(std::vector<double>& z) {
  const double rise = z.back() - z.front();
  for (std::size_t i = 0; i < z.size(); ++i) z[i] -= rise * double(i) / double(z.size() - 1);
}

void check_resolution(const MeasuredSurfaceSpec& spec, double spacing, double d50,
                      std::vector<std::string>& warnings) {
  if (spacing > d50 / kMinSamplesPerD50)
    throw InputError(fmt::format(
        "{}: samples {:g} mm apart, coarser than d50/{:g} = {:g} mm: R_max over d50 cannot be "
        "measured",
        spec.path, spacing / kMetresPerMillimetre, kMinSamplesPerD50,
        d50 / kMinSamplesPerD50 / kMetresPerMillimetre));
  if (spacing > d50 / kFineSamplesPerD50)
    warnings.push_back(fmt::format(
        "{}: samples {:g} mm apart, coarser than d50/{:g}: peaks between samples are cut "
        "and R_n is underestimated",
        spec.path, spacing / kMetresPerMillimetre, kFineSamplesPerD50));
}

}  // namespace

MeasuredSurface measured_surface(const MeasuredSurfaceSpec& spec, double length, double width,
                                 double d50) {
  const auto rows = read_rows(spec.path, spec.layout == MeasuredLayout::kLine);
  std::vector<std::vector<double>> grid;  // rows along x, n + 1 samples each, m + 1 rows for a map
  double spacing = spec.spacing_m;
  if (spec.layout == MeasuredLayout::kLine) {
    grid.push_back(line_window(rows, spec, length, spacing));
  } else {
    const std::size_t columns = rows.front().values.size();
    for (const auto& r : rows)
      if (r.values.size() != columns)
        throw InputError(
            fmt::format("{}:{}: {} heights; the first row has {} (a map is a full grid)", spec.path,
                        r.line, r.values.size(), columns));
    const int n = int(std::lround(length / spacing)), m = int(std::lround(width / spacing));
    const int first = int(std::lround(spec.offset_m / spacing));
    if (first + n + 1 > int(columns) || m + 1 > int(rows.size()))
      throw InputError(
          fmt::format("{}: a map of {} x {} heights at {:g} mm spans {:g} x {:g} mm; the box (from "
                      "offset_mm = {:g}) needs {} x {} heights",
                      spec.path, columns, rows.size(), spacing / kMetresPerMillimetre,
                      double(columns - 1) * spacing / kMetresPerMillimetre,
                      double(rows.size() - 1) * spacing / kMetresPerMillimetre,
                      spec.offset_m / kMetresPerMillimetre, first + n + 1, m + 1));
    for (int j = 0; j <= m; ++j) {
      std::vector<double> z(rows[j].values.begin() + first, rows[j].values.begin() + first + n + 1);
      for (double& v : z) v *= kMetresPerMillimetre * spec.scale;
      grid.push_back(std::move(z));
    }
  }
  MeasuredSurface out{HeightMap(1, 1, 1.0, 1.0, {0.0}), 0.0, {}};
  check_resolution(spec, spacing, d50, out.warnings);
  resample(grid, spacing, spec.resample_m);  // before R_max: the untiled window as the wall will be
  for (const auto& row : grid)
    out.window_r_max_m = std::max(out.window_r_max_m, window_r_max(row, spacing, d50));
  for (auto& row : grid) detrend(row);
  if (grid.size() > 1)  // the columns too: the map tiles in y
    for (std::size_t i = 0; i < grid.front().size(); ++i) {
      std::vector<double> column;
      for (const auto& row : grid) column.push_back(row[i]);
      detrend(column);
      for (std::size_t j = 0; j < grid.size(); ++j) grid[j][i] = column[j];
    }
  // A line is extruded along y in rows about d50 apart: no triangle may span the periodic width.
  const int nx = int(grid.front().size()) - 1;
  const int ny = grid.size() > 1 ? int(grid.size()) - 1 : std::max(2, int(std::ceil(width / d50)));
  std::vector<double> z;
  double lowest = INFINITY;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      z.push_back(grid[grid.size() > 1 ? j : 0][i]), lowest = std::min(lowest, z.back());
  for (double& v : z) v -= lowest;
  out.map = HeightMap(nx, ny, length, width, std::move(z));
  return out;
}

}  // namespace iwb::walls
