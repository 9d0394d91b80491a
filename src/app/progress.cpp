#include "app/progress.hpp"

#include <fmt/core.h>

#include <chrono>
#include <memory>

namespace iwb::app {

std::function<void(long, long)> increment_progress(const std::string& what) {
  auto start =
      std::make_shared<std::chrono::steady_clock::time_point>(std::chrono::steady_clock::now());
  auto last = std::make_shared<double>(1.0);
  return [start, last, what](long done, long total) {
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - *start).count();
    if (t < *last && done < total) return;
    *last = t + 1.0;
    if (t < 1.0) return;
    const double eta = done > 0 ? t * double(total - done) / double(done) : 0.0;
    fmt::print(stderr, "  {} {}/{} ({:.0f} %), {:.0f} s elapsed, ETA {:.0f} s\n", what, done, total,
               100.0 * double(done) / double(total), t, eta);
  };
}

std::function<void(const std::string&)> engine_progress() {
  auto last = std::make_shared<std::chrono::steady_clock::time_point>();
  auto kind = std::make_shared<std::string>();
  return [last, kind](const std::string& line) {
    const auto now = std::chrono::steady_clock::now();
    const std::string k = line.substr(0, line.find(':'));
    if (k == *kind && now - *last < std::chrono::seconds(2)) return;
    *last = now;
    *kind = k;
    fmt::print(stderr, "  {}\n", line);
  };
}

std::function<void(const std::string&)> sparse_engine_progress() {
  auto last =
      std::make_shared<std::chrono::steady_clock::time_point>(std::chrono::steady_clock::now());
  return [last](const std::string& line) {
    if (std::chrono::steady_clock::now() - *last < std::chrono::seconds(3)) return;
    *last = std::chrono::steady_clock::now();
    print_progress_line(line);
  };
}

void print_progress_line(const std::string& line) {
  fmt::print(stderr, "  {}\n", line);
}

}  // namespace iwb::app
