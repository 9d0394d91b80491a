#pragma once
// What seed 6.4 says of the clay interface models, each claim put to the study's runs: the numbers
// and whether the claim holds for these models as implemented.
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "studies/clay_cases.hpp"

namespace iwb::studies {

struct ClayClaim {
  std::string section;   // "6.4.2 CV"
  std::string claim;     // the seed's words, shortened
  std::string measured;  // the numbers that decide it
  bool holds = false;
  nlohmann::json values;
};

// The claims, from the curves of clay_cases() by name.
std::vector<ClayClaim> clay_claims(const std::map<std::string, ClayCurve>& curves);

// max |a - b| over max |b|, row by row; infinite when the curves have different lengths.
double largest_relative_difference(const std::vector<double>& a, const std::vector<double>& b);

// Adds to `claim` the comparison of a model's reduced form `reduced` with its 3D form `three_d`,
// as values[key] and in the measured text as `label`; the claim holds only while every pair
// agrees to round-off (kSameResponse).
void add_reduced_against_3d(ClayClaim& claim, const std::string& key, const std::string& label,
                            const ClayCurve& reduced, const ClayCurve& three_d);

// d tau / d gamma over the first increment after the first reversal of a cyclic curve, and over
// its first increment from the start.
double tangent_after_first_reversal(const ClayCurve& c);
double initial_tangent(const ClayCurve& c);

}  // namespace iwb::studies
