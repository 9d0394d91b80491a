#pragma once
// The soil-test run-directory contract (README.md here): element tests on the soil alone, from a
// DEM cell or a continuum model, that the hypoplastic parameters are calibrated against.
//   manifest.json   kind "soiltest", test "oedometer" | "simpleshear" | "cyclicshear", initial
//                   state, source
//   timeseries.csv  named, unit-carrying columns; compression positive (CONVENTIONS.md)
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "driver/control.hpp"

namespace iwb::soil_test {

// kCyclicShear: simple shear whose gamma reverses (cycles 0 -> +A -> -A -> 0), the test the
// intergranular strain's parameters are calibrated on (issue 34).
enum class SoilTestKind { kOedometer, kSimpleShear, kCyclicShear };

const char* to_string(SoilTestKind k);
// The kind of a name as to_string writes it; InputError naming `where` otherwise.
SoilTestKind soil_test_kind(const std::string& name, const std::string& where);
// Simple shear, monotonic or cyclic: rows gamma, tau_kPa, sigma_n_kPa, e under CNL or CV.
inline bool is_shear(SoilTestKind k) {
  return k != SoilTestKind::kOedometer;
}

// What one unit of a residual is worth, per quantity, in the quantity's own unit: the scatter of
// the measurement. 0: the declared scales of calibrate.hpp. Set from the seed scatter when the
// same test was run with several seeds (seed_scatter.hpp).
struct ResidualScales {
  double tau_kPa = 0.0, sigma_n_kPa = 0.0, e = 0.0;
  double dilatancy_rate = 0.0;  // of the peak d eps_n / d gamma (CNL shear; objectives.hpp)
  int replicates = 1;           // tests of this design the scatter was measured over
};

struct SoilTest {
  std::string name;  // the directory it was read from or is written to (messages, reports)
  SoilTestKind kind = SoilTestKind::kOedometer;
  driver::BoundaryKind boundary = driver::BoundaryKind::kCNL;  // simple shear: CNL or CV
  double sigma0_kPa = 0.0;  // sigma_v0 (oedometer) or sigma_n0 (simple shear)
  double e0 = 0.0;
  double K0 = 0.0;       // lateral / vertical stress at the start; 0 = not given: 1 - sin(phi_c)
  std::string source;    // "dem:<engine>" or "synthetic:<model>"
  std::string specimen;  // how it was prepared, if the manifest says ("dense", "loose"; DEM cells)
  int seed = 0;          // the DEM seed, if the manifest says (0: not given)
  ResidualScales scales;
  nlohmann::json source_parameters = nlohmann::json::object();  // what a synthetic source used
  // A periodic DEM cell that localised (its manifest's profile windows,
  // dem/soil_cells/soil_cell.hpp): the gamma of the end of its last homogeneous window, beyond
  // which its rows are a band's and are not read; 0 when the whole test is an element's.
  // rows_in_file counts every row.
  double element_until = 0.0;
  std::size_t rows_in_file = 0;

  // One entry per row of timeseries.csv. Oedometer: sigma_kPa = sigma_v (the control), e and
  // eps_v measured. Simple shear: gamma (the control), tau_kPa, sigma_kPa = sigma_n, e measured.
  // Cyclic shear: the same, gamma reversing at the amplitudes.
  std::vector<double> control;  // sigma_v_kPa (oedometer) or gamma (simple shear)
  std::vector<double> e, eps_v, tau_kPa, sigma_n_kPa;
  // Written after the contract's columns, not read back (a DEM cell's sigma_h, K0, coordination).
  std::vector<std::pair<std::string, std::vector<double>>> extra_columns;

  std::size_t rows() const { return control.size(); }
  // Index of the largest sigma_v: the end of the loading branch (oedometer).
  std::size_t loading_end() const;
};

// Reads and validates a soil-test directory. InputError naming the file (and line, key, value)
// for: a missing file, a wrong or missing manifest key, a missing column, a non-number or NaN,
// fewer than kMinimumRows rows, and a control that is not monotonic (gamma must increase;
// sigma_v must increase to its maximum and then, if unloaded, decrease; cyclic gamma must change
// from row to row and reverse at least once).
// A periodic DEM cell whose shear localised is read up to the end of its last homogeneous profile
// window only (element_until); one that localised from its first window, or too early to leave
// kMinimumRows, has no element to read: NotAnElement.
SoilTest read_soil_test(const std::filesystem::path& dir);

// A well-formed test that is no element test: its cell localised before it had rows to give. A
// calibration of many tests leaves it out and says so (calibration_run.hpp).
class NotAnElement : public InputError {
 public:
  using InputError::InputError;
};

// A DEM cell sheared homogeneously where the R^2 of a straight line through its velocity profile
// (vx/v_wall against height) is at least this in a profile window (dem/soil_cells/soil_cell.cpp).
inline constexpr double kHomogeneousCellR2 = 0.9;

// The gamma up to which a periodic cell sheared homogeneously: the end of the last profile window
// before its velocity profile bends (R^2 below the manifest's homogeneous_r2_threshold) in two
// windows running, or in the last one; a lone bent window between straight ones is taken for
// noise. 0 when it never bends so (or the manifest is not a periodic cell's simple shear), -1 when
// it does from the first window.
double element_until_gamma(const nlohmann::json& manifest);

inline constexpr std::size_t kMinimumRows = 3;

// A shear test is at critical state when over its last fifth tau/sigma_n changes by less than
// kCriticalRatioChange and e by less than kCriticalVoidChange.
inline constexpr double kCriticalRatioChange = 0.01;
inline constexpr double kCriticalVoidChange = 0.002;
bool ends_at_critical_state(const SoilTest& test);

// Writes manifest.json and timeseries.csv atomically (io/run_directory). `extra` is merged into
// the manifest (command line, workbench version, timing).
void write_soil_test(const SoilTest& test, const std::filesystem::path& dir, bool force,
                     const nlohmann::json& extra);
// The same into a directory the caller has prepared (a DEM cell's run directory, which holds the
// engine's work files and a manifest with status "running" until this replaces it).
void write_soil_test_files(const SoilTest& test, const std::filesystem::path& dir,
                           const nlohmann::json& extra);

}  // namespace iwb::soil_test
