#include "assessment/distribution_file.hpp"

#include <fmt/core.h>

#include "common/errors.hpp"
#include "io/run_directory.hpp"
#include "io/toml_reader.hpp"

namespace iwb::assessment {

std::vector<Distribution> read_distributions(const std::filesystem::path& file) {
  return parse_distributions(io::read_file(file), file.string());
}

std::map<std::string, std::string> distribution_texts(const std::filesystem::path& dir) {
  if (dir.empty()) return embedded_distributions();
  if (!std::filesystem::is_directory(dir))
    throw InputError(
        fmt::format("--distributions {}: no such directory (one <table>.toml per parameter table: "
                    "data/assessment/distributions/)",
                    dir.string()));
  std::map<std::string, std::string> out;
  for (const auto& f : std::filesystem::directory_iterator(dir))
    if (f.path().extension() == ".toml")
      out[f.path().filename().string()] = io::read_file(f.path());
  return out;
}

std::vector<Distribution> parse_distributions(const std::string& text, const std::string& source) {
  const auto root =
      io::parse_toml_text(text, source);  // a syntax error is bad input (exit 2), naming the file
  io::TableReader top(root, source);
  std::vector<Distribution> out;
  for (auto& p : top.array_of_tables("parameter")) {
    const std::string kind = p.text("distribution");
    const auto k = kind == "normal"      ? Distribution::Kind::kNormal
                   : kind == "lognormal" ? Distribution::Kind::kLognormal
                   : kind == "uniform"
                       ? Distribution::Kind::kUniform
                       : throw InputError(fmt::format(
                             "{} = \"{}\"; allowed \"normal\", \"lognormal\", \"uniform\"",
                             p.where("distribution"), kind));
    out.push_back({p.text("key"), k, p.positive("mean"), p.positive("cov", 1.0)});
    p.finish();
  }
  top.finish();
  return out;
}

}  // namespace iwb::assessment
