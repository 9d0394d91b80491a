#include "dem/engines/engines.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "common/errors.hpp"
#include "dem/engines/liggghts/liggghts_engine.hpp"
#include "dem/engines/yade/yade_engine.hpp"

namespace iwb::dem {

std::vector<std::string> engine_names() {
  return {"liggghts", "yade"};
}

std::unique_ptr<Engine> make_engine(const std::string& name, const std::string& option) {
  if (name == "liggghts") return std::make_unique<LiggghtsEngine>();
  if (name == "yade") return std::make_unique<YadeEngine>();
  throw InputError(
      fmt::format("{} {}: available engines: {}", option, name, fmt::join(engine_names(), ", ")));
}

}  // namespace iwb::dem
