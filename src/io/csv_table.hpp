#pragma once
// A numeric CSV table: header line with unit-carrying column names, then rows of numbers.
// Reading validates what the contract files promise (header, column count, finite numbers) and
// names the file and line of the first violation.
#include <filesystem>
#include <string>
#include <vector>

namespace iwb::io {

struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  int column(const std::string& name) const;  // -1 if absent
  // Values of a named column; InputError naming `source` if absent.
  std::vector<double> values(const std::string& name, const std::string& source = "table") const;
  std::string to_csv(int significant_digits = 10) const;
};

CsvTable read_csv_table(const std::filesystem::path& path);

}  // namespace iwb::io
