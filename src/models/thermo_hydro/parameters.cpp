#include <fmt/core.h>

#include "models/thermo_hydro/thermo_hydro_clay.hpp"

namespace iwb::models {

// Beyond these a value is a units mistake (alpha_s of clays ~1e-5 to 1e-4 1/K; l_t, n_t, l_s, n_s
// a few hundredths in Masin & Khalili's sets; T0 in kelvin).
constexpr double kMaxExpansion = 1e-2;
constexpr double kMaxSlopeChange = 1.0;
constexpr double kMaxSuctionKPa = 1e6;
constexpr double kMaxCollapseExponent = 100.0;

const ParameterTable& ThermoHydroParameters::table() {
  static const ParameterTable t{
      "thermo_hydro",
      {
          {"alpha_s_per_K",
           "1/K",
           {0.0, false},
           {kMaxExpansion, false},
           "volumetric thermal expansion coefficient alpha_s of the grains (D^TE = alpha_s T_rate "
           "/ 3 1)",
           "eq. 6.32"},
          {"l_t",
           "-",
           {-kMaxSlopeChange, false},
           {kMaxSlopeChange, false},
           "change of lambda* per ln(T/T0)",
           "eq. 6.44"},
          {"n_t",
           "-",
           {-kMaxSlopeChange, false},
           {kMaxSlopeChange, false},
           "change of N per ln(T/T0)",
           "eq. 6.45"},
          {"l_s",
           "-",
           {-kMaxSlopeChange, false},
           {kMaxSlopeChange, false},
           "change of lambda* per ln(s/s_e) above s_e",
           "eq. 6.44"},
          {"n_s",
           "-",
           {-kMaxSlopeChange, false},
           {kMaxSlopeChange, false},
           "change of N per ln(s/s_e) above s_e",
           "eq. 6.45"},
          {"s_e_kPa",
           "kPa",
           {0.0, true},
           {kMaxSuctionKPa, false},
           "air-entry (air-expulsion) suction s_e: chi = 1 below it, (s_e/s)^0.55 above",
           "eq. 6.31"},
          {"m",
           "-",
           {0.0, true},
           {kMaxCollapseExponent, false},
           "exponent of the collapse factor f_u = (f_d / f_d^SBS)^(m/alpha)",
           "eq. 6.51"},
          {"T0_K",
           "K",
           {0.0, true},
           {1000.0, false},
           "reference temperature T0 of lambda* and N, kelvin",
           "eq. 6.44"},
      }};
  return t;
}

ThermoHydroParameters ThermoHydroParameters::from(const ParameterValues& v,
                                                  const std::string& source) {
  validate(table(), v, source);
  return {v.at("alpha_s_per_K"), v.at("l_t"),     v.at("n_t"), v.at("l_s"),
          v.at("n_s"),           v.at("s_e_kPa"), v.at("m"),   v.at("T0_K")};
}

}  // namespace iwb::models
