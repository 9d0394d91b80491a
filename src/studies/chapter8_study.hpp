#pragma once
// `iwb run --study chapter8`: seed section 8.4, constant-volume simple shear of three frameworks on
// the reduced vectors (HCE, Barodesy for clay, modified Cam clay) with Table 8.1's London and
// Kaolin sets, the seed's qualitative findings checked one by one, and reduced against 3D for the
// two models of chapter 8 (README.md in this folder).
#include "studies/study.hpp"

namespace iwb::studies {

StudyDefinition chapter8_study();

}  // namespace iwb::studies
