// The command line's validators (src/app/option_checks.hpp): NaN, inf, zero and negatives where
// they make no sense are refused with the value and a readable range; files and directories are
// told apart.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "models/registry.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {
// The validator's message for `text` ("" when it admits it).
std::string refusal(const CLI::Validator& v, std::string text) {
  return v(text);
}
}  // namespace

TEST_CASE("a number option refuses nan, inf, text and values outside its range", "[app]") {
  const auto sigma = app::number_in(positive(app::kMaxStressKPa), "kPa");
  CHECK(refusal(sigma, "50").empty());
  CHECK(refusal(sigma, "1e5").empty());
  CHECK(refusal(sigma, "nan") == "nan: must be finite and in (0, 100000] (kPa)");
  CHECK(refusal(sigma, "inf") == "inf: must be finite and in (0, 100000] (kPa)");
  CHECK(refusal(sigma, "-inf") == "-inf: must be finite and in (0, 100000] (kPa)");
  CHECK(refusal(sigma, "-5") == "-5: must be finite and in (0, 100000] (kPa)");
  CHECK(refusal(sigma, "0") == "0: must be finite and in (0, 100000] (kPa)");
  CHECK(refusal(sigma, "1.00001e5") == "1.00001e5: must be finite and in (0, 100000] (kPa)");
  CHECK(refusal(sigma, "50kPa") == "50kPa: not a number; must be finite and in (0, 100000] (kPa)");
  CHECK(refusal(sigma, "") == ": not a number; must be finite and in (0, 100000] (kPa)");
  // without an upper bound the message says so plainly, and never prints the largest double
  CHECK(refusal(app::number_in(positive()), "nan") == "nan: must be finite and > 0");
  CHECK(refusal(app::number_in(closed(4.0, 100.0), "d50"), "3.9") ==
        "3.9: must be finite and in [4, 100] (d50)");
  CHECK(refusal(app::number_in(closed(1e-6, 1e-1)), "5") ==
        "5: must be finite and in [1e-06, 0.1]");
}

TEST_CASE("a whole-number option refuses 0, fractions, exponents and text", "[app]") {
  const auto ranks = app::whole_in(1, app::kMaxProcesses);
  CHECK(refusal(ranks, "1").empty());
  CHECK(refusal(ranks, "256").empty());
  for (const char* bad : {"0", "-1", "257", "1.5", "1e3", "two", "nan", ""})
    CHECK(refusal(ranks, bad) == std::string(bad) + ": must be a whole number in [1, 256]");
}

TEST_CASE("file and directory options tell files, directories and missing paths apart", "[app]") {
  const fs::path dir = fs::path(IWB_TEST_RUNS_DIR) / "option_checks";
  fs::create_directories(dir);
  const auto file = (dir / "a.toml").string();
  std::ofstream(file) << "x = 1\n";
  const auto missing = (dir / "missing.toml").string();
  CHECK(refusal(app::input_file(), file).empty());
  CHECK(refusal(app::input_file(), missing) == missing + ": no such file");
  CHECK(refusal(app::input_file(), dir.string()) == dir.string() + ": is a directory, not a file");
  CHECK(refusal(app::input_directory(), dir.string()).empty());
  CHECK(refusal(app::input_directory(), file) == file + ": is a file, not a directory");
  CHECK(refusal(app::input_directory(), missing) == missing + ": no such directory");
  CHECK(refusal(app::input_path(), missing) == missing + ": no such file or directory");
  CHECK(refusal(app::output_file(), missing).empty());
  CHECK(refusal(app::output_file(), dir.string()) ==
        dir.string() + ": is a directory; give the file to write");
  CHECK(refusal(app::output_directory(), missing).empty());
  CHECK(refusal(app::output_directory(), dir.string()).empty());
  CHECK(refusal(app::output_directory(), file) ==
        file + ": is a file; give the directory to write");
}

TEST_CASE("a range prints its bounds with %g and never admits a value that is not finite",
          "[app]") {
  CHECK(positive().text() == "(0, inf)");
  CHECK(non_negative(10.0).text() == "[0, 10]");
  CHECK(Range{0.0, 0.5, false, true}.text() == "[0, 0.5)");
  CHECK(positive(1.2e12).text() == "(0, 1.2e+12]");
  CHECK(Range{}.text() == "(-inf, inf)");
  CHECK(Range{}.requirement() == "must be finite");
  CHECK_FALSE(Range{}.admits(std::numeric_limits<double>::quiet_NaN()));
  CHECK_FALSE(Range{}.admits(std::numeric_limits<double>::infinity()));
  CHECK(Range{}.admits(-1e308));
  CHECK_FALSE(positive().admits(0.0));
  CHECK(non_negative().admits(0.0));
  CHECK_FALSE((Range{0.0, 0.5, false, true}.admits(0.5)));
}

// The ladder the plan's and the league's help name is written in app (not asked of the registry
// at start-up); it must be the registry's, rank by rank.
TEST_CASE("the help's model ladder is the one the registry ranks", "[app]") {
  CHECK(std::string(app::kInterfaceModelLadder) == models::ranked_interface_models_text());
}
