#include "dem/scene/scene_content.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>

#include "io/run_directory.hpp"
#include "io/toml_reader.hpp"

namespace iwb::dem {

using nlohmann::json;

namespace {

constexpr std::size_t kDifferencesShown = 4;  // a message stays readable; the first keys say enough

// Keys of a scene's top level that say what the results are for, not how the engine runs.
constexpr const char* kNotRunKeys[] = {"description", "requirements"};

json to_json(const toml::node& node) {
  if (const auto* t = node.as_table()) {
    json out = json::object();
    for (const auto& [key, value] : *t) out[std::string(key.str())] = to_json(value);
    return out;
  }
  if (const auto* a = node.as_array()) {
    json out = json::array();
    for (const auto& value : *a) out.push_back(to_json(value));
    return out;
  }
  if (const auto* i = node.as_integer()) return i->get();
  if (const auto* f = node.as_floating_point()) return f->get();
  if (const auto* b = node.as_boolean()) return b->get();
  if (const auto* s = node.as_string()) return s->get();
  return io::describe(node);  // dates and times: as written
}

std::string shown(const json* value, const char* where) {
  return value == nullptr ? fmt::format("absent {}", where)
                          : fmt::format("= {} {}", value->dump(), where);
}

void differences(const json* mine, const json* theirs, const std::string& key,
                 std::vector<std::string>& out) {
  if (mine != nullptr && theirs != nullptr && mine->is_object() && theirs->is_object()) {
    json keys = json::object();  // the union of both key sets, sorted
    for (const auto& [k, v] : mine->items()) keys[k] = true;
    for (const auto& [k, v] : theirs->items()) keys[k] = true;
    for (const auto& [k, v] : keys.items()) {
      const auto a = mine->find(k), b = theirs->find(k);
      differences(a == mine->end() ? nullptr : &*a, b == theirs->end() ? nullptr : &*b,
                  key.empty() ? k : key + "." + k, out);
    }
    return;
  }
  if (mine != nullptr && theirs != nullptr && *mine == *theirs) return;
  out.push_back(fmt::format("key '{}' {}, {}", key, shown(mine, "here"), shown(theirs, "there")));
}

}  // namespace

json scene_content(const std::string& text, const std::string& source) {
  json content = to_json(io::parse_toml_text(text, source));
  for (const char* key : kNotRunKeys) content.erase(key);
  // A wall file counts by what it holds, not by where it lies.
  for (const char* table : {"wall", "plate"}) {
    auto* t = content.contains(table) && content[table].is_object() ? &content[table] : nullptr;
    if (t == nullptr || !t->contains("file") || !(*t)["file"].is_string()) continue;
    const auto path = std::filesystem::path(source).parent_path() / (*t)["file"].get<std::string>();
    if (std::filesystem::is_regular_file(path))
      (*t)["file"] = "sha256:" + io::sha256_hex(io::read_file(path));
  }
  return content;
}

std::vector<std::string> content_differences(const json& mine, const json& theirs) {
  std::vector<std::string> out;
  differences(&mine, &theirs, "", out);
  return out;
}

std::string differences_text(const std::vector<std::string>& differences) {
  std::string s;
  for (std::size_t i = 0; i < std::min(differences.size(), kDifferencesShown); ++i)
    s += (i == 0 ? "" : "; ") + differences[i];
  if (differences.size() > kDifferencesShown)
    s += fmt::format("; and {} more", differences.size() - kDifferencesShown);
  return s;
}

}  // namespace iwb::dem
