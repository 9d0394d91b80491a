#pragma once
// The measurement scatter of soil tests run with several seeds. A DEM soil test is one packing;
// the same test with another seed differs by as much as the packing matters, and a calibration
// that weighs every row by one declared scatter (0.01 sigma0, 0.002 in e) lets the least
// repeatable tests decide the fit: a dense cell sheared at constant volume reaches 1-2 MPa from
// 200 kPa, and its seeds differ there by ~100 kPa, fifty declared units.
#include <vector>

#include "soil_test/soil_test.hpp"

namespace iwb::calibration {

// Replicates: tests of one design (kind, boundary, sigma0, specimen, source) from different seeds.
bool same_design(const soil_test::SoilTest& a, const soil_test::SoilTest& b);

// For each design run with at least two seeds, sets every member's `scales` to the RMS over rows
// (row by row, from the first row after the start, up to the shortest member) of the sample
// standard deviation across the seeds, per quantity, never below the declared scale
// (calibrate.hpp); for CNL shear also the sample SD of the peak dilatancy rate across the seeds
// (objectives.hpp), never below kDilatancyRateScale. Tests run once keep the declared scales.
void measure_seed_scatter(std::vector<soil_test::SoilTest>& tests);

}  // namespace iwb::calibration
