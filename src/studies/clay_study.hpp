#pragma once
// `iwb run --study clay`: the seed's section 6.4 comparisons of the clay interface models, which
// the granular DEM cannot check, reproduced as element tests with figures, a table of the seed's
// claims against what the models do, and one HTML page (README.md in this folder).
#include "studies/study.hpp"

namespace iwb::studies {

// The cases (clay_cases.hpp), claims (clay_claims.hpp) and the seed's Figures 6.3-6.7 and 6.11.
StudyDefinition clay_study();

}  // namespace iwb::studies
