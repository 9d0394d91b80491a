#pragma once
// Validators for every command-line option, in one place (CLI11's own PositiveNumber admits NaN
// and inf and prints its bound as a 309-digit number; its Range admits NaN). Each refuses a value
// with a message naming the value and what is allowed, e.g.
//   iwb dem soiltest: --sigma: nan: must be finite and > 0 (kPa)
// and the command line then exits 2 (main.cpp). Ranges are iwb::Range (src/common/range.hpp), the
// same type the file readers check values with.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "common/range.hpp"

namespace iwb::app {

// A number (double) that is finite and inside `range`; `unit` is printed after the range.
CLI::Validator number_in(const Range& range, const std::string& unit = "");
// A whole number inside [lower, upper] (ranks, repeats, seeds, levels).
CLI::Validator whole_in(long lower, long upper);
// An input file: exists and is a regular file (a directory is named as such).
CLI::Validator input_file();
// An input directory: exists and is a directory.
CLI::Validator input_directory();
// An input file or directory that must exist.
CLI::Validator input_path();
// A file to be written: not an existing directory.
CLI::Validator output_file();
// A directory to be written: not an existing file.
CLI::Validator output_directory();
// A text that is not empty (an option given as '' would otherwise mean its default).
CLI::Validator non_empty();

// After parsing: refuses (InputError) the first of `options` given to `command`, naming it, its
// value and `why` it does not apply ("applies only to --test cyclicshear, not to --test
// oedometer"): an option the run would ignore is refused rather than ignored.
void refuse_given(const CLI::App& command, const std::vector<std::string>& options,
                  const std::string& why);

// The items of a comma-separated option value ("liggghts,yade"), empty items dropped.
std::vector<std::string> split_list(const std::string& csv);

// Physical ranges shared by the commands (kPa, d50, strain).
inline constexpr double kMaxStressKPa = 1e5;     // 100 MPa: far beyond grain crushing
inline constexpr double kMaxShearStrain = 10.0;  // 1000 % shear strain
inline constexpr double kMaxVoidRatio = 10.0;
inline constexpr double kMaxCellSizeD50 = 1000.0;
inline constexpr double kMaxBudgetSeconds = 86400.0;  // a day per stability point
inline constexpr long kMaxProcesses = 256;

}  // namespace iwb::app
