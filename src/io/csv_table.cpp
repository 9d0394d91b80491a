#include "io/csv_table.hpp"

#include <fmt/core.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"

namespace iwb::io {

namespace {
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}
}  // namespace

int CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return int(i);
  return -1;
}

std::vector<double> CsvTable::values(const std::string& name, const std::string& source) const {
  const int c = column(name);
  if (c < 0) throw InputError(fmt::format("{}: no column '{}'", source, name));
  std::vector<double> out;
  out.reserve(rows.size());
  for (const auto& r : rows) out.push_back(r[c]);
  return out;
}

std::string CsvTable::to_csv(int digits) const {
  std::string s;
  for (std::size_t i = 0; i < columns.size(); ++i) s += (i ? "," : "") + columns[i];
  s += "\n";
  for (const auto& r : rows) {
    for (std::size_t i = 0; i < r.size(); ++i)
      s += fmt::format("{}{:.{}g}", i ? "," : "", r[i], digits);
    s += "\n";
  }
  return s;
}

CsvTable read_csv_table(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot read", path.string()));
  CsvTable t;
  std::string line;
  if (!std::getline(in, line) || line.empty())
    throw InputError(fmt::format("{}:1: missing header line", path.string()));
  t.columns = split(line);
  for (int n = 2; std::getline(in, line); ++n) {
    if (line.empty()) continue;
    const auto cells = split(line);
    if (cells.size() != t.columns.size())
      throw InputError(fmt::format("{}:{}: {} fields, the header has {} (truncated row?)",
                                   path.string(), n, cells.size(), t.columns.size()));
    std::vector<double> row;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      std::size_t used = 0;
      double v = NAN;
      try {
        v = std::stod(cells[i], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != cells[i].size() || !std::isfinite(v))
        throw InputError(fmt::format("{}:{}: column '{}' = '{}' is not a finite number",
                                     path.string(), n, t.columns[i], cells[i]));
      row.push_back(v);
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace iwb::io
