#pragma once
// Physical ranges of element-test values: beyond them a value is a typo or a units mistake (the
// model's own domain checks, e.g. e0 in (e_d, e_i), come on top). The declared rows
// (element_test_keys.cpp) carry them; the reader checks the limits that involve several keys.
// (kMaxStressKPa, kMaxVoidRatio, kMaxK0: common/physical_limits.hpp)
#include "common/range.hpp"

namespace iwb::element {

inline constexpr double kMaxShearStrain = 10.0;  // 1000 % shear strain
inline constexpr double kMaxLengthMm = 1e4;      // shear-zone thickness, grain size
inline constexpr double kMaxRoughness = 100.0;   // R_n = R_max / d50
inline constexpr double kMaxSlope = 10.0;        // mean |dz/dx|: 84 degrees
inline constexpr double kMaxIncrements = 1e8;    // a path longer than this would run for hours
inline const Range kRelativeTolerance{0.0, 0.1, true, false};  // rtol, Newton tolerance

// The external variables' paths.
inline constexpr double kKelvinOffset = 273.15;
inline const Range kTemperatureK = closed(200.0, 500.0);  // -73 to 227 deg C
inline const Range kTemperatureC =
    closed(kTemperatureK.lower - kKelvinOffset, kTemperatureK.upper - kKelvinOffset);
inline const Range kSuctionKPa = closed(0.0, 1e6);
inline const Range kTimeS = closed(0.0, 1e10);
inline constexpr int kMaxStageCycles = 10000;

}  // namespace iwb::element
