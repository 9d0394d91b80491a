#pragma once
// The DEM engines by name: the one place that knows which engines exist.
#include <memory>
#include <string>
#include <vector>

#include "dem/engines/engine.hpp"

namespace iwb::dem {

std::vector<std::string> engine_names();  // "liggghts", "yade"

// Throws InputError naming the option and the engines available.
std::unique_ptr<Engine> make_engine(const std::string& name,
                                    const std::string& option = "--engine");

}  // namespace iwb::dem
