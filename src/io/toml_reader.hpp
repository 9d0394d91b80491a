#pragma once
// Reading a TOML table with every error naming the file, the dotted key and the value, and with
// unknown keys refused (a typo must not silently fall back to a default).
#include <toml++/toml.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/range.hpp"

namespace iwb::io {

class TableReader {
 public:
  TableReader(const toml::table& table, std::string file, std::string prefix = "");

  double number(const std::string& key);
  std::optional<double> optional_number(const std::string& key);
  // Every number is finite (TOML's inf and nan are refused); these also check a range.
  double number_in(const std::string& key, const Range& range);
  std::optional<double> optional_number_in(const std::string& key, const Range& range);
  // A number that must be > 0 (and at most `upper`).
  double positive(const std::string& key, double upper = kInf);
  std::optional<double> optional_positive(const std::string& key, double upper = kInf);
  int count(const std::string& key);  // integer >= 1
  std::optional<int> optional_count(const std::string& key);
  std::string text(const std::string& key);
  std::optional<std::string> optional_text(const std::string& key);
  std::optional<bool> optional_flag(const std::string& key);  // true or false
  std::optional<TableReader> table(const std::string& key);
  TableReader required_table(const std::string& key);
  std::vector<TableReader> array_of_tables(const std::string& key);
  bool has(const std::string& key) const;
  // The node itself, for values of more than one type (e.g. a path or an inline table).
  const toml::node* node(const std::string& key);

  // InputError for the first key that was never read.
  void finish() const;
  bool was_read(const std::string& key) const { return read_.count(key) > 0; }

  // "file: key 'path.increments'" for messages.
  std::string where(const std::string& key) const;
  std::string where() const;
  const std::string& file() const { return file_; }
  // Exactly one of `keys` must be present; returns it.
  std::string one_of(const std::vector<std::string>& keys);

 private:
  // "file: key 'x' is missing (what)", suggesting unread keys that look like a misspelling of it:
  // a typo shows up as a missing key and an unknown one, and the message should say both.
  std::string missing(const std::string& key, const std::string& what) const;

  const toml::table* table_;
  std::string file_;
  std::string prefix_;
  std::set<std::string> read_;
};

std::string describe(const toml::node& node);  // the value as the user wrote it, for messages

// A relative tolerance under `key` of a [requirements] table: absent -> nullopt; the string
// "not needed" -> an empty inner optional; a number in (0, 1] (0.05 = 5 %) -> that number.
// Anything else is an InputError naming the file, the key and the value.
std::optional<std::optional<double>> read_tolerance(TableReader& table, const std::string& key);

// Parses `path`; InputError naming the file and the line on syntax errors, and the file and what
// is there when it is not a regular file (missing, a directory, a named pipe).
toml::table parse_toml_file(const std::string& path);
toml::table parse_toml_text(const std::string& text, const std::string& name);

}  // namespace iwb::io
