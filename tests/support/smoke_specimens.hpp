#pragma once
// Test time (issue 37): the smoke scenes that differ only in their shear stage (CNL, CNS, CV, the
// start-of-shear variants, the implausible speed) start from one consolidated specimen per engine,
// as a campaign's runs do (dem/run/consolidation_cache.hpp), instead of consolidating it again in
// each test: consolidation is most of a smoke run (YADE: ~70 of ~90 s). The first test to need it
// consolidates and the others wait on its lock. Consolidation itself stays tested by that first
// run, by the runs that change what it reads (glued wall, servo failure, resume) and by
// tests/dem/run/test_consolidation_cache.cpp, which also shows a reused specimen gives the bytes of
// a run that consolidated itself.
#include <fmt/core.h>

#include <filesystem>
#include <string>

#include "support/replaced.hpp"

namespace iwb::test {

// A smoke scene file's text sheared over `mm` instead of its 2 mm: each engine test shears only
// what its check needs (the margin measured is in the test's comment).
inline std::string smoke_sheared_over(const std::filesystem::path& file, double mm) {
  return replaced(io::read_file(file), "displacement_mm = 2.0",
                  fmt::format("displacement_mm = {:.1f}", mm));
}

inline std::filesystem::path smoke_specimens() {
  return std::filesystem::path(IWB_TEST_RUNS_DIR) / "dem" / "consolidated";
}

}  // namespace iwb::test
