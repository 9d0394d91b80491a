#pragma once
// `iwb run --study thermo`: seed section 6.5, the thermo-hydro-mechanical interface model hcthm
// (Masin & Khalili 2012) under CNL and CV at several constant temperatures, with n_t and l_t
// varied, and at several suctions, Table 6.5's sets; the seed's findings checked one by one, and
// reduced against 3D (README.md in this folder).
#include "studies/study.hpp"

namespace iwb::studies {

StudyDefinition thermo_study();

}  // namespace iwb::studies
