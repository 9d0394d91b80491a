// hcthm: Masin & Khalili's (2012) thermo-mechanical hypoplasticity for variably saturated clay
// (seed 6.3), on the reduced interface vectors with the roughness of 6.2.4 (hcthm3d, on full 3x3
// tensors in simple shear, is hcthm3d.cpp). The state holds the net stress, e, T_K and s_kPa; a
// test's stages prescribe the paths of T and s (src/driver/path.hpp), which the model alone reads.
#include "models/thermo_hydro/hcthm_build.hpp"

namespace iwb::models {

ModelDeclaration masin_clay_declaration(const std::vector<std::string>& stress_components,
                                        bool interface_model,
                                        int listing_order);  // hc/hc.cpp

ModelDeclaration thermo_hydro_declaration(const std::vector<std::string>& stress_components,
                                          bool interface_model, int listing_order) {
  auto d = masin_clay_declaration(stress_components, interface_model, listing_order);
  const int first = d.layout.size();
  d.layout.components.push_back({"T_K", "K", ComponentKind::kExternal});
  d.layout.components.push_back({"s_kPa", "kPa", ComponentKind::kExternal});
  d.layout.external[std::size_t(External::kTemperature)] = first;
  d.layout.external[std::size_t(External::kSuction)] = first + 1;
  d.externals = {{External::kTemperature, "T_K", "K",
                  "absolute temperature (a test file may give T_C in deg C)"},
                 {External::kSuction, "s_kPa", "kPa", "matric suction s = u_a - u_w"}};
  InitialInputSpec T{"T_K", "K", "initial temperature (default: the parameters' T0_K)"};
  T.need = InitialInputSpec::Need::kOptional;
  T.range = closed(200.0, 500.0);
  T.default_value = [](const ModelInputs& in) {
    return require_table(in, "thermo_hydro").at("T0_K");
  };
  InitialInputSpec s{"s_kPa", "kPa", "initial matric suction (default 0: saturated)"};
  s.need = InitialInputSpec::Need::kOptional;
  s.range = closed(0.0, 1e6);
  s.default_value = [](const ModelInputs&) { return 0.0; };
  d.initial.push_back(T);
  d.initial.push_back(s);
  d.diagnostics = {{"mean_stress_kPa", "kPa", "mean effective stress", DiagnosticRole::kMeanStress},
                   {"p_e_kPa", "kPa", "Hvorslev's p_e at this temperature and suction (6.43-6.45)",
                    DiagnosticRole::kEquivalentPressure},
                   {"F_m", "-", "Matsuoka-Nakai's F_m of the effective stress"},
                   {"chi", "-", "Khalili's effective stress factor (6.31)"},
                   {"f_d_over_f_dSBS", "-", "f_d / f_d^SBS: 1 on the state boundary surface (6.49)",
                    DiagnosticRole::kOverconsolidation}};
  d.example_start = {{"sigma_n_kPa", 300.0}, {"e0", 0.44}, {"T_K", 298.15}};  // as hc's
  return d;
}

ModelSpec hcthm_spec() {
  return {
      "hcthm",
      "Masin & Khalili (2012) thermo-hydro-mechanical clay hypoplasticity, interface model on "
      "[sigma_n, sigma_p, tau_x, "
      "tau_y] (net stresses), with temperature and suction",
      "seed 6.3 (6.29-6.52; issue 19 closing note), roughness 6.2.4",
      true,
      {&MasinClayParameters::table(), &ThermoHydroParameters::table()},
      [](const ModelInputs& in) {
        return build_thermo_hydro("hcthm", ReducedInterfaceKinematics<algebra::ReducedOps>{}, in);
      },
      thermo_hydro_declaration(ReducedInterfaceKinematics<algebra::ReducedOps>::component_names(),
                               true, kThermoHydroListingOrder)};
}

}  // namespace iwb::models
