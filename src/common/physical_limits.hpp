#pragma once
// Largest values an input may take before it is taken for a typo or a units mistake (the model's
// own domain checks, e.g. e0 in (e_d, e_i), come on top). One place, so that a test file, a
// command-line option, a scene and a model's declaration refuse the same values.
namespace iwb {

inline constexpr double kMaxStressKPa = 1e5;  // 100 MPa: far beyond grain crushing
inline constexpr double kMaxVoidRatio = 10.0;
inline constexpr double kMaxK0 = 10.0;  // lateral stress ratio sigma_p / sigma_n

}  // namespace iwb
