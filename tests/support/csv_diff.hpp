#pragma once
// Gold-file comparison after MOOSE's CSVDiff (STYLE.md): two CSV texts compared column by column,
// same header, same row count, every compared column within its absolute OR relative tolerance.
// The first failure names the column, the row, both values and the tolerance, so that a failing
// gold test says what moved without anyone opening the files.
#include <toml++/toml.h>

#include <filesystem>
#include <map>
#include <string>

namespace iwb::test {

// A cell passes when |expected - actual| <= abs or <= rel * max(|expected|, |actual|): abs covers
// values that cross zero (tau in a cycle), rel the rest. A skipped column is only required to be
// present in both headers.
struct ColumnTolerance {
  double abs = 0.0;
  double rel = 0.0;
  bool skip = false;
};

struct CsvTolerances {
  ColumnTolerance fallback;  // every column not named in `columns`
  std::map<std::string, ColumnTolerance> columns;
  const ColumnTolerance& of(const std::string& column) const;
};

// The first difference; `row` counts data rows from 1 (0: the header or the row count).
struct CsvDiff {
  bool failed = false;
  std::string column;
  std::size_t row = 0;
  std::string message;
};

CsvDiff diff_csv(const std::string& expected, const std::string& actual, const CsvTolerances& tol);
// Files; a missing or unreadable one is a failure naming it, not an exception.
CsvDiff diff_csv_files(const std::filesystem::path& expected, const std::filesystem::path& actual,
                       const CsvTolerances& tol);

// The table `[tolerance]` of a TOML file: `abs`, `rel` (the fallback), `skip = [columns]` and
// `[tolerance.columns] NAME = { abs = .., rel = .. }`. InputError naming `source` and the key.
CsvTolerances read_tolerances(const toml::table& root, const std::string& source);

}  // namespace iwb::test
