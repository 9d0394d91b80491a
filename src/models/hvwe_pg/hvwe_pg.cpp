// hvwe-pg: hvwe with a geometric dilatancy of the wall's asperities (issue 56, candidate B of
// data/models_beyond/README.md; after Patton 1966 and Plesha 1987). The element's normal strain
// rate is the soil's plus the asperities' ride,
//   eps_n = eps_n(soil) + tan(psi_w) |gamma_rate|,  tan(psi_w) = beta_w m_w exp(-u_s / lambda_w),
// where m_w is the wall's mean |slope| (`iwb dem roughness`), u_s = d_s * integral |gamma_rate|
// the slip travelled, and lambda_w the travel over which the asperities stop riding (worn, or
// buried in grains). The soil (its stress and void ratio) sees only its own share: the ride lifts
// the soil without straining it. On a flat wall (m_w = 0) or with beta_w = 0 it is hvwe.
#include <fmt/core.h>

#include <cmath>

#include "common/errors.hpp"
#include "common/scalar.hpp"
#include "models/hypoplastic/family.hpp"

namespace iwb::models {

namespace {

constexpr int kListingOrder = 41;  // after hvwe-rd

const ParameterTable& asperity_dilatancy_table() {
  static const ParameterTable t{
      "asperity_dilatancy",
      {{"beta_w",
        "-",
        {0.0, false},
        {1.0, false},
        "share of the wall's mean |slope| the grains ride at the start: tan psi_w0 = beta_w m_w",
        "issue 56, data/models_beyond/README.md (candidate B); Patton 1966",
        ParameterRole::kMaterial,
        CalibrationBox{0.0, 1.0, false}},
       {"lambda_w_d50",
        "d50",
        {0.0, true},
        {1e4, false},
        "slip over which the ride decays by 1/e: tan psi_w = beta_w m_w exp(-u_s / lambda_w)",
        "issue 56, data/models_beyond/README.md (candidate B); Plesha 1987",
        ParameterRole::kMaterial,
        CalibrationBox{0.5, 50.0, true}}}};
  return t;
}

// The ride's constants: tan psi_w = tan_psi0 exp(-s d_s / lambda_mm), s the travelled shear strain.
struct Ride {
  double tan_psi0 = 0.0;
  double d_s_mm = 1.0;
  double lambda_mm = 1.0;

  template <class S>
  S tan_psi(const S& travelled) const {
    using std::exp;
    const S exponent = -travelled * (d_s_mm / lambda_mm);  // a value, not an expression
    return S(tan_psi0 * exp(exponent));
  }
};

// hvwe's state with the travelled shear strain s = integral |gamma_rate| appended.
class AsperityDilatancy final : public Model {
 public:
  AsperityDilatancy(std::unique_ptr<Model> soil, Ride ride)
      : soil_(std::move(soil)), ride_(ride), n_(soil_->state_size()) {}

  std::string_view name() const override { return "hvwe-pg"; }
  int state_size() const override { return n_ + 1; }
  std::vector<std::string> state_names() const override {
    auto names = soil_->state_names();
    names.push_back("s");
    return names;
  }
  bool has_second_shear_direction() const override { return soil_->has_second_shear_direction(); }

  StateVector initial_state(const InitialState& init) const override {
    StateVector s(n_ + 1);
    s.head(n_) = soil_->initial_state(init);
    s(n_) = 0.0;
    return s;
  }
  std::vector<std::string> initial_warnings(const InitialState& init) const override {
    return soil_->initial_warnings(init);
  }

  void rate(const StateVector& s, const InterfaceStrain& d, StateVector& ds) const override {
    rate_impl<double>(s, d, ds);
  }
  void rate(const StateVectorT<Dual>& s, const InterfaceStrainT<Dual>& d,
            StateVectorT<Dual>& ds) const override {
    rate_impl<Dual>(s, d, ds);
  }

  InterfaceStress stress(const StateVector& s) const override { return soil_->stress(soil(s)); }
  double void_ratio(const StateVector& s) const override { return soil_->void_ratio(soil(s)); }
  std::string domain_violation(const StateVector& s) const override {
    if (!std::isfinite(s(n_))) return "travelled shear strain is not finite";
    return soil_->domain_violation(soil(s));
  }
  // s is measured against its own size, at least a shear strain of 1e-3
  StateVector error_scale(const StateVector& s) const override {
    StateVector scale(n_ + 1);
    scale.head(n_) = soil_->error_scale(soil(s));
    scale(n_) = std::max(std::abs(s(n_)), 1e-3);
    return scale;
  }
  std::vector<NamedValue> diagnostics(const StateVector& s) const override {
    auto out = soil_->diagnostics(soil(s));
    out.push_back({"tan_psi_w", ride_.tan_psi(s(n_))});
    return out;
  }
  void flush_negligible_components(StateVector& s) const override {
    StateVector head = soil(s);
    soil_->flush_negligible_components(head);
    s.head(n_) = head;
  }

 private:
  StateVector soil(const StateVector& s) const { return s.head(n_); }

  template <class S>
  void rate_impl(const StateVectorT<S>& s, const InterfaceStrainT<S>& d,
                 StateVectorT<S>& ds) const {
    const S squared = d.gamma_x * d.gamma_x + d.gamma_y * d.gamma_y;
    const S slip_rate = safe_sqrt(squared);
    const S ride = ride_.tan_psi(S(s(n_))) * slip_rate;
    InterfaceStrainT<S> own = d;
    own.eps_n = d.eps_n - ride;  // opening positive
    const StateVectorT<S> head = s.head(n_);
    StateVectorT<S> dhead;
    soil_->rate(head, own, dhead);
    ds.resize(n_ + 1);
    ds.head(n_) = dhead;
    ds(n_) = slip_rate;
  }

  std::unique_ptr<Model> soil_;
  Ride ride_;
  int n_;
};

// The wall's ride from the inputs: none where no wall is described (the stability map, a pile),
// as on a flat one; the grains' d50 is needed where the ride is not zero.
Ride ride_of(const ModelInputs& in, const ParameterValues& table) {
  Ride r;
  r.d_s_mm = in.shear_zone_mm;
  r.tan_psi0 = table.at("beta_w") * in.roughness.mean_abs_slope.value_or(0.0);
  if (r.tan_psi0 > 0.0 && !in.d50_mm)
    throw InputError(fmt::format(
        "{}: hvwe-pg's ride decays over lambda_w_d50 grain diameters and no d50 is given (an "
        "element test: [shear_zone] d50_mm)",
        in.source));
  r.lambda_mm = table.at("lambda_w_d50") * in.d50_mm.value_or(1.0);
  return r;
}

std::unique_ptr<Model> build(const ModelInputs& in) {
  const auto& table = require_table(in, "asperity_dilatancy");
  validate(asperity_dilatancy_table(), table, in.source + " [asperity_dilatancy]");
  return std::make_unique<AsperityDilatancy>(
      make_hypoplastic("hvwe", ReducedInterfaceKinematics<algebra::ReducedOps>{},
                       HypoplasticVariant{}, in),
      ride_of(in, table));
}

}  // namespace

ModelSpec hvwe_pg_spec() {
  ModelSpec spec{
      "hvwe-pg",
      "hvwe with a geometric dilatancy of the wall's asperities, worn with the slip",
      "seed 5.2, 5.4, 5.5 as hvwe; eps_n += beta_w m_w exp(-u_s/lambda_w) |gamma| (issue 56, "
      "candidate B)",
      true,
      {&HypoplasticParameters::table(), &asperity_dilatancy_table()},
      build,
      hypoplastic_declaration(ReducedInterfaceKinematics<algebra::ReducedOps>::component_names(),
                              true, InPlaneStart::kFreeK0, kListingOrder)};
  auto& d = spec.declaration;
  d.layout.components.push_back({"s", "-", ComponentKind::kHardening});
  d.diagnostics.push_back({"tan_psi_w", "-", "the asperities' ride, beta_w m_w exp(-u_s/lambda_w)",
                           DiagnosticRole::kNone});
  d.roughness.reads_mean_slope = true;
  d.example_parameters = "hvwe_pg_example.toml";
  // tried by `iwb plan` and the league after hvwe-rd: hvwe and two parameters (fitted to DEM
  // walls: --params-for hvwe-pg=FILE)
  d.plan_rank = 10;
  return spec;
}

}  // namespace iwb::models
