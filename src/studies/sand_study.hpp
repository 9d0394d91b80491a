#pragma once
// The sand study, `iwb run`'s default: the continuum half of the validation, hvwe against its 3D
// reference vw3d in simple shear under CNL, CNS and CV at 100 kPa (seed Table 5.1), one run
// directory each and a table of their differences.
#include <array>
#include <filesystem>
#include <functional>
#include <string>

namespace iwb::studies {

// The embedded test, with {model} and {boundary} placeholders.
extern const char* const kDefaultElementTest;

// One boundary's line of the table: hvwe's curve, and how far vw3d's is from it.
struct SandRow {
  std::string boundary;                   // CNL, CNS or CV
  double peak = 0.0, last = 0.0;          // hvwe's peak and end tau/sigma_n
  double sigma_last = 0.0, e_last = 0.0;  // hvwe's end sigma_n (kPa) and void ratio
  // max |hvwe - vw3d| along the path of tau, sigma_n, sigma_p (kPa) and e
  std::array<double, 4> differences{};
  std::string status;  // of the boundary's last run (vw3d)
};

// Runs both models under each boundary into OUT/<model>-<BC>/, gives each boundary's row to
// `on_row` as it is done and writes OUT/summary.json. True when every run completed.
bool run_sand_study(const std::filesystem::path& out, bool force, const std::string& command_line,
                    const std::function<void(const SandRow&)>& on_row);

}  // namespace iwb::studies
