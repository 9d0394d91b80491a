#pragma once
// The main job on the embedded default (README): until the DEM scenes land (issues 4-6) it is the
// continuum half of the validation: hvwe against its 3D reference vw3d in simple shear under CNL,
// CNS and CV at 100 kPa (seed Table 5.1), one run directory each and a table of differences.
#include <filesystem>
#include <string>

namespace iwb::studies {

// The embedded test, with {model} and {boundary} placeholders.
extern const char* const kDefaultElementTest;

int run_default_job(const std::filesystem::path& out, bool force, const std::string& command_line);

}  // namespace iwb::studies
