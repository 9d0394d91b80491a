#include "io/toml_override.hpp"

#include <fmt/core.h>

#include <sstream>

#include "common/errors.hpp"
#include "io/toml_reader.hpp"

namespace iwb::io {

TomlScalar scalar_of(const toml::node& node, const std::string& where) {
  if (auto v = node.as_integer()) return v->get();
  if (auto v = node.as_floating_point()) return v->get();
  if (auto v = node.as_boolean()) return v->get();
  if (auto v = node.as_string()) return v->get();
  throw InputError(
      fmt::format("{} = {}: a number, a boolean or a string is needed", where, describe(node)));
}

std::string to_toml(const TomlScalar& value) {
  std::ostringstream os;
  std::visit(
      [&os](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::string>)
          os << toml::value<std::string>(v);
        else if constexpr (std::is_same_v<T, bool>)
          os << (v ? "true" : "false");
        else
          os << toml::value<T>(v);
      },
      value);
  return os.str();
}

namespace {
void insert_scalar(toml::table& table, const std::string& key, const TomlScalar& value) {
  std::visit([&](const auto& v) { table.insert_or_assign(key, v); }, value);
}
}  // namespace

void set_dotted(toml::table& root, const std::string& dotted_key, const TomlScalar& value,
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
  if (auto* existing = table->get(leaf); existing && (existing->is_table() || existing->is_array()))
    throw InputError(fmt::format("{}: cannot set '{}' = {}: it holds {} in the base", source,
                                 dotted_key, to_toml(value), describe(*existing)));
  insert_scalar(*table, leaf, value);
}

std::string serialise(const toml::table& root) {
  std::ostringstream os;
  os << root;
  return os.str() + "\n";
}

}  // namespace iwb::io
