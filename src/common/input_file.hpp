#pragma once
// What is at a path named as an input file, for a message that says it rather than "no such file"
// (issue 60): a directory, a named pipe (which would also block the reader for ever), a device, a
// link that leads back to itself.
#include <filesystem>
#include <string>
#include <system_error>

namespace iwb {

// "" when `path` is a regular file or a link to one; else why it cannot be read as one, e.g. "is
// a directory, not a file", to follow the path in a message.
inline std::string unreadable_input_file(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status s = fs::status(path, ec);
  if (ec == std::errc::too_many_symbolic_link_levels)
    return "a symbolic link loop (the link leads back to itself)";
  if (fs::is_regular_file(s)) return "";
  if (!fs::exists(s)) return "no such file";
  if (fs::is_directory(s)) return "is a directory, not a file";
  if (fs::is_fifo(s)) return "is a named pipe (FIFO), not a regular file";
  return "is a special file (a socket or a device), not a regular file";
}

}  // namespace iwb
