#include "io/json_file.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "common/errors.hpp"
#include "io/run_directory.hpp"

namespace iwb::io {

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
T json_field(const nlohmann::json& j, const std::string& pointer,
             const std::filesystem::path& file) {
  try {
    return j.at(nlohmann::json::json_pointer(pointer)).get<T>();
  } catch (const nlohmann::json::exception&) {
    throw InputError(fmt::format("{}: missing or malformed field '{}'", file.string(), pointer));
  }
}

template std::string json_field<std::string>(const nlohmann::json&, const std::string&,
                                             const std::filesystem::path&);
template double json_field<double>(const nlohmann::json&, const std::string&,
                                   const std::filesystem::path&);
template int json_field<int>(const nlohmann::json&, const std::string&,
                             const std::filesystem::path&);

}  // namespace iwb::io
