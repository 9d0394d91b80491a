#include "models/external/external_model.hpp"

#include <dlfcn.h>
#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <memory>
#include <regex>

#include "common/errors.hpp"

namespace iwb::models {

namespace {

using UmatEntry = void (*)(double*, double*, double*, const double*, const double*, const int*,
                           const double*, const int*, double*);

constexpr int kMaxStatev = kMaxStateSize - 6;  // stress (3) and total strain (3) come first
constexpr int kListingOrder = 1000;            // after every built-in model

// State: [T_n, tau_x, tau_y, eps_n, gamma_x, gamma_y, statev...]: the stress (tension positive,
// every model's component 0), the total strain the UMAT is given as STRAN, the user's variables.
enum : int { kTn = 0, kStrain = 3, kStatev = 6 };

struct Library {
  std::shared_ptr<void> handle;
  UmatEntry entry = nullptr;
};

Library open(const std::string& path, const std::string& name) {
  void* h = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (h == nullptr) throw InputError(fmt::format("--model-lib {}: {}", path, dlerror()));
  Library lib{std::shared_ptr<void>(h, [](void* p) { dlclose(p); })};
  for (const std::string& symbol : {name, name + "_"})
    if (void* f = dlsym(h, symbol.c_str())) {
      lib.entry = reinterpret_cast<UmatEntry>(f);
      return lib;
    }
  throw InputError(fmt::format("--entry {}: no symbol '{}' (or '{}_', gfortran's) in {}", name,
                               name, name, path));
}

class ExternalModel final : public Model {
 public:
  ExternalModel(std::string name, Library lib, std::vector<double> props, int nstatv)
      : name_(std::move(name)), lib_(std::move(lib)), props_(std::move(props)), nstatv_(nstatv) {}

  std::string_view name() const override { return name_; }
  int state_size() const override { return kStatev + kMaxStatev; }
  std::vector<std::string> state_names() const override {
    std::vector<std::string> n{"T_n", "tau_x", "tau_y", "eps_n", "gamma_x", "gamma_y"};
    for (int i = 1; i <= kMaxStatev; ++i) n.push_back(fmt::format("statev_{}", i));
    return n;
  }
  // The user's state variables start at zero.
  StateVector initial_state(const InitialState& in) const override {
    StateVector s = StateVector::Zero(state_size());
    s(kTn) = -in.sigma_n;
    return s;
  }
  bool updates_by_increment() const override { return true; }
  void update(const StateVector& s, const InterfaceStrain& d, StateVector& out) const override {
    double ddsdde[9];
    call(s, {d.eps_n, d.gamma_x, d.gamma_y}, out, ddsdde);
  }
  // The stress carries DDSDDE's derivative; the user's variables none (the UMAT does not give it).
  void update(const StateVectorT<Dual>& s, const InterfaceStrainT<Dual>& d,
              StateVectorT<Dual>& out) const override {
    const StateVector values = values_of<Dual>(s);
    StateVector end;
    const Dual du[3] = {d.eps_n, d.gamma_x, d.gamma_y};
    double ddsdde[9];
    call(values, {value_of(du[0]), value_of(du[1]), value_of(du[2])}, end, ddsdde);
    out = end.cast<Dual>();
    for (int i = 0; i < 3; ++i) {
      double derivative = derivative_of(s(kTn + i));
      for (int j = 0; j < 3; ++j) derivative += ddsdde[i + 3 * j] * derivative_of(du[j]);
      out(kTn + i).derivatives()(0) = derivative;
      out(kStrain + i).derivatives()(0) = derivative_of(s(kStrain + i)) + derivative_of(du[i]);
    }
  }
  // The rate form for the callers that ask for one (the closed-form mixed control): the response to
  // a small increment along d, per unit of it.
  void rate(const StateVector& s, const InterfaceStrain& d, StateVector& ds) const override {
    rate_of(s, d, ds);
  }
  void rate(const StateVectorT<Dual>& s, const InterfaceStrainT<Dual>& d,
            StateVectorT<Dual>& ds) const override {
    StateVectorT<Dual> end;
    const double h = kRateStep;
    update(s, {d.eps_n * h, d.gamma_x * h, d.gamma_y * h}, end);
    ds = (end - s) / h;
  }
  InterfaceStress stress(const StateVector& s) const override {
    return {-s(kTn), std::nullopt, s(kTn + 1), s(kTn + 2)};
  }
  double void_ratio(const StateVector&) const override { return std::nan(""); }
  std::string domain_violation(const StateVector& s) const override {
    return s.allFinite() ? "" : "non-finite state";
  }
  StateVector error_scale(const StateVector& s) const override {
    StateVector e = StateVector::Constant(s.size(), 1e-3);
    e.head(3).setConstant(std::max(1.0, std::abs(s(kTn))));
    return e;
  }
  std::vector<NamedValue> diagnostics(const StateVector&) const override { return {}; }
  bool has_second_shear_direction() const override { return true; }

 private:
  static constexpr double kRateStep = 1e-8;

  void call(const StateVector& s, const std::array<double, 3>& dstran, StateVector& out,
            double* ddsdde) const {
    out = s;
    double stress[3] = {s(kTn), s(kTn + 1), s(kTn + 2)},
           stran[3] = {s(kStrain), s(kStrain + 1), s(kStrain + 2)};
    std::vector<double> statev(s.data() + kStatev, s.data() + kStatev + nstatv_);
    statev.reserve(1);  // a valid pointer even for nstatv = 0
    const int nprops = int(props_.size());
    double pnewdt = 1.0;
    lib_.entry(stress, statev.data(), ddsdde, stran, dstran.data(), &nstatv_, props_.data(),
               &nprops, &pnewdt);
    if (pnewdt < 1.0)
      throw DomainError(
          fmt::format("{}: the model asks for a smaller increment (PNEWDT = {:g})", name_, pnewdt));
    for (int i = 0; i < 3; ++i)
      out(kTn + i) = stress[i], out(kStrain + i) = s(kStrain + i) + dstran[i];
    for (int i = 0; i < nstatv_; ++i) out(kStatev + i) = statev[i];
  }
  void rate_of(const StateVector& s, const InterfaceStrain& d, StateVector& ds) const {
    StateVector end;
    update(s, {d.eps_n * kRateStep, d.gamma_x * kRateStep, d.gamma_y * kRateStep}, end);
    ds = (end - s) / kRateStep;
  }

  std::string name_;
  Library lib_;
  std::vector<double> props_;
  int nstatv_;
};

// The [external] table of a parameter file: nstatv and the PROPS p1 (or p01), p2, ... by number.
struct Props {
  int nstatv = 0;
  std::vector<double> values;
};

Props props_of(const ModelInputs& in) {
  const auto& v = require_table(in, "external");
  const std::string where = in.source + " [external]";
  Props out;
  std::vector<std::pair<int, double>> numbered;
  const std::regex prop("p([0-9]+)");
  for (const auto& [key, value] : v) {
    std::smatch m;
    if (key == "nstatv") {
      if (!(value >= 0.0 && value <= kMaxStatev && value == std::round(value)))
        throw InputError(
            fmt::format("{}: nstatv = {:g}; an integer in [0, {}]", where, value, kMaxStatev));
      out.nstatv = int(value);
    } else if (std::regex_match(key, m, prop)) {
      numbered.push_back({std::stoi(m[1].str()), value});
    } else {
      throw InputError(fmt::format(
          "{}: unknown key '{}'; [external] takes nstatv and p1 (or p01), p2, ... (PROPS)", where,
          key));
    }
  }
  std::sort(numbered.begin(), numbered.end());
  for (std::size_t i = 0; i < numbered.size(); ++i) {
    if (numbered[i].first != int(i) + 1)
      throw InputError(
          fmt::format("{}: the PROPS p1, p2, ... must have no gap (p{} missing)", where, i + 1));
    out.values.push_back(numbered[i].second);
  }
  return out;
}

// Every slot of state variables is declared (the layout is fixed before a parameter file is read);
// the UMAT sees the first nstatv, the others stay 0.
ModelDeclaration declaration() {
  ModelDeclaration d;
  d.listing_order = kListingOrder;
  d.layout.components = {
      {"T_n", "kPa", ComponentKind::kStress},      {"tau_x", "kPa", ComponentKind::kStress},
      {"tau_y", "kPa", ComponentKind::kStress},    {"eps_n", "-", ComponentKind::kHardening},
      {"gamma_x", "-", ComponentKind::kHardening}, {"gamma_y", "-", ComponentKind::kHardening}};
  for (int i = 1; i <= kMaxStatev; ++i)
    d.layout.components.push_back({fmt::format("statev_{}", i), "-", ComponentKind::kHardening});
  d.layout.void_ratio = -1;
  d.initial = {
      {"sigma_n_kPa", "kPa",
       "initial normal stress (compression positive); the user's state variables start at 0"}};
  d.update = StressPointUpdate::kIncrement;
  d.example_start = {{"sigma_n_kPa", 100.0}};
  return d;
}

}  // namespace

ModelSpec external_model_spec(const std::string& library, const std::string& entry) {
  const Library lib = open(library, entry);
  return {
      entry,
      fmt::format("a user's model: {} in {} (UMAT-style entry point, --model-lib)", entry, library),
      "the user's",
      false,
      {},
      [lib, entry](const ModelInputs& in) {
        const Props p = props_of(in);
        return std::unique_ptr<Model>(
            std::make_unique<ExternalModel>(entry, lib, p.values, p.nstatv));
      },
      declaration()};
}

}  // namespace iwb::models
