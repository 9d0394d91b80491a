#pragma once
// An allowed range of an input value, checked and printed in one place: the command line's
// validators (src/app/option_checks.hpp) and the file readers (io::TableReader::number_in) both
// use it, so a message reads the same wherever the value came from: "must be finite and in
// (0, 1e+05]". NaN and +-inf are never admitted: a value that is not finite means something went
// wrong before it reached us (a typo, a units mistake), never a setting.
#include <fmt/core.h>

#include <cmath>
#include <limits>
#include <string>

namespace iwb {

struct Range {
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool lower_open = false;  // true: the bound itself is excluded
  bool upper_open = false;

  bool admits(double v) const {
    if (!std::isfinite(v)) return false;
    return (lower_open ? v > lower : v >= lower) && (upper_open ? v < upper : v <= upper);
  }

  // "(0, 100]", "[1, inf)"; %g so that no bound prints as a 309-digit number.
  std::string text() const {
    const auto end = [](double b) {
      if (std::isinf(b)) return std::string(b > 0 ? "inf" : "-inf");
      return fmt::format("{:g}", b);
    };
    return fmt::format("{}{}, {}{}", lower_open || std::isinf(lower) ? "(" : "[", end(lower),
                       end(upper), upper_open || std::isinf(upper) ? ")" : "]");
  }

  // "must be finite and > 0", "must be finite and in [4, 100]": what a message says is allowed.
  std::string requirement() const {
    const bool no_upper = std::isinf(upper);
    if (no_upper && lower == 0.0)
      return lower_open ? "must be finite and > 0" : "must be finite and >= 0";
    if (no_upper && std::isinf(lower)) return "must be finite";
    return "must be finite and in " + text();
  }
};

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// The usual ranges.
inline Range positive(double upper = kInf) {
  return {0.0, upper, true, false};
}
inline Range non_negative(double upper = kInf) {
  return {0.0, upper, false, false};
}
inline Range closed(double lower, double upper) {
  return {lower, upper, false, false};
}

}  // namespace iwb
