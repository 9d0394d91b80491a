#include "io/declared_keys.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/errors.hpp"

namespace iwb::io {

namespace {

std::string quoted_list(const std::vector<std::string>& words) {
  std::string s;
  for (const auto& w : words) s += fmt::format("{}\"{}\"", s.empty() ? "" : ", ", w);
  return s;
}

// The tighter of two ranges at each end.
Range intersect(const Range& a, const Range& b) {
  Range r = a;
  if (b.lower > r.lower || (b.lower == r.lower && b.lower_open))
    r.lower = b.lower, r.lower_open = b.lower_open;
  if (b.upper < r.upper || (b.upper == r.upper && b.upper_open))
    r.upper = b.upper, r.upper_open = b.upper_open;
  return r;
}

const char* kind_name(KeyKind k) {
  switch (k) {
    case KeyKind::kNumber:
      return "a number";
    case KeyKind::kWholeNumber:
      return "a whole number";
    case KeyKind::kText:
      return "a text";
    case KeyKind::kFlag:
      return "a flag";
    case KeyKind::kNumberList:
      return "a list of numbers";
    case KeyKind::kTolerance:
      return "a tolerance";
    case KeyKind::kPath:
      return "a path";
    case KeyKind::kTable:
      return "a table";
    case KeyKind::kTables:
      return "an array of tables";
  }
  return "?";
}

// Markdown cells hold no bare '|'.
std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

}  // namespace

std::string KeyDeclaration::allowed() const {
  std::string s;
  switch (kind) {
    case KeyKind::kNumber:
      s = range.text() + (unit.empty() ? "" : " " + unit);
      break;
    case KeyKind::kWholeNumber:
      s = "integer in [1, 1e8]";
      break;
    case KeyKind::kText:
      s = choices.empty() ? "text" : quoted_list(choices);
      break;
    case KeyKind::kFlag:
      s = "true or false";
      break;
    case KeyKind::kNumberList:
      s = "array of numbers";
      break;
    case KeyKind::kTolerance:
      s = "(0, 1] or \"not needed\"";
      break;
    case KeyKind::kPath:
      s = "a file, relative to the file that names it";
      break;
    case KeyKind::kTable:
      s = "a table" + (unit.empty() && range.lower == -kInf && range.upper == kInf
                           ? std::string()
                           : ", values in " + range.text() + (unit.empty() ? "" : " " + unit));
      break;
    case KeyKind::kTables:
      s = "array of tables";
      break;
  }
  return limit.empty() ? s : s + "; " + limit;
}

std::string KeyDeclaration::default_text() const {
  if (const auto* d = std::get_if<double>(&value)) return fmt::format("{:g}", *d);
  if (const auto* t = std::get_if<std::string>(&value)) return fmt::format("\"{}\"", *t);
  if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (!default_note.empty()) return default_note;
  if (need == Need::kRequired) return "required";
  if (need == Need::kConditional) return when;
  return "none";
}

const KeyDeclaration& declared(const KeyDeclarations& rows, const std::string& table,
                               const std::string& key) {
  const auto it = std::find_if(rows.begin(), rows.end(), [&](const KeyDeclaration& r) {
    return r.table == table && r.key == key;
  });
  if (it == rows.end())
    throw std::logic_error(
        fmt::format("key '{}{}' is read but not declared", table.empty() ? "" : table + ".", key));
  return *it;
}

std::vector<std::string> path_keys(const KeyDeclarations& rows) {
  std::vector<std::string> out;
  for (const auto& r : rows)
    if (r.kind == KeyKind::kPath) out.push_back(r.dotted());
  return out;
}

std::string markdown_table(const KeyDeclarations& rows) {
  std::string s = "| key | allowed | default | meaning |\n|---|---|---|---|\n";
  for (const auto& r : rows) {
    const std::string key =
        r.table.empty() ? fmt::format("`{}`", r.key) : fmt::format("`[{}] {}`", r.table, r.key);
    s += fmt::format("| {} | {} | {} | {} |\n", key, cell(r.allowed()), cell(r.default_text()),
                     cell(r.meaning));
  }
  return s;
}

nlohmann::json to_json(const KeyDeclarations& rows) {
  auto out = nlohmann::json::array();
  for (const auto& r : rows) {
    nlohmann::json j = {{"table", r.table},
                        {"key", r.key},
                        {"kind", kind_name(r.kind)},
                        {"allowed", r.allowed()},
                        {"default", r.default_text()},
                        {"meaning", r.meaning}};
    j["need"] = r.need == Need::kRequired   ? "required"
                : r.need == Need::kOptional ? "optional"
                                            : r.when;
    if (r.kind == KeyKind::kNumber) {
      // JSON has no infinity: an open end is null
      const auto bound = [](double b) {
        return std::isinf(b) ? nlohmann::json() : nlohmann::json(b);
      };
      j["range"] = {{"lower", bound(r.range.lower)},
                    {"upper", bound(r.range.upper)},
                    {"lower_open", r.range.lower_open},
                    {"upper_open", r.range.upper_open}};
      if (!r.unit.empty()) j["unit"] = r.unit;
    }
    if (!r.choices.empty()) j["choices"] = r.choices;
    if (!r.limit.empty()) j["limit"] = r.limit;
    out.push_back(j);
  }
  return out;
}

DeclaredTable::DeclaredTable(TableReader reader, const KeyDeclarations& rows, std::string table)
    : reader_(std::move(reader)), rows_(&rows), table_(std::move(table)) {}

const KeyDeclaration& DeclaredTable::row(const std::string& key, KeyKind kind) const {
  const auto& r = declared(*rows_, table_, key);
  if (r.kind != kind)
    throw std::logic_error(fmt::format("key '{}' is declared {} but read as {}", r.dotted(),
                                       kind_name(r.kind), kind_name(kind)));
  return r;
}

std::optional<double> DeclaredTable::optional_number(const std::string& key, const Range& limit) {
  return reader_.optional_number_in(key, intersect(row(key, KeyKind::kNumber).range, limit));
}

std::optional<double> DeclaredTable::optional_number(const std::string& key) {
  return optional_number(key, Range{});
}

double DeclaredTable::number(const std::string& key, const Range& limit) {
  const auto& r = row(key, KeyKind::kNumber);
  const Range range = intersect(r.range, limit);
  if (const auto* d = std::get_if<double>(&r.value))
    return reader_.optional_number_in(key, range).value_or(*d);
  return reader_.number_in(key, range);
}

double DeclaredTable::number(const std::string& key) {
  return number(key, Range{});
}

std::optional<int> DeclaredTable::optional_whole_number(const std::string& key) {
  row(key, KeyKind::kWholeNumber);
  return reader_.optional_count(key);
}

int DeclaredTable::whole_number(const std::string& key) {
  const auto& r = row(key, KeyKind::kWholeNumber);
  if (const auto* d = std::get_if<double>(&r.value))
    return reader_.optional_count(key).value_or(int(*d));
  return reader_.count(key);
}

std::string DeclaredTable::text(const std::string& key) {
  const auto& r = row(key, KeyKind::kText);
  const auto* d = std::get_if<std::string>(&r.value);
  if (d == nullptr) reader_.text(key);  // required: "is missing"
  return optional_text(key).value_or(d != nullptr ? *d : std::string());
}

std::optional<std::string> DeclaredTable::optional_text(const std::string& key) {
  const auto& r = row(key, KeyKind::kText);
  const auto v = reader_.optional_text(key);
  if (v && !r.choices.empty() &&
      std::find(r.choices.begin(), r.choices.end(), *v) == r.choices.end())
    throw InputError(fmt::format("{} = \"{}\"; allowed {}{}", reader_.where(key), *v,
                                 quoted_list(r.choices),
                                 r.limit.empty() ? "" : " (" + r.limit + ")"));
  return v;
}

std::string DeclaredTable::path(const std::string& key) {
  row(key, KeyKind::kPath);
  return reader_.text(key);
}

bool DeclaredTable::flag(const std::string& key) {
  const auto& r = row(key, KeyKind::kFlag);
  const auto v = reader_.optional_flag(key);
  if (v) return *v;
  if (const auto* d = std::get_if<bool>(&r.value)) return *d;
  throw InputError(fmt::format("{} is missing (true or false)", reader_.where(key)));
}

std::vector<double> DeclaredTable::numbers(const std::string& key) {
  row(key, KeyKind::kNumberList);
  std::vector<double> out;
  const toml::node* n = reader_.node(key);
  if (n == nullptr) return out;
  const auto* arr = n->as_array();
  if (arr == nullptr)
    throw InputError(
        fmt::format("{} = {} should be an array of numbers", reader_.where(key), describe(*n)));
  for (const auto& x : *arr) {
    const auto v = x.value<double>();
    if (!v)
      throw InputError(fmt::format("{} has a non-number {}", reader_.where(key), describe(x)));
    if (!std::isfinite(*v))
      throw InputError(
          fmt::format("{} has {}, not a finite number", reader_.where(key), describe(x)));
    out.push_back(*v);
  }
  return out;
}

std::optional<TableReader> DeclaredTable::table(const std::string& key) {
  row(key, KeyKind::kTable);
  return reader_.table(key);
}

std::vector<TableReader> DeclaredTable::tables(const std::string& key) {
  row(key, KeyKind::kTables);
  return reader_.array_of_tables(key);
}

}  // namespace iwb::io
