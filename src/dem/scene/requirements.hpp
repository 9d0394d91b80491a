#pragma once
// What a scene asks of its results (issue 7, item 5): the quantities of interest and the relative
// tolerance each must meet, from the scene's optional [requirements] table. `iwb plan` chooses the
// cheapest DEM setting and the simplest continuum model that meet them.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/toml_reader.hpp"

namespace iwb::dem {

// The quantities of interest of a DEM run (summary.json), in the order tables list them.
struct Qoi {
  const char* key;    // as in [requirements] and the tradeoff tables
  const char* label;  // for people
};
const std::vector<Qoi>& quantities_of_interest();
// Quantities that only `iwb compare` judges (a model against the DEM;
// comparison/replay/quantities.hpp holds their default tolerances): a scene may state tolerances
// for them too.
const std::vector<Qoi>& compared_only_quantities();
// The cyclic quantities `iwb compare` judges on a cyclic run (issue 34; their default tolerances
// are comparison/verdicts/cyclic_verdicts.cpp's), each per cycle and as a change over the cycles.
const std::vector<Qoi>& cyclic_quantities();
// Every key [requirements] may hold: the three lists above.
const std::vector<const std::vector<Qoi>*>& requirement_lists();

// QoI key -> relative tolerance (0.05 = 5 %); nullopt: "not needed". QoIs not named are not needed.
using Requirements = std::map<std::string, std::optional<double>>;

// Reads [requirements]: each key a QoI, each value a number in (0, 1] or the string "not needed".
// InputError naming the file, the key and the value otherwise.
Requirements read_requirements(io::TableReader table);

}  // namespace iwb::dem
