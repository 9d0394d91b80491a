// The element-test file's declared rows (element/element_test_keys.hpp): the README's key table is
// theirs, and the reader refuses a value just outside each declared range, naming the key. The
// refused values are built from the rows alone; the shipped test files that take each key are the
// bases, so a row no shipped file takes is itself a failure (an undocumented example is missing).
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <set>

#include "common/errors.hpp"
#include "element/element_test_file.hpp"
#include "element/element_test_keys.hpp"
#include "io/run_directory.hpp"
#include "io/toml_reader.hpp"
#include "support/generated_section.hpp"

namespace iwb {

namespace {

namespace fs = std::filesystem;

const std::string kReadme = "data/tests/README.md";
const std::string kBegin = "<!-- BEGIN generated from src/element/element_test_keys.cpp -->\n";
const std::string kEnd = "<!-- END generated from src/element/element_test_keys.cpp -->";

// Every shipped element-test file: the examples, the gold templates, the models' own.
std::vector<fs::path> shipped_tests() {
  std::vector<fs::path> out;
  for (const auto* dir : {"data/tests", "data/gold/tests"})
    for (const auto& f : fs::directory_iterator(dir))
      if (f.path().extension() == ".toml") out.push_back(f.path());
  for (const auto& f : fs::recursive_directory_iterator("src/models"))
    if (f.path().extension() == ".toml" && f.path().parent_path().filename() == "gold")
      out.push_back(f.path());
  std::sort(out.begin(), out.end());
  return out;
}

// The table a row lives in, in a parsed file: "path.stage" is the first [[path.stage]].
toml::table* table_of(toml::table& root, const std::string& dotted, std::string& where) {
  toml::table* t = &root;
  where.clear();
  std::size_t start = 0;
  while (start <= dotted.size() && !dotted.empty()) {
    const auto dot = dotted.find('.', start);
    const std::string part = dotted.substr(start, dot - start);
    toml::node* n = t->get(part);
    if (n == nullptr) return nullptr;
    where += (where.empty() ? "" : ".") + part;
    if (auto* arr = n->as_array()) {
      if (arr->empty() || !arr->get(0)->is_table()) return nullptr;
      n = arr->get(0);
      where += "[0]";
    }
    t = n->as_table();
    if (t == nullptr || dot == std::string::npos) break;
    start = dot + 1;
  }
  return t;
}

std::string refusal(const toml::table& root, const fs::path& file) {
  try {
    element::parse_element_test(root, file.string(), file.parent_path());
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

// Values just outside a number row's range (and NaN); 0 for a whole number; an unknown word for a
// text with choices.
std::vector<double> outside(const Range& r) {
  std::vector<double> v{std::nan("")};
  if (std::isfinite(r.lower)) v.push_back(r.lower_open ? r.lower : std::nextafter(r.lower, -kInf));
  if (std::isfinite(r.upper)) v.push_back(r.upper_open ? r.upper : std::nextafter(r.upper, kInf));
  return v;
}

}  // namespace

TEST_CASE("data/tests/README.md's key table is the declared one", "[element][element_keys]") {
  test::check_generated_section(kReadme, kBegin, kEnd, element::element_test_key_table(),
                                "[element_keys]");
}

TEST_CASE("every declared element-test number is refused just outside its range, naming the key",
          "[element][element_keys]") {
  const auto files = shipped_tests();
  for (const auto& row : element::element_test_keys()) {
    if (row.kind != io::KeyKind::kNumber && row.kind != io::KeyKind::kWholeNumber &&
        !(row.kind == io::KeyKind::kText && !row.choices.empty() &&
          row.limit.rfind("in any case", 0) != 0))  // any case: driver::parse_boundary_kind
      continue;
    INFO(row.dotted() << " allowed " << row.allowed());
    bool taken = false;
    for (const auto& file : files) {
      toml::table root = io::parse_toml_file(file.string());
      std::string where;
      toml::table* t = table_of(root, row.table, where);
      if (t == nullptr || !t->contains(row.key) || refusal(root, file) != "accepted") continue;
      taken = true;
      INFO("base " << file.string());
      const std::string key = "key '" + (where.empty() ? "" : where + ".") + row.key + "'";
      if (row.kind == io::KeyKind::kText) {
        t->insert_or_assign(row.key, "no-such-choice");
        CHECK_THAT(refusal(root, file), Catch::Contains(key) && Catch::Contains("allowed"));
      } else if (row.kind == io::KeyKind::kWholeNumber) {
        t->insert_or_assign(row.key, 0);
        CHECK_THAT(refusal(root, file), Catch::Contains(key));
      } else {
        for (double v : outside(row.range)) {
          INFO("value " << v);
          t->insert_or_assign(row.key, v);
          CHECK_THAT(refusal(root, file), Catch::Contains(key));
        }
      }
      break;
    }
    CHECK(taken);  // some shipped file takes the key: an example of it exists
  }
}

TEST_CASE("the element-test declarations list each key once, with a meaning",
          "[element][element_keys]") {
  std::set<std::string> seen;
  for (const auto& row : element::element_test_keys()) {
    CHECK(seen.insert(row.dotted()).second);
    CHECK_FALSE(row.meaning.empty());
  }
  for (const auto& row : element::initial_input_keys()) CHECK(seen.insert(row.dotted()).second);
}

}  // namespace iwb
