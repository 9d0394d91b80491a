#pragma once
// A pile load-transfer analysis (`iwb pile`, README.md here) as data: the pile, the soil around it,
// the base, the interface model at the shaft and the head's loading, read from a TOML file.
#include <toml++/toml.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace iwb::pile {

struct PileGeometry {
  double length_m = 0.0;
  double diameter_m = 0.0;
  double EA_kN = 0.0;  // axial stiffness
  int elements = 0;    // along the shaft; one interface stress point at each element's middle
};

struct SoilProfile {
  double unit_weight_kN_m3 = 0.0;  // effective: sigma_v = gamma' z
  double K0 = 0.0;                 // sigma_h0 = K0 sigma_v: the shaft's initial normal stress
  double shear_modulus_kPa = 0.0;  // G: the cavity's normal stiffness K = 4G/D (Boulon & Foray)
};

struct InterfaceSpec {
  std::string model;
  std::filesystem::path parameters;
  double kappa_r = 1.0;  // the default when [interface] gives none: a fully rough shaft
  double d_s_mm = 0.0;   // the virtual thickness d_s^v (seed 7.1)
  std::map<std::string, double> initial;  // the model's other [initial] inputs (e0, OCR, delta...)
};

// kCyclicSettlement: the head displaced 0 -> +A -> -A -> 0 `cycles` times, as the DEM's cyclic
// interface cells are (issue 34, item 6): the shaft's friction fatigue under displacement cycles.
enum class LoadingKind { kSettlement, kCyclicLoad, kCyclicSettlement };

struct Loading {
  LoadingKind kind = LoadingKind::kSettlement;
  double settlement_mm = 0.0;  // kSettlement: the head pushed to this settlement
  int increments = 0;
  double mean_kN = 0.0, amplitude_kN = 0.0;  // kCyclicLoad: head load mean +- amplitude
  double amplitude_mm = 0.0;                 // kCyclicSettlement: head settlement +- amplitude
  int cycles = 0, increments_per_quarter = 0;
  // the head's settlement is prescribed (kSettlement, kCyclicSettlement), else its load
  bool settlement_given() const { return kind != LoadingKind::kCyclicLoad; }
  std::vector<double> profile_loads_kN;  // profiles written where the head load first reaches these
};

struct PileSpec {
  std::string source;  // the file, for messages
  std::string description;
  PileGeometry pile;
  SoilProfile soil;
  double base_stiffness_kN_per_mm = 0.0;
  InterfaceSpec interface;
  Loading loading;
};

// InputError naming the file, the key and the value for anything missing, unknown or out of range.
PileSpec load_pile_spec(const std::filesystem::path& file);
PileSpec parse_pile_spec(const toml::table& root, const std::string& source,
                         const std::filesystem::path& base_dir);

}  // namespace iwb::pile
