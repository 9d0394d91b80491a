#pragma once
// The keys of an element-test file, declared once as rows (issue 33): the reader takes every range
// and default from them, and data/tests/README.md's key table is generated from them
// (`element_test_key_table`), with a test that fails when the README drifts.
//
// [initial] is the model's: each model declares its initial inputs (models/declaration.hpp), and
// the rows of [initial] here are derived from the registry, for the documentation only.
#include "io/declared_keys.hpp"

namespace iwb::element {

// Every key of an element-test file but [initial], in the order the README lists them.
const io::KeyDeclarations& element_test_keys();

// The [initial] keys of every registered model: unit, range, default and which models take each.
io::KeyDeclarations initial_input_keys();

// data/tests/README.md's key table: the file's keys, [initial]'s from the registry in [initial]'s
// place.
std::string element_test_key_table();

}  // namespace iwb::element
