// mcc: modified Cam clay (seed 8.3) on the reduced interface vectors [sigma_n, sigma_p, tau_x,
// tau_y] (the kinematics of hvwe: in-plane strain zero), and mcc3d on 3x3 tensors in simple shear,
// the reference the interface form is checked against. The return is modified_cam_clay.hpp's.
#include <fmt/core.h>

#include <cmath>
#include <memory>

#include "common/errors.hpp"
#include "common/physical_limits.hpp"
#include "models/hypoplastic/family.hpp"
#include "models/hypoplastic/kinematics.hpp"
#include "models/mcc/modified_cam_clay.hpp"
#include "models/registry.hpp"

namespace iwb::models {

namespace {

// After the clay hypoplastic models (10-13) and the reference interface models (20, 21).
constexpr int kListingOrder = 30;

// Where f counts as zero for the rate form: the return leaves |f| at round-off of p_c^2.
constexpr double kOnSurface = 1e-9;

const ParameterTable& cam_clay_table() {
  static const ParameterTable t{
      "modified_cam_clay",
      {{"lambda",
        "-",
        {0.0, true},
        {2.0, false},
        "slope of the isotropic normal compression line, eps_v against ln p",
        "eq. 8.20, Table 8.1"},
       {"kappa",
        "-",
        {0.0, true},
        {2.0, false},
        "slope of the unloading-reloading line, eps_v against ln p (K = p/kappa)",
        "eq. 8.19, Table 8.1"},
       {"M",
        "-",
        {0.0, true},
        {3.0, true},
        "critical state stress ratio q / p",
        "eq. 8.18, Table 8.1"},
       {"nu",
        "-",
        {0.0, false},
        {0.5, true},
        "Poisson's ratio of the elasticity (G from K)",
        "eq. 8.19, Table 8.1"}}};
  return t;
}

CamClayParameters read(const ModelInputs& in) {
  const std::string source = in.source + " [modified_cam_clay]";
  const auto& v = require_table(in, "modified_cam_clay");
  validate(cam_clay_table(), v, source);
  require_below(v, "kappa", "lambda", source, "unloading is stiffer than normal compression");
  return {v.at("lambda"), v.at("kappa"), v.at("M"), v.at("nu")};
}

// K0 = 1 - sin phi with the friction angle of M in triaxial compression: sin phi = 3M / (6 + M).
double default_K0(const ModelInputs& in) {
  const double M = require_table(in, "modified_cam_clay").at("M");
  return 1.0 - 3.0 * M / (6.0 + M);
}

template <class Kinematics>
class ModifiedCamClay final : public Model {
  using Ops = typename Kinematics::Ops;
  static constexpr int kE = Ops::kPackedSize;  // void ratio
  static constexpr int kPc = kE + 1;           // preconsolidation pressure p_c

 public:
  ModifiedCamClay(std::string name, CamClayParameters c) : name_(std::move(name)), c_(c) {}

  std::string_view name() const override { return name_; }
  int state_size() const override { return kPc + 1; }
  std::vector<std::string> state_names() const override {
    auto names = Kinematics::component_names();
    names.push_back("e");
    names.push_back("p_c");
    return names;
  }
  bool has_second_shear_direction() const override { return true; }

  // p_c = OCR times the ellipse through the initial stress: p + q^2 / (M^2 p).
  StateVector initial_state(const InitialState& init) const override {
    StateVector s(state_size());
    const auto T = kin_.initial_stress(init);
    Ops::template pack<double>(T, s, 0);
    s(kE) = init.e0;
    const CamClayInvariants<Ops, double> inv(T);
    const auto ocr = init.named.find("OCR");
    s(kPc) = (ocr == init.named.end() ? 1.0 : ocr->second) *
             (inv.p + inv.q * inv.q / (c_.M * c_.M * inv.p));
    if (const auto why = domain_violation(s); !why.empty())
      throw InputError(
          fmt::format("initial state (sigma_n0 = {:g} kPa, K0 = {:g}) is not admissible for {}: {}",
                      init.sigma_n, init.K0, name_, why));
    return s;
  }

  bool updates_by_increment() const override { return true; }
  void update(const StateVector& s, const InterfaceStrain& d, StateVector& out) const override {
    update_of(s, d, out);
  }
  void update(const StateVectorT<Dual>& s, const InterfaceStrainT<Dual>& d,
              StateVectorT<Dual>& out) const override {
    update_of(s, d, out);
  }
  void rate(const StateVector& s, const InterfaceStrain& d, StateVector& ds) const override {
    rate_of(s, d, ds);
  }
  void rate(const StateVectorT<Dual>& s, const InterfaceStrainT<Dual>& d,
            StateVectorT<Dual>& ds) const override {
    rate_of(s, d, ds);
  }

  InterfaceStress stress(const StateVector& s) const override {
    return kin_.stress(Ops::template unpack<double>(s, 0));
  }
  double void_ratio(const StateVector& s) const override { return s(kE); }

  std::string domain_violation(const StateVector& s) const override {
    if (!s.allFinite()) return "state is not finite (NaN or inf)";
    const CamClayInvariants<Ops, double> inv(Ops::template unpack<double>(s, 0));
    if (!(inv.p > kMinimumPressure_kPa))
      return fmt::format("no compression: p = {:.6g} kPa", inv.p);
    if (!(s(kPc) > 0.0)) return fmt::format("preconsolidation pressure p_c = {:.6g} kPa", s(kPc));
    if (cam_clay_yield(inv.p, inv.q, s(kPc), c_.M) > kOnSurface * 1e3 * s(kPc) * s(kPc))
      return fmt::format(
          "outside the yield ellipse: f = {:.6g} kPa^2 (p = {:.6g}, q = {:.6g}, p_c = {:.6g} kPa)",
          cam_clay_yield(inv.p, inv.q, s(kPc), c_.M), inv.p, inv.q, s(kPc));
    return {};
  }

  void flush_negligible_components(StateVector& s) const override {
    flush_negligible(s.head(Ops::kPackedSize));
  }

  StateVector error_scale(const StateVector& s) const override {
    const auto t = Ops::template unpack<double>(s, 0);
    StateVector scale = StateVector::Constant(state_size(), std::sqrt(Ops::contract(t, t)));
    scale(kE) = std::abs(s(kE));
    scale(kPc) = s(kPc);
    return scale;
  }

  std::vector<NamedValue> diagnostics(const StateVector& s) const override {
    const CamClayInvariants<Ops, double> inv(Ops::template unpack<double>(s, 0));
    return {{"mean_stress_kPa", inv.p},
            {"q_kPa", inv.q},
            {"f_yield", cam_clay_yield(inv.p, inv.q, s(kPc), c_.M) / (s(kPc) * s(kPc))},
            {"eta_over_M", inv.q / (inv.p * c_.M)}};
  }

 private:
  template <class S>
  CamClayPoint<Ops, S> point(const StateVectorT<S>& s) const {
    return {Ops::template unpack<S>(s, 0), s(kPc)};
  }

  // e on the total volumetric strain: d ln(1 + e) = tr dD, exact for the increment.
  template <class S>
  void update_of(const StateVectorT<S>& s, const InterfaceStrainT<S>& d,
                 StateVectorT<S>& out) const {
    using std::exp;
    const auto D = kin_.template stretching<S>(d);
    const auto next = cam_clay_increment<Ops, S>(point(s), D, c_);
    out = s;
    Ops::template pack<S>(next.T, out, 0);
    out(kE) = (1.0 + s(kE)) * exp(Ops::trace(D)) - 1.0;
    out(kPc) = next.p_c;
  }

  template <class S>
  void rate_of(const StateVectorT<S>& s, const InterfaceStrainT<S>& d, StateVectorT<S>& ds) const {
    const auto D = kin_.template stretching<S>(d);
    const CamClayInvariants<Ops, double> inv(Ops::template unpack<double>(values_of<S>(s), 0));
    const double pc = value_of(s(kPc));
    const bool on_surface =
        std::abs(cam_clay_yield(inv.p, inv.q, pc, c_.M)) <= kOnSurface * pc * pc;
    const auto r = cam_clay_rate<Ops, S>(point(s), D, c_, on_surface);
    ds.resize(state_size());
    Ops::template pack<S>(r.T, ds, 0);
    ds(kE) = (1.0 + s(kE)) * Ops::trace(D);
    ds(kPc) = r.p_c;
  }

  std::string name_;
  Kinematics kin_{};
  CamClayParameters c_;
};

ModelDeclaration mcc_declaration(const std::vector<std::string>& stress_components,
                                 int listing_order) {
  ModelDeclaration d;
  d.listing_order = listing_order;
  for (const auto& c : stress_components)
    d.layout.components.push_back({c, "kPa", ComponentKind::kStress});
  d.layout.void_ratio = d.layout.size();
  d.layout.components.push_back({"e", "-", ComponentKind::kVoidRatio});
  d.layout.components.push_back({"p_c", "kPa", ComponentKind::kHardening});
  InitialInputSpec sigma_n{"sigma_n_kPa", "kPa",
                           "initial normal stress sigma_n0, compression positive"};
  sigma_n.range = positive(kMaxStressKPa);
  // e only follows the volumetric strain: no stiffness or strength of the model reads it
  // (8.19, 8.20)
  InitialInputSpec e0{
      "e0", "-",
      "initial void ratio, recorded and updated by the volumetric strain (default 1: the "
      "model's response does not depend on it)"};
  e0.range = positive(kMaxVoidRatio);
  e0.need = InitialInputSpec::Need::kOptional;
  e0.default_value = [](const ModelInputs&) { return 1.0; };
  InitialInputSpec k0{"K0", "-",
                      "sigma_p0 = K0 sigma_n0 (default: 1 - sin phi, sin phi = 3M/(6+M))"};
  k0.range = positive(kMaxK0);
  k0.need = InitialInputSpec::Need::kOptional;
  k0.default_value = default_K0;
  InitialInputSpec ocr{
      "OCR", "-",
      "p_c over the ellipse through the initial stress (default 1: normally consolidated)"};
  ocr.need = InitialInputSpec::Need::kOptional;
  ocr.range = closed(1.0, 1000.0);
  d.initial = {sigma_n, e0, k0, ocr};
  d.diagnostics = {
      {"mean_stress_kPa", "kPa", "mean stress p = -tr T / 3", DiagnosticRole::kMeanStress},
      {"q_kPa", "kPa", "deviatoric stress q = sqrt(3/2 s:s)"},
      {"f_yield", "-", "f / p_c^2 (eq. 8.18): 0 on the ellipse, negative inside",
       DiagnosticRole::kYieldFunction},
      {"eta_over_M", "-", "q / (M p): 1 at the critical state"}};
  d.update = StressPointUpdate::kIncrement;
  d.example_parameters = "table_8_1_london_clay.toml";
  d.example_start = {{"sigma_n_kPa", 100.0}, {"e0", 1.0}};
  return d;
}

}  // namespace

ModelSpec mcc_spec() {
  using Kinematics = ReducedInterfaceKinematics<algebra::ReducedOps>;
  return {"mcc",
          "modified Cam clay (Roscoe & Burland 1968), interface model on [sigma_n, sigma_p, tau_x, "
          "tau_y], implicit return",
          "seed 8.16-8.20, Table 8.1",
          false,
          {&cam_clay_table()},
          [](const ModelInputs& in) {
            return std::make_unique<ModifiedCamClay<Kinematics>>("mcc", read(in));
          },
          mcc_declaration(Kinematics::component_names(), kListingOrder)};
}

ModelSpec mcc3d_spec() {
  return {"mcc3d",
          "modified Cam clay (Roscoe & Burland 1968), full 3x3 tensors in simple shear, implicit "
          "return",
          "seed 8.16-8.20, Table 8.1",
          false,
          {&cam_clay_table()},
          [](const ModelInputs& in) {
            return std::make_unique<ModifiedCamClay<SimpleShearKinematics>>("mcc3d", read(in));
          },
          mcc_declaration(SimpleShearKinematics::component_names(), kListingOrder + 1)};
}

}  // namespace iwb::models
