#pragma once
// Every key of a scene file, declared once (issue 33): the parser (scene.cpp) reads each through
// its row, and data/scenes/README.md's key table is generated from the rows (`iwb dem keys`;
// tests/dem/scene/test_scene_keys.cpp fails when the README drifts from them).
#include "io/declared_keys.hpp"

namespace iwb::dem {

// The most particles a scene may ask for, given or derived from the box (a 1e8-grain run would
// take the engine months on the machines this serves).
inline constexpr double kMaxParticles = 1e8;

const io::KeyDeclarations& scene_keys();

}  // namespace iwb::dem
