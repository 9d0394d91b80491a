#include "app/option_checks.hpp"

#include <fmt/core.h>

#include <filesystem>

#include "common/errors.hpp"

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

// What is at `p`: "missing", "directory", "file", "other" (a FIFO, a device), "loop" (a symbolic
// link that leads back to itself: not a missing file, though no file is there) or "under a file"
// (a path through a regular file, which can be neither read nor made).
std::string kind_of(const fs::path& p) {
  std::error_code ec;
  const auto s = fs::status(p, ec);
  if (ec == std::errc::too_many_symbolic_link_levels) return "loop";
  if (ec == std::errc::not_a_directory) return "under a file";
  if (!fs::exists(s)) return "missing";
  if (fs::is_directory(s)) return "directory";
  if (fs::is_regular_file(s)) return "file";
  return "other";
}

// A missing input path, or no path at all: '' would otherwise read as "no such file", and CLI11
// takes the word after an option that needs a value as that value (`--runs --held-out X` gives
// --runs "--held-out"), which would blame the next option. CLI11 puts the option's name first.
std::string missing(const std::string& text, const std::string& what) {
  if (text.find_first_not_of(" \t") == std::string::npos)
    return fmt::format("an empty value; give a {}", what);
  if (text.front() == '-')
    return fmt::format("no {} given ('{}' is the next option, not a {})", what, text, what);
  return fmt::format("{}: no such {}", text, what);
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

namespace {
// A validator of a path: `refusal` gets the text and what is there (kind_of) and says what is
// wrong, or nothing. A link loop and a path through a file are refused for every kind of path.
CLI::Validator path_check(const std::string& name,
                          std::string (*refusal)(const std::string&, const std::string&)) {
  return CLI::Validator(
      [refusal](std::string& text) {
        const std::string kind = kind_of(text);
        if (kind == "loop") return text + ": a symbolic link loop (the link leads back to itself)";
        if (kind == "under a file")
          return text + ": a path through a file (a part of it is a file, not a directory)";
        return refusal(text, kind);
      },
      name);
}
}  // namespace

CLI::Validator input_file() {
  return path_check("FILE", [](const std::string& text, const std::string& kind) -> std::string {
    if (kind == "file") return "";
    if (kind == "missing") return missing(text, "file");
    return fmt::format("{}: is a {}, not a file", text,
                       kind == "directory" ? "directory" : "special file");
  });
}

CLI::Validator input_directory() {
  return path_check("DIR", [](const std::string& text, const std::string& kind) -> std::string {
    if (kind == "directory") return "";
    return kind == "missing" ? missing(text, "directory") : text + ": is a file, not a directory";
  });
}

CLI::Validator input_path() {
  return path_check("PATH", [](const std::string& text, const std::string& kind) -> std::string {
    return kind == "missing" ? missing(text, "file or directory") : "";
  });
}

CLI::Validator output_file() {
  return path_check("FILE", [](const std::string& text, const std::string& kind) -> std::string {
    if (text.empty()) return "an empty path; give a file name";
    return kind == "directory" ? text + ": is a directory; give the file to write" : "";
  });
}

CLI::Validator output_directory() {
  return path_check("DIR", [](const std::string& text, const std::string& kind) -> std::string {
    if (text.empty()) return "an empty path; give a directory";
    return kind == "missing" || kind == "directory"
               ? ""
               : text + ": is a file; give the directory to write";
  });
}

CLI::Validator non_empty() {
  return CLI::Validator(
      [](std::string& text) {
        return text.find_first_not_of(" \t") == std::string::npos
                   ? std::string(
                         "an empty value; give one, or leave the option out for its default")
                   : std::string();
      },
      "TEXT");
}

void refuse_given(const CLI::App& command, const std::vector<std::string>& options,
                  const std::string& why) {
  for (const auto& name : options)
    if (const CLI::Option* given = command.get_option(name); given->count() > 0)
      throw InputError(fmt::format("{} {}: {}; leave it out", name, given->as<std::string>(), why));
}

std::vector<std::string> split_list(const std::string& csv) {
  std::vector<std::string> out;
  std::string item;
  for (char c : csv + ",") {
    if (c != ',') {
      item += c;
    } else if (!item.empty()) {
      out.push_back(item);
      item.clear();
    }
  }
  return out;
}

}  // namespace iwb::app
