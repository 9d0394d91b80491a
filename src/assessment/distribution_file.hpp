#pragma once
// Distribution files (data/assessment/distributions/, seed Table 4.8 and Appendix A): per parameter
// its key, distribution ("normal", "lognormal", "uniform"), mean and coefficient of variation.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "assessment/sobol.hpp"

namespace iwb::assessment {

// InputError naming the file and key for a syntax error, a missing or unknown key or a bad value.
std::vector<Distribution> read_distributions(const std::filesystem::path& file);
// The same from a file's text; `source` names it in messages.
std::vector<Distribution> parse_distributions(const std::string& text, const std::string& source);

// data/assessment/distributions/*.toml as they were when iwb was built, by file name (generated).
const std::map<std::string, std::string>& embedded_distributions();

// The distribution files by name: the .toml files of `dir`, or the embedded ones when `dir` is
// empty. InputError naming `dir` when it is not a directory.
std::map<std::string, std::string> distribution_texts(const std::filesystem::path& dir);

}  // namespace iwb::assessment
