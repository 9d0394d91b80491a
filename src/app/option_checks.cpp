#include "app/option_checks.hpp"

#include <filesystem>
#include <fmt/core.h>

namespace iwb::app {

namespace fs = std::filesystem;

namespace {

// Parses the whole text as a double ("5kPa" and "" are not numbers); NaN and inf parse.
bool parse_double(const std::string& text, double& v) {
  try {
    std::size_t used = 0;
    v = std::stod(text, &used);
    return used == text.size();
  } catch (const std::exception&) {
    return false;
  }
}

std::string kind_of(const fs::path& p) {
  std::error_code ec;
  const auto s = fs::status(p, ec);
  if (!fs::exists(s)) return "missing";
  if (fs::is_directory(s)) return "directory";
  if (fs::is_regular_file(s)) return "file";
  return "other";
}

}  // namespace

CLI::Validator number_in(const Range& range, const std::string& unit) {
  const std::string allowed = range.requirement() + (unit.empty() ? "" : " (" + unit + ")");
  return CLI::Validator(
      [range, allowed](std::string& text) {
        double v = 0.0;
        if (!parse_double(text, v)) return fmt::format("{}: not a number; {}", text, allowed);
        if (!range.admits(v)) return fmt::format("{}: {}", text, allowed);
        return std::string();
      },
      "NUMBER in " + range.text());
}

CLI::Validator whole_in(long lower, long upper) {
  const std::string allowed = fmt::format("must be a whole number in [{}, {}]", lower, upper);
  return CLI::Validator(
      [lower, upper, allowed](std::string& text) {
        try {
          std::size_t used = 0;
          const long v = std::stol(text, &used);
          if (used == text.size() && v >= lower && v <= upper) return std::string();
        } catch (const std::exception&) {
        }
        return fmt::format("{}: {}", text, allowed);
      },
      fmt::format("INT in [{}, {}]", lower, upper));
}

CLI::Validator input_file() {
  return CLI::Validator(
      [](std::string& text) {
        const auto kind = kind_of(text);
        if (kind == "file") return std::string();
        if (kind == "missing") return fmt::format("{}: no such file", text);
        return fmt::format("{}: is a {}, not a file", text, kind == "directory" ? "directory" : "special file");
      },
      "FILE");
}

CLI::Validator input_directory() {
  return CLI::Validator(
      [](std::string& text) {
        const auto kind = kind_of(text);
        if (kind == "directory") return std::string();
        if (kind == "missing") return fmt::format("{}: no such directory", text);
        return fmt::format("{}: is a file, not a directory", text);
      },
      "DIR");
}

CLI::Validator input_path() {
  return CLI::Validator(
      [](std::string& text) {
        return kind_of(text) == "missing" ? fmt::format("{}: no such file or directory", text) : std::string();
      },
      "PATH");
}

CLI::Validator output_file() {
  return CLI::Validator(
      [](std::string& text) {
        if (text.empty()) return std::string("an empty path; give a file name");
        return kind_of(text) == "directory"
                   ? fmt::format("{}: is a directory; give the file to write", text)
                   : std::string();
      },
      "FILE");
}

CLI::Validator output_directory() {
  return CLI::Validator(
      [](std::string& text) {
        if (text.empty()) return std::string("an empty path; give a directory");
        const auto kind = kind_of(text);
        return kind == "missing" || kind == "directory"
                   ? std::string()
                   : fmt::format("{}: is a file; give the directory to write", text);
      },
      "DIR");
}

}  // namespace iwb::app
