#include "io/checksum_record.hpp"

#include <fmt/core.h>

#include "io/run_directory.hpp"

namespace iwb::io {

namespace fs = std::filesystem;

fs::path checksum_record_path(const fs::path& file) {
  return file.string() + ".checksum.json";
}

nlohmann::json write_checksum_record(const fs::path& file) {
  const std::string bytes = read_file(file);
  const nlohmann::json record = {{"file", file.filename().string()},
                                 {"size_bytes", bytes.size()},
                                 {"sha256", sha256_hex(bytes)},
                                 {"written", utc_timestamp()}};
  write_atomically(checksum_record_path(file), record.dump(2) + "\n");
  return record;
}

std::optional<std::string> checksum_problem(const fs::path& file) {
  const fs::path record_file = checksum_record_path(file);
  if (!fs::exists(file)) return fmt::format("{} is missing", file.string());
  if (!fs::exists(record_file))
    return fmt::format("{} has no size and hash record ({})", file.string(),
                       record_file.filename().string());
  nlohmann::json record;
  try {
    record = nlohmann::json::parse(read_file(record_file));
  } catch (const nlohmann::json::exception&) {
    return fmt::format("{}: its record {} is not readable", file.string(),
                       record_file.filename().string());
  }
  const auto size = fs::file_size(file);
  if (size != record.value("size_bytes", std::uintmax_t(0)))
    return fmt::format("{} has {} bytes, its record says {}", file.string(), size,
                       record.value("size_bytes", std::uintmax_t(0)));
  if (sha256_hex(read_file(file)) != record.value("sha256", std::string()))
    return fmt::format("{} has the recorded size but not the recorded sha256", file.string());
  return std::nullopt;
}

}  // namespace iwb::io
