#include "io/json_file.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/errors.hpp"
#include "io/run_directory.hpp"

namespace iwb::io {

namespace {

using nlohmann::json;

// A value is shown in a message up to this many characters: an edited object can be a whole run.
constexpr std::size_t kShownCharacters = 60;

std::string shown(const json& v) {
  const std::string s = v.dump();
  return s.size() <= kShownCharacters ? s : s.substr(0, kShownCharacters) + "...";
}

// The value at `pointer`, or null when the pointer does not lead to one (a missing key, an index
// past the end, a step into a number).
const json* lookup(const json& j, const std::string& pointer) {
  try {
    return &j.at(json::json_pointer(pointer));
  } catch (const json::exception&) {
    return nullptr;
  }
}

const json& found(const json& j, const std::string& pointer, const std::filesystem::path& file) {
  const json* v = lookup(j, pointer);
  if (v == nullptr)
    throw InputError(fmt::format("{}: missing or malformed field '{}'", file.string(), pointer));
  return *v;
}

[[noreturn]] void wrong_type(const json& v, const std::string& pointer,
                             const std::filesystem::path& file, const char* expected) {
  throw InputError(
      fmt::format("{}: key '{}' = {}: should be {}", file.string(), pointer, shown(v), expected));
}

// What each T accepts, and how a message names it.
template <class T>
struct Kind;
template <>
struct Kind<std::string> {
  static bool admits(const json& v) { return v.is_string(); }
  static constexpr const char* kName = "a string";
};
template <>
struct Kind<double> {
  static bool admits(const json& v) { return v.is_number(); }
  static constexpr const char* kName = "a number";
};
template <>
struct Kind<int> {  // 2.0 is a whole number; 2.5 would be cut to 2 by get<int>()
  static bool admits(const json& v) {
    if (!v.is_number()) return false;
    const double x = v.get<double>();
    return x == std::floor(x) && std::abs(x) <= std::numeric_limits<int>::max();
  }
  static constexpr const char* kName = "a whole number";
};
template <>
struct Kind<bool> {
  static bool admits(const json& v) { return v.is_boolean(); }
  static constexpr const char* kName = "true or false";
};

template <class T>
T typed(const json& v, const std::string& pointer, const std::filesystem::path& file) {
  if (!Kind<T>::admits(v)) wrong_type(v, pointer, file, Kind<T>::kName);
  return v.get<T>();
}

}  // namespace

nlohmann::json read_json_file(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path))
    throw InputError(fmt::format("{}: missing (not a directory iwb wrote?)", path.string()));
  const std::string text = read_file(path);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(
        fmt::format("{}: not valid JSON (truncated or edited?): parsing stopped at byte {} of {}",
                    path.string(), std::min(e.byte, text.size()), text.size()));
  }
}

template <class T>
T json_field(const json& j, const std::string& pointer, const std::filesystem::path& file) {
  return typed<T>(found(j, pointer, file), pointer, file);
}

template <class T>
std::optional<T> json_optional(const json& j, const std::string& pointer,
                               const std::filesystem::path& file) {
  const json* v = lookup(j, pointer);
  if (v == nullptr || v->is_null()) return std::nullopt;
  return typed<T>(*v, pointer, file);
}

const json& json_array(const json& j, const std::string& pointer,
                       const std::filesystem::path& file) {
  const json& v = found(j, pointer, file);
  if (!v.is_array()) wrong_type(v, pointer, file, "an array");
  return v;
}

const json& json_object(const json& j, const std::string& pointer,
                        const std::filesystem::path& file) {
  const json& v = found(j, pointer, file);
  if (!v.is_object()) wrong_type(v, pointer, file, "an object");
  return v;
}

template std::string json_field<std::string>(const json&, const std::string&,
                                             const std::filesystem::path&);
template std::optional<std::string> json_optional<std::string>(const json&, const std::string&,
                                                               const std::filesystem::path&);
template double json_field<double>(const json&, const std::string&, const std::filesystem::path&);
template std::optional<double> json_optional<double>(const json&, const std::string&,
                                                     const std::filesystem::path&);
template int json_field<int>(const json&, const std::string&, const std::filesystem::path&);
template std::optional<int> json_optional<int>(const json&, const std::string&,
                                               const std::filesystem::path&);
template bool json_field<bool>(const json&, const std::string&, const std::filesystem::path&);
template std::optional<bool> json_optional<bool>(const json&, const std::string&,
                                                 const std::filesystem::path&);

}  // namespace iwb::io
