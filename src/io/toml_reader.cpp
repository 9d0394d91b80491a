#include "io/toml_reader.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "common/errors.hpp"
#include "common/input_file.hpp"

namespace iwb::io {

TableReader::TableReader(const toml::table& table, std::string file, std::string prefix)
    : table_(&table), file_(std::move(file)), prefix_(std::move(prefix)) {}

std::string TableReader::where(const std::string& key) const {
  return fmt::format("{}: key '{}{}'", file_, prefix_.empty() ? "" : prefix_ + ".", key);
}

std::string TableReader::where() const {
  return prefix_.empty() ? file_ : fmt::format("{}: table [{}]", file_, prefix_);
}

std::string describe(const toml::node& node) {
  std::ostringstream os;
  if (auto s = node.as_string()) return fmt::format("\"{}\"", s->get());
  if (node.is_table()) return "a table";
  if (node.is_array()) return "an array";
  if (const auto* f = node.as_floating_point())
    return fmt::format("{}", f->get());  // 0.1, not 0.1000...01
  node.visit([&os](const auto& v) {
    if constexpr (toml::is_value<decltype(v)>) os << v;
  });
  return os.str();
}

bool TableReader::has(const std::string& key) const {
  return table_->contains(key);
}

const toml::node* TableReader::node(const std::string& key) {
  read_.insert(key);
  return table_->get(key);
}

std::optional<double> TableReader::optional_number(const std::string& key) {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  const auto v = n->value<double>();
  if (!v || !(n->is_floating_point() || n->is_integer()))
    throw InputError(fmt::format("{} = {} is not a number", where(key), describe(*n)));
  if (!std::isfinite(*v))  // TOML admits inf and nan; no setting means either
    throw InputError(fmt::format("{} = {} is not a finite number", where(key), describe(*n)));
  return *v;
}

namespace {
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}
constexpr std::size_t kTypoDistance = 2;  // a dropped, doubled or swapped letter or two
}  // namespace

std::string TableReader::missing(const std::string& key, const std::string& what) const {
  std::string near;
  for (const auto& [k, v] : *table_) {
    const std::string name(k.str());
    if (!read_.count(name) && edit_distance(name, key) <= kTypoDistance)
      near += fmt::format("{}'{}' (value {})", near.empty() ? "" : ", ", name, describe(v));
  }
  return fmt::format("{} is missing ({}){}", where(key), what,
                     near.empty() ? "" : "; did you mean " + near + "?");
}

double TableReader::number(const std::string& key) {
  if (auto v = optional_number(key)) return *v;
  throw InputError(missing(key, "a number"));
}

std::optional<double> TableReader::optional_number_in(const std::string& key, const Range& range) {
  auto v = optional_number(key);
  if (v && !range.admits(*v))
    throw InputError(
        fmt::format("{} = {:g} is out of range; allowed {}", where(key), *v, range.text()));
  return v;
}

double TableReader::number_in(const std::string& key, const Range& range) {
  if (auto v = optional_number_in(key, range)) return *v;
  throw InputError(missing(key, "a number in " + range.text()));
}

std::optional<double> TableReader::optional_positive(const std::string& key, double upper) {
  return optional_number_in(key, iwb::positive(upper));
}

double TableReader::positive(const std::string& key, double upper) {
  return number_in(key, iwb::positive(upper));
}

std::optional<int> TableReader::optional_count(const std::string& key) {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  const auto v = n->value_exact<int64_t>();
  if (!v || *v < 1 || *v > 100000000)
    throw InputError(
        fmt::format("{} = {} must be a whole number in [1, 1e8]", where(key), describe(*n)));
  return int(*v);
}

int TableReader::count(const std::string& key) {
  if (auto v = optional_count(key)) return *v;
  throw InputError(missing(key, "a whole number >= 1"));
}

std::optional<std::string> TableReader::optional_text(const std::string& key) {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (auto s = n->value<std::string>()) return *s;
  throw InputError(fmt::format("{} = {} is not a string", where(key), describe(*n)));
}

std::optional<bool> TableReader::optional_flag(const std::string& key) {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (auto b = n->value<bool>()) return *b;
  throw InputError(fmt::format("{} = {} is not true or false", where(key), describe(*n)));
}

std::string TableReader::text(const std::string& key) {
  if (auto v = optional_text(key)) return *v;
  throw InputError(missing(key, "a string"));
}

std::optional<TableReader> TableReader::table(const std::string& key) {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (auto t = n->as_table())
    return TableReader(*t, file_, prefix_.empty() ? key : prefix_ + "." + key);
  throw InputError(fmt::format("{} = {} should be a table", where(key), describe(*n)));
}

TableReader TableReader::required_table(const std::string& key) {
  if (auto t = table(key)) return *t;
  throw InputError(
      fmt::format("{}: table [{}{}] is missing", file_, prefix_.empty() ? "" : prefix_ + ".", key));
}

std::vector<TableReader> TableReader::array_of_tables(const std::string& key) {
  std::vector<TableReader> out;
  const toml::node* n = node(key);
  if (n == nullptr) return out;
  const auto* arr = n->as_array();
  if (arr == nullptr)
    throw InputError(fmt::format("{} = {} should be an array of tables", where(key), describe(*n)));
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const auto* t = arr->get(i)->as_table();
    if (t == nullptr) throw InputError(fmt::format("{}[{}] should be a table", where(key), i));
    out.emplace_back(*t, file_,
                     fmt::format("{}{}[{}]", prefix_.empty() ? "" : prefix_ + ".", key, i));
  }
  return out;
}

void TableReader::finish() const {
  for (const auto& [k, v] : *table_) {
    const std::string key(k.str());
    if (!read_.count(key))
      throw InputError(fmt::format("{} is not a known key (value {})", where(key), describe(v)));
  }
}

std::string TableReader::one_of(const std::vector<std::string>& keys) {
  std::string found, names;
  for (const auto& k : keys) names += (names.empty() ? "" : ", ") + k;
  for (const auto& k : keys) {
    if (has(k)) {
      if (!found.empty())
        throw InputError(fmt::format("{}: give only one of {} (both '{}' and '{}' are set)",
                                     where(), names, found, k));
      found = k;
    }
  }
  if (found.empty()) throw InputError(fmt::format("{}: one of {} is required", where(), names));
  return found;
}

toml::table parse_toml_text(const std::string& text, const std::string& name) {
  try {
    return toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", name, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
}

toml::table parse_toml_file(const std::string& path) {
  if (const auto why = unreadable_input_file(path); !why.empty())
    throw InputError(fmt::format("{}: {}", path, why));
  try {
    return toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", path, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
}

std::optional<std::optional<double>> read_tolerance(TableReader& t, const std::string& key) {
  const toml::node* n = t.node(key);
  if (n == nullptr) return std::nullopt;
  const auto s = n->value<std::string>();
  const auto v = n->value<double>();
  if (s && *s == "not needed") return std::optional<double>();
  if (!s && v && *v > 0.0 && *v <= 1.0) return std::optional<double>(*v);
  throw InputError(
      fmt::format("{} = {}: a tolerance is a number in (0, 1] (0.05 = 5 %) or \"not needed\"",
                  t.where(key), describe(*n)));
}

}  // namespace iwb::io
