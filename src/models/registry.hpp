#pragma once
// The list of models the workbench knows. Adding a model: one folder under src/models/ whose
// register.cpp names its specs (IWB_REGISTER_MODELS); nothing outside the folder changes.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "models/declaration.hpp"
#include "models/model.hpp"
#include "models/parameters.hpp"
#include "models/roughness/roughness.hpp"

namespace iwb::models {

// The interface model a comparison, a form limit, a set of runs or a sweep's [compare] replays
// unless told another: the seed's enhanced model (issue 58: written once).
inline constexpr const char* kDefaultInterfaceModel = "hvwe";

// What a model is built from: parameter tables by TOML table name, where they came from (for
// messages), and the wall roughness (interface models only).
struct ModelInputs {
  std::map<std::string, ParameterValues> tables;
  std::string source;
  Roughness roughness;
  // The element's shear-zone thickness d_s (mm): what a model whose stiffness is per unit
  // displacement (hyperbolic, eq. 3.49) scales by to act on strains. Element tests set it from
  // [shear_zone], the replay per variant; elsewhere (stability map, benches) 1 mm, u = gamma.
  double shear_zone_mm = 1.0;
  // The grains' mean diameter where the caller knows it (a DEM run, an element test's
  // [shear_zone] d50_mm): a model with a length in grain diameters reads it (issue 56).
  std::optional<double> d50_mm = {};
};

struct ModelSpec {
  std::string name;
  std::string summary;
  std::string equations;  // seed equations it implements
  bool uses_roughness;
  std::vector<const ParameterTable*> tables;
  std::function<std::unique_ptr<Model>(const ModelInputs&)> make;
  // What the rest of the workbench may know of the model (declaration.hpp).
  ModelDeclaration declaration = {};
  // The folder under src/models/ whose register.cpp registers it, set by the registry (a folder
  // need not name itself): where its README and gold files are. Empty for a model added at run
  // time.
  std::string folder = {};
};

// Why a declaration is inconsistent (state over kMaxStateSize, component 0 not the normal stress,
// names not unique, indices out of range or of the wrong kind, roughness flag and schemes
// disagreeing); empty when it is consistent. The registry refuses such a model (std::logic_error).
std::string declaration_problem(const ModelSpec& spec);

// The models as their folders register them (register_all_models, generated from
// src/models/*/register.cpp). `add` only collects: the declarations are checked and ordered once
// all are in (model_registry()).
class ModelRegistry {
 public:
  // The generated code calls each folder's registration through this, so that every spec knows
  // its folder without the folder repeating its own name.
  void register_folder(std::string folder, void (*register_models)(ModelRegistry&)) {
    folder_ = std::move(folder);
    register_models(*this);
    folder_.clear();
  }
  void add(ModelSpec spec) {
    spec.folder = folder_;
    specs_.push_back(std::move(spec));
  }
  std::vector<ModelSpec> take() { return std::move(specs_); }

 private:
  std::vector<ModelSpec> specs_;
  std::string folder_;
};

// Generated: calls register_<folder>() of every model folder.
void register_all_models(ModelRegistry& registry);

// In a model folder's register.cpp, the one registration of its models:
//   IWB_REGISTER_MODELS(hvwe, hvwe_spec(), hvwe_igs_spec())
// defines register_hvwe(); the first argument is the folder's name as a C identifier.
#define IWB_REGISTER_MODELS(folder, ...)                                                  \
  void register_##folder(ModelRegistry& registry) {                                       \
    for (auto& spec : std::vector<ModelSpec>{__VA_ARGS__}) registry.add(std::move(spec)); \
  }

// Every registered model, checked (declaration_problem) and in listing order.
const std::vector<ModelSpec>& model_registry();
// Throws InputError listing the known names.
const ModelSpec& find_model(const std::string& name);
// The interface models for granular scenes (ModelDeclaration::plan_rank > 0), simplest first;
// those with intergranular strain only when `with_intergranular_strain` (it acts on reversals).
std::vector<std::string> ranked_interface_models(bool with_intergranular_strain);
// The same, for a command's help: "mc, hyperbolic, ...; ahe-igs and hvwe-igs for reversing paths".
std::string ranked_interface_models_text();
// Adds a model at run time (a user's library, models/external): checked like the registered ones;
// InputError for an inconsistent declaration or a name already taken. Before any thread starts.
void add_runtime_model(ModelSpec spec);

// phi_c (rad) of the parameter the model declares in the role kCriticalFrictionAngle, from its
// own tables (never another model's table in the same file); NaN if it declares none.
double critical_friction_angle(const ModelSpec& spec, const ModelInputs& inputs);

// Puts a declared number input into an InitialState: the shared members, else `named`.
void set_initial_input(InitialState& s, const std::string& key, double value);

// Puts a declared vector input into an InitialState (the intergranular strain's "delta").
void set_initial_vector(InitialState& s, const std::string& key, const std::array<double, 3>& v);

// The initial state a caller that does not know the model offers it (the DEM replay, the soil-test
// simulation, the stability map, the benches): each offered value the model declares, every other
// declared number at its default (K0 = 1 - sin phi_c for sand; a fixed value always). Values the
// model does not declare are dropped (a replay offers e0 to every model alike).
InitialState offer(const ModelSpec& spec, const ModelInputs& inputs,
                   std::initializer_list<std::pair<std::string, double>> values);

// The parameter table `name` of `inputs`; InputError if the file has no such table.
const ParameterValues& require_table(const ModelInputs& inputs, const std::string& name);

}  // namespace iwb::models
