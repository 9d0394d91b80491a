#include "io/toml_override.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <sstream>

#include "common/errors.hpp"
#include "io/toml_reader.hpp"

namespace iwb::io {

TomlValue toml_value_of(const toml::node& node, const std::string& where) {
  if (auto v = node.as_integer()) return v->get();
  if (auto v = node.as_floating_point()) return v->get();
  if (auto v = node.as_boolean()) return v->get();
  if (auto v = node.as_string()) return v->get();
  if (const auto* a = node.as_array(); a && !a->empty()) {  // a list of numbers, or nothing
    std::vector<double> out;
    for (const auto& e : *a) {
      const auto x = e.value<double>();
      if (!x) break;
      out.push_back(*x);
    }
    if (out.size() == a->size()) return out;
  }
  throw InputError(
      fmt::format("{} = {}: a number, a boolean, a string or a list of numbers is needed", where,
                  describe(node)));
}

std::string to_toml(const TomlValue& value) {
  std::ostringstream os;
  std::visit(
      [&os](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::string>)
          os << toml::value<std::string>(v);
        else if constexpr (std::is_same_v<T, std::vector<double>>)
          os << fmt::format("[{}]", fmt::join(v, ", "));
        else if constexpr (std::is_same_v<T, bool>)
          os << (v ? "true" : "false");
        else
          os << toml::value<T>(v);
      },
      value);
  return os.str();
}

namespace {
void insert_value(toml::table& table, const std::string& key, const TomlValue& value) {
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::vector<double>>) {
          toml::array a;
          for (const double x : v) a.push_back(x);
          table.insert_or_assign(key, std::move(a));
        } else {
          table.insert_or_assign(key, v);
        }
      },
      value);
}
}  // namespace

void set_dotted(toml::table& root, const std::string& dotted_key, const TomlValue& value,
                const std::string& source) {
  toml::table* table = &root;
  std::string path;
  std::size_t start = 0;
  for (std::size_t dot; (dot = dotted_key.find('.', start)) != std::string::npos; start = dot + 1) {
    const std::string part = dotted_key.substr(start, dot - start);
    path += (path.empty() ? "" : ".") + part;
    if (!table->contains(part)) table->insert(part, toml::table{});
    table = (*table)[part].as_table();
    if (table == nullptr)
      throw InputError(fmt::format("{}: cannot set '{}': '{}' is a value, not a table", source,
                                   dotted_key, path));
  }
  const std::string leaf = dotted_key.substr(start);
  if (leaf.empty() || dotted_key.front() == '.')
    throw InputError(
        fmt::format("{}: '{}' is not a dotted key (e.g. wall.height_d50)", source, dotted_key));
  const bool list = std::holds_alternative<std::vector<double>>(value);
  // a list replaces a list and a scalar a scalar: the scene's key is one or the other
  if (auto* existing = table->get(leaf);
      existing && (existing->is_table() || existing->is_array() != list))
    throw InputError(fmt::format("{}: cannot set '{}' = {}: it holds {} in the base", source,
                                 dotted_key, to_toml(value), describe(*existing)));
  insert_value(*table, leaf, value);
}

std::string serialise(const toml::table& root) {
  std::ostringstream os;
  os << root;
  return os.str() + "\n";
}

}  // namespace iwb::io
