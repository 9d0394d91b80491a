#pragma once
// A campaign's claims, declared and tested in one place (issue 59 item 3): "roughness lowers the
// loss of friction ratio" is a claim about cells of DEM runs, not a sentence in a README. A claims
// file (data/<campaign>/claims.toml) declares each claim: the runs of its two groups, the quantity
// read from each run's summary.json (a soil cell's: its manifest's cell_summary), the direction it
// asserts, and what is done with runs whose band split between wall and plate or formed at the
// plate. One analysis tests them all: Welch's t-test between groups (one run against a group: its
// prediction interval), the family of a file controlled by Benjamini-Hochberg at the file's q, and
// a status per claim:
//   supported      significant after the control, in the direction claimed (for "b = a": the
//                  two one-sided tests significant: equal within the margin);
//   contradicted   significant after the control, the other way;
//   not resolved   not significant after the control (never read as "equal"): with the seeds per
//                  group that the measured scatter would need to resolve the effect measured;
//   not testable   a group of fewer than two runs (and not one run against a group).
//
// The file:
//   q = 0.05                                   # false-discovery rate of the file's family
//   [[claim]]
//   id = "cns-025"                             # unique in the file
//   says = "roughness lowers the loss of ..."  # the sentence the README would say
//   quantity = "/cyclic/cycles/19/friction_ratio"      # JSON pointer into summary.json
//   relative_to = "/cyclic/cycles/0/friction_ratio"   # optional: (q - r) / r
//   quantity_b = "/cyclic/post_cyclic/peak_friction"  # optional: group b's own pointer, where
//   relative_to_b = ...                               # the two groups are runs of different
//                                                     # kinds (a post-cyclic peak against a
//                                                     # virgin one); default: as group a
//   a = ["cyclic_small/runs/flat_cns*"]        # run directories, relative to the file; a '*' in
//   b = ["cyclic_small/runs/rough_cns*"]       # the last component matches names
//   expect = "b > a"                           # "b > a", "b < a", "b != a" or "b = a"
//   margin = 0.05                              # "b = a" only: equal within +-margin (the
//                                              # quantity's units; a fraction for a relative
//                                              # change), by two one-sided tests: the one
//                                              # form in which "no difference" can be shown
//   flagged = "exclude"                        # runs split or at the plate: "exclude" or "include"
//   unsteady = "include"                       # a claim on /residual_friction: runs whose
//                                              # residual_is is not "steady" are left out
//                                              # ("exclude", the default: a residual is settled)
//                                              # or kept ("include": the claim is then on the
//                                              # friction at the runs' stated travel, and says so)
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "statistics/group_tests.hpp"

namespace iwb::claims {

struct Claim {
  std::string id, says, quantity, relative_to, expect, flagged;
  std::string quantity_b, relative_to_b;  // group b's pointers (default: quantity, relative_to)
  std::string unsteady = "exclude";
  std::vector<std::string> a, b;
  double margin = 0.0;  // of an equality claim ("b = a")
  bool equality() const { return expect == "b = a"; }
};

struct ClaimsFile {
  std::filesystem::path file;
  double q = 0.05;
  std::vector<Claim> claims;
};

// InputError naming the file, the key and the value for anything malformed: a missing or unknown
// key, a q outside (0, 1), an expect or flagged not of the forms above, ids repeated.
ClaimsFile read_claims(const std::filesystem::path& file);

struct Group {
  std::vector<std::string> runs;  // the runs whose values were used
  std::vector<double> values;
  std::vector<std::pair<std::string, std::string>> excluded;  // run, why (split, at the plate)
  int flagged_included = 0;
  statistics::Sample sample;
};

struct ClaimResult {
  Claim claim;
  Group a, b;
  std::optional<statistics::Difference> difference;
  double p = 1.0;  // the claim's own test: Welch's (or the prediction interval's) two-sided p, or
                   // for an equality claim the two one-sided tests' p
  double p_adjusted = 1.0;
  std::string status;
  std::optional<int> seeds_needed;
};

// What the family's runs cost (issue 59 item 4, core-hours per resolved claim): each distinct run
// read, excluded ones included, at the engine's wall time its manifest records (the stages'
// wall_seconds times the engine's processes). A lower bound: a resumed stage records its last
// attempt only, and a consolidation taken from the cache the copy, not the consolidation once run.
struct FamilyCost {
  int runs = 0;                 // distinct runs read
  int runs_without_record = 0;  // no manifest.json with stages: not counted
  double core_hours = 0.0;
};

struct ClaimsReport {
  ClaimsFile file;
  std::vector<ClaimResult> results;
  FamilyCost cost;
};

// Reads every run (InputError naming the run and the pointer when a value is missing or not a
// number, or a pattern matching no run), tests each claim and controls the family.
ClaimsReport test_claims(const ClaimsFile& file);

// A run's engine core-hours from its manifest.json; nullopt without one or without stages.
std::optional<double> engine_core_hours(const std::filesystem::path& run);
// The same from a manifest already read.
std::optional<double> engine_core_hours(const nlohmann::json& manifest);

nlohmann::json to_json(const ClaimsReport& report);
// The table a README shows: one row per claim, the family's control in a line above it.
std::string markdown(const ClaimsReport& report);

// The README's generated block: between "<!-- BEGIN claims: NAME -->" and "<!-- END claims -->".
// InputError when the README has no such block.
std::string readme_with_block(const std::filesystem::path& readme, const std::string& name,
                              const std::string& block);

}  // namespace iwb::claims
