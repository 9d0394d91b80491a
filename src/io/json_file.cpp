#include "io/json_file.hpp"

#include <algorithm>
#include <fmt/core.h>

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
    throw InputError(fmt::format("{}: not valid JSON (truncated or edited?): parsing stopped at byte {} of {}",
                                 path.string(), std::min(e.byte, text.size()), text.size()));
  }
}

}  // namespace iwb::io
