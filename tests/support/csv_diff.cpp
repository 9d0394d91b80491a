#include "support/csv_diff.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <vector>

#include "common/errors.hpp"
#include "io/toml_reader.hpp"

namespace iwb::test {

namespace {

using Row = std::vector<std::string>;

// Cells kept as text: an empty cell (hp1d's sigma_p) must equal an empty cell, not fail to parse.
Row split(const std::string& line) {
  Row out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

std::vector<Row> rows_of(const std::string& text) {
  std::vector<Row> rows;
  std::stringstream ss(text);
  std::string line;
  while (std::getline(ss, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty()) rows.push_back(split(line));
  }
  return rows;
}

bool parse(const std::string& cell, double& v) {
  char* end = nullptr;
  v = std::strtod(cell.c_str(), &end);
  return !cell.empty() && end == cell.c_str() + cell.size();
}

bool within(double a, double b, const ColumnTolerance& t) {
  const double d = std::fabs(a - b);
  return d <= t.abs || d <= t.rel * std::max(std::fabs(a), std::fabs(b));
}

CsvDiff failure(std::string column, std::size_t row, std::string message) {
  return {true, std::move(column), row, std::move(message)};
}

std::string joined(const Row& r) {
  std::string s;
  for (const auto& c : r) s += (s.empty() ? "" : ",") + c;
  return s;
}

// The cell in data row `row` (from 1) of `column`; empty result when it passes.
std::optional<CsvDiff> diff_cell(const std::string& column, std::size_t row,
                                 const std::string& want, const std::string& got,
                                 const ColumnTolerance& t) {
  if (t.skip || want == got) return std::nullopt;
  double a = NAN, b = NAN;
  const std::string where = fmt::format("column '{}', row {} (line {})", column, row, row + 1);
  if (!parse(want, a) || !parse(got, b))
    return failure(column, row, fmt::format("{}: expected '{}', got '{}'", where, want, got));
  if (within(a, b, t)) return std::nullopt;
  return failure(
      column, row,
      fmt::format("{}: expected {}, got {} (difference {:.3g}, relative {:.3g}; "
                  "tolerance abs {:g} or rel {:g})",
                  where, want, got, std::fabs(a - b),
                  std::fabs(a - b) / std::max(std::fabs(a), std::fabs(b)), t.abs, t.rel));
}

}  // namespace

const ColumnTolerance& CsvTolerances::of(const std::string& column) const {
  const auto it = columns.find(column);
  return it == columns.end() ? fallback : it->second;
}

namespace {

// Same header, same row count, every row as wide as the header; empty result when so.
std::optional<CsvDiff> diff_shape(const std::vector<Row>& want, const std::vector<Row>& got) {
  if (want.empty() || got.empty()) return failure("", 0, "no header line");
  if (want.front() != got.front())
    return failure("", 0,
                   fmt::format("headers differ: expected '{}', got '{}'", joined(want.front()),
                               joined(got.front())));
  if (want.size() != got.size())
    return failure(
        "", 0,
        fmt::format("row counts differ: expected {}, got {}", want.size() - 1, got.size() - 1));
  const std::size_t width = want.front().size();
  for (std::size_t r = 1; r < want.size(); ++r)
    if (want[r].size() != width || got[r].size() != width)
      return failure("", r,
                     fmt::format("row {} (line {}): {} and {} fields, the header has {}", r, r + 1,
                                 want[r].size(), got[r].size(), width));
  return std::nullopt;
}

}  // namespace

// Column by column, in the header's order (displacements and stresses before the diagnostics
// computed from them), so that the failure reported is the earliest row of the most primary
// response that moved, not a consequence of it.
CsvDiff diff_csv(const std::string& expected, const std::string& actual, const CsvTolerances& tol) {
  const auto want = rows_of(expected);
  const auto got = rows_of(actual);
  if (auto d = diff_shape(want, got)) return *d;
  const Row& header = want.front();
  for (std::size_t c = 0; c < header.size(); ++c)
    for (std::size_t r = 1; r < want.size(); ++r)
      if (auto d = diff_cell(header[c], r, want[r][c], got[r][c], tol.of(header[c]))) return *d;
  return {};
}

CsvDiff diff_csv_files(const std::filesystem::path& expected, const std::filesystem::path& actual,
                       const CsvTolerances& tol) {
  std::string text[2];
  const std::filesystem::path* files[2] = {&expected, &actual};
  for (int i = 0; i < 2; ++i) {
    std::ifstream in(*files[i]);
    if (!in) return failure("", 0, fmt::format("{}: cannot read", files[i]->string()));
    text[i].assign(std::istreambuf_iterator<char>(in), {});
  }
  auto d = diff_csv(text[0], text[1], tol);
  if (d.failed)
    d.message = fmt::format("{} against {}: {}", actual.string(), expected.string(), d.message);
  return d;
}

namespace {

ColumnTolerance read_one(io::TableReader t) {
  ColumnTolerance out;
  out.abs = t.optional_number("abs").value_or(0.0);
  out.rel = t.optional_number("rel").value_or(0.0);
  if (!(out.abs >= 0.0) || !(out.rel >= 0.0))
    throw InputError(
        fmt::format("{}: abs = {:g}, rel = {:g}; allowed >= 0", t.where(), out.abs, out.rel));
  t.finish();
  return out;
}

std::vector<std::string> strings(const toml::node* node, const std::string& where) {
  std::vector<std::string> out;
  if (node == nullptr) return out;
  const auto* arr = node->as_array();
  if (arr == nullptr) throw InputError(where + " should be an array of column names");
  for (const auto& v : *arr) {
    if (!v.is_string()) throw InputError(where + " should be an array of column names");
    out.push_back(*v.value<std::string>());
  }
  return out;
}

}  // namespace

CsvTolerances read_tolerances(const toml::table& root, const std::string& source) {
  const auto* table = root["tolerance"].as_table();
  if (table == nullptr) throw InputError(source + ": table [tolerance] is missing");
  io::TableReader t(*table, source, "tolerance");
  CsvTolerances out;
  out.fallback.abs = t.optional_number("abs").value_or(0.0);
  out.fallback.rel = t.optional_number("rel").value_or(0.0);
  for (const auto& name : strings(t.node("skip"), t.where("skip"))) out.columns[name].skip = true;
  if (const auto* cols = (*table)["columns"].as_table()) {
    t.node("columns");
    for (const auto& [key, node] : *cols) {
      const std::string name(key.str());
      const auto* sub = node.as_table();
      if (sub == nullptr)
        throw InputError(t.where("columns." + name) + " should be { abs = .., rel = .. }");
      out.columns[name] = read_one(io::TableReader(*sub, source, "tolerance.columns." + name));
    }
  }
  t.finish();
  return out;
}

}  // namespace iwb::test
