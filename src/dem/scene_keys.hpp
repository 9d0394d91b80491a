#pragma once
// Every key of a scene file, declared once (issue 33): the parser (scene.cpp) reads each through
// its row, and data/scenes/README.md's key table is generated from the rows (`iwb dem keys`;
// tests/dem/test_scene_keys.cpp fails when the README drifts from them).
#include "io/declared_keys.hpp"

namespace iwb::dem {

const io::KeyDeclarations& scene_keys();

}  // namespace iwb::dem
