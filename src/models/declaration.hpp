#pragma once
// What a model declares of itself for the rest of the workbench (src/models/README.md, "The model
// contract", sections 2.2-2.7): its state layout, the inputs of its initial state, the external
// variables it reads, its diagnostics, how wall roughness enters it and which of its parameters
// `iwb compare` may fit. Declarations are data; the physics stays in the model's C++. Consumers
// read these instead of asking a model's or a table's name.
#include <array>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/range.hpp"
#include "models/model.hpp"
#include "models/parameters.hpp"
#include "models/roughness/roughness.hpp"

namespace iwb::models {

struct ModelInputs;
struct ModelSpec;

// ---- 2.2 State layout ----

enum class ComponentKind { kStress, kVoidRatio, kHardening, kIntergranularStrain, kExternal };

struct StateComponent {
  std::string
      name;  // as manifest.json "state_variables" and messages name it: "T_n", "e", "delta_x"
  std::string unit;  // "kPa", "-", "K"
  ComponentKind kind;
};

struct StateLayout {
  std::vector<StateComponent> components;
  int void_ratio = -1;  // index of e; -1: the model has none (Mohr-Coulomb, Clough & Duncan)
  // Per External slot, the state component holding its current value; -1: not read.
  std::array<int, kExternalSlots> external{-1, -1, -1};

  int size() const { return int(components.size()); }
  std::vector<std::string> names() const;
};

// ---- 2.3 Inputs of the initial state ----

// One input of the initial state as a test file's [initial] table names it.
struct InitialInputSpec {
  enum class Kind { kNumber, kVector3, kKeywordOrVector3, kChoice };
  // kFixed: the model's kinematics fix the value (AH's K0 = 1, eq. 5.16); a value given in a file
  // is ignored with a warning, the default is what the manifest records.
  enum class Need { kRequired, kOptional, kOneOf, kFixed };
  std::string key;  // "sigma_n_kPa", "K0", "e0", "OCR", "T_K", "s_kPa", "delta"
  std::string unit;
  std::string doc;
  Kind kind = Kind::kNumber;
  Need need = Need::kRequired;
  std::string group = {};    // Need::kOneOf: the inputs of which exactly one is given ("density")
  Range range = positive();  // beyond it a value is a typo or a units mistake (common/range.hpp)
  std::vector<std::string> choices = {};  // kChoice and keywords: "seed"
  // The value when absent, from the model's parameters (K0 = 1 - sin phi_c); empty: no default.
  std::function<double(const ModelInputs&)> default_value = {};
  // kKeywordOrVector3: the vector the keyword (choices[0]) names, which is also the default, and
  // what it is, for the manifest. A vector's size is checked against `range` in units of a scale
  // its parameters set (the intergranular strain's ||delta|| <= 2 R). Declared by the model, so
  // that a test file's reader knows nothing of what the vector is.
  std::function<std::array<double, 3>(const ModelInputs&)> default_vector = {};
  std::string default_origin = {};
  std::string scale_name = {};  // "R"
  std::function<double(const ModelInputs&)> scale = {};
  std::function<double(const std::array<double, 3>&)> norm = {};
};

// The declared input `key` of a declaration, or nullptr.
const InitialInputSpec* find_initial_input(const std::vector<InitialInputSpec>& inputs,
                                           const std::string& key);

// ---- 2.4 External variables ----

struct ExternalVariableSpec {
  External which;
  std::string key;  // as a test file's stage names it: "T_K", "s_kPa", "t_s"
  std::string unit;
  std::string doc;
};

// ---- 2.5 Diagnostics ----

// What the workbench may read a diagnostic for; the others are history.csv columns only.
enum class DiagnosticRole {
  kNone,
  kMeanStress,
  kMinVoidRatio,       // e_d
  kCriticalVoidRatio,  // e_c
  kMaxVoidRatio,       // e_i
  kEquivalentPressure,
  kOverconsolidation,
  kYieldFunction,
  kIntergranularRho,
};

struct DiagnosticSpec {
  std::string name;  // history.csv column, in the order Model::diagnostics() returns them
  std::string unit;
  std::string doc;
  DiagnosticRole role = DiagnosticRole::kNone;
};

// ---- 2.6 Roughness and the parameters `iwb compare` may fit ----

enum class KappaFromAngle { kNone, kTangentRatio /* eq. 5.36 */, kAngleRatio /* eq. 6.21 */ };

struct RoughnessSupport {
  std::vector<RoughnessScheme> schemes;  // empty: a continuum model; [roughness] is refused
  RoughnessScheme default_scheme = RoughnessScheme::kGutjahr;
  bool from_normalized_roughness = false;  // eq. 5.35 (Gutjahr, granular) allowed
  KappaFromAngle from_angle = KappaFromAngle::kNone;
  // The model reads the wall's R_n itself (Roughness::R_n), beside kappa_r: an element test must
  // give [roughness] R_n, never kappa_r alone (issue 56).
  bool reads_normalized_roughness = false;
  // It reads the wall's mean |slope| (Roughness::mean_abs_slope) and the grains' d50: an element
  // test must give [roughness] mean_abs_slope and [shear_zone] d50_mm.
  bool reads_mean_slope = false;

  // The declared scheme called `name` ("gutjahr", ...), nullopt if the model declares none such.
  std::optional<RoughnessScheme> scheme_named(const std::string& name) const;
  // The declared schemes' names, quoted and joined by `separator`, for messages.
  std::string scheme_names(const std::string& separator) const;
  // Whether Arnold & Herle's rate factor f_c (eq. 5.40, ERRATA 9) applies: their sand scheme only.
  bool reads_arnold_herle_factor(RoughnessScheme scheme) const {
    return scheme == RoughnessScheme::kArnoldHerle && from_normalized_roughness;
  }
};

// What a prediction may use of a DEM run: a plain struct, so models/ does not depend on
// comparison/.
struct WallDescription {
  double R_n = 0.0;  // normalized roughness, 0 for a flat wall
  double d50_mm = 0.0;
};

// A quantity `iwb compare` fits to a DEM run, where it goes, its box and its prediction without a
// fit.
struct FitParameter {
  enum class Target { kRoughness, kShearZone, kParameter };
  std::string name;  // compare.json key: "kappa_r", "d_s_mm"
  Target target;
  std::string table = {}, key = {};  // Target::kParameter: where in ModelInputs::tables
  double lower = 0.0, upper = 0.0;   // the box; in d50 when per_d50
  bool per_d50 = false;
  bool logarithmic = false;  // fitted as ln x
  // The variant that needs no fit, with a word on where it comes from; empty: the file's value.
  std::function<std::pair<double, std::string>(const WallDescription&)> predict = {};
};

// ---- 2.7 How the stress point is updated ----

enum class StressPointUpdate {
  kRate,       // the integrator integrates rate() over the increment
  kIncrement,  // the model integrates its own increment (a return mapping)
};

// The declaration proper, a member of ModelSpec. Kept apart so that ModelSpec's first six members
// stay positional for the folders that initialise them.
struct ModelDeclaration {
  int listing_order = 0;  // `iwb models` and "known models: ..." follow it
  StateLayout layout;
  std::vector<InitialInputSpec> initial;
  std::vector<ExternalVariableSpec> externals;
  std::vector<DiagnosticSpec> diagnostics;
  RoughnessSupport roughness;
  std::vector<FitParameter> fit;
  StressPointUpdate update = StressPointUpdate::kRate;
  bool second_shear_direction = true;  // false: one shear direction (hp1d)
  std::string calibration_recipe;      // "herle-gudehus" (sand); empty: a joint fit over the boxes
  // Its stiffnesses are per displacement and it reads d_s (ModelInputs::shear_zone_mm) to turn
  // the element's strains back into displacements: its (u, tau, u_n) response does not depend on
  // d_s, which a fit to interface runs therefore leaves alone (Clough & Duncan, Mortara).
  bool displacement_based = false;
  // Only its monotonic part is built (Mortara's outer surface, without the inner surface that
  // acts where the path reverses): `iwb compare` refuses it on a cyclic run.
  bool monotonic_only = false;
  std::string example_parameters;  // a file of data/params/: bench, stability, gold, tests
  std::map<std::string, double> example_start;  // {sigma_n_kPa: 100, e0: 0.8} for the bench
  // The interface models for granular scenes that `iwb plan` and the league of `iwb assess
  // --reference` consider, simplest first: 1, 2, ...; 0: not a candidate. Not the listing order,
  // which keeps today's `iwb models` (vw3d first).
  int plan_rank = 0;
};

}  // namespace iwb::models
