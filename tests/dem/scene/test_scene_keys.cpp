// The scene keys declared once (src/dem/scene/scene_keys.cpp): the README's table is theirs, the
// parser enforces every declared range, and every declared key is one the parser takes.
#include <toml++/toml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>

#include "common/errors.hpp"
#include "dem/scene/scene.hpp"
#include "dem/scene/scene_keys.hpp"
#include "io/run_directory.hpp"
#include "io/toml_reader.hpp"
#include "support/replaced.hpp"

using namespace iwb;

namespace {

using io::KeyDeclaration;
using io::KeyKind;

// A scene's text with table.key set to `value` (the table made when the scene has none).
std::string with_value(const std::string& scene, const KeyDeclaration& row, toml::node&& value) {
  toml::table root = toml::parse(scene);
  toml::table* t = &root;
  if (!row.table.empty()) {
    if (!root.contains(row.table)) root.insert(row.table, toml::table{});
    t = root[row.table].as_table();
  }
  value.visit([&](auto&& v) { t->insert_or_assign(row.key, std::move(v)); });
  std::ostringstream os;
  os << root;
  return os.str();
}

std::string refusal_of(const std::string& text) {
  try {
    dem::parse_scene(text, "scene.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// A smoke scene whose plate (its first sawtooth) is a file wall with these keys.
std::string plate_from(const std::string& scene, const std::string& keys) {
  return test::replaced(scene, "profile = \"sawtooth\"\npitch_d50 = 2\nheight_d50 = 1.0",
                        "profile = \"file\"\n" + keys);
}

// The scenes a key is tried in: one of them must take it (a conditional key needs its condition).
std::vector<std::string> bases() {
  const std::string smoke = io::read_file("data/scenes/smoke.toml");
  const std::string random = io::read_file("data/scenes/smoke_random.toml");
  // file walls by absolute paths: the texts are parsed as "scene.toml" in the working directory
  const std::string file =
      test::replaced(io::read_file("data/scenes/smoke_file.toml"), "../walls/sandblasted_like.csv",
                     std::filesystem::absolute("data/walls/sandblasted_like.csv").string());
  const auto map = std::filesystem::temp_directory_path() / "iwb_scene_keys_map.csv";
  {
    std::ofstream out(map);
    for (int j = 0; j <= 40; ++j)
      for (int i = 0; i <= 120; ++i)
        out << (i ? "," : "") << 0.1 * std::sin(0.3 * i) * std::cos(0.2 * j)
            << (i == 120 ? "\n" : "");
  }
  return {
      smoke,
      io::read_file("data/scenes/smoke_cns.toml"),
      io::read_file("data/scenes/smoke_glued.toml"),
      io::read_file("data/scenes/smoke_cyclic.toml"),
      random,
      test::replaced(random, "profile = \"sawtooth\"\npitch_d50 = 2\nheight_d50 = 1.0",
                     "profile = \"random\"\nrms_height_d50 = 0.3\ncorrelation_length_d50 = 1"),
      test::replaced(smoke, "inertial_number = 1e-3", "velocity_mm_s = 1"),
      file,
      test::replaced(
          test::replaced(file,
                         std::filesystem::absolute("data/walls/sandblasted_like.csv").string(),
                         map.string()),
          "height_scale = 8", "layout = \"map\"\nspacing_mm = 0.2"),
      plate_from(file, "file = \"" +
                           std::filesystem::absolute("data/walls/sandblasted_like.csv").string() +
                           "\""),
      plate_from(file, "file = \"" + map.string() + "\"\nlayout = \"map\"\nspacing_mm = 0.2")};
}

// A value the row admits: the scene's own where it has one, else the default, else one inside the
// range.
toml::node_view<const toml::node> existing(const toml::table& root, const KeyDeclaration& row) {
  return row.table.empty() ? root[row.key] : root[row.table][row.key];
}

std::unique_ptr<toml::node> admitted(const std::string& scene, const KeyDeclaration& row) {
  const toml::table root = toml::parse(scene);
  if (const auto v = existing(root, row); v) {
    std::unique_ptr<toml::node> copy;
    v.node()->visit([&](auto&& x) { copy = std::make_unique<std::decay_t<decltype(x)>>(x); });
    return copy;
  }
  if (const auto* d = std::get_if<double>(&row.value)) {
    if (row.kind == KeyKind::kWholeNumber)
      return std::make_unique<toml::value<int64_t>>(int64_t(*d));
    return std::make_unique<toml::value<double>>(*d);
  }
  if (const auto* s = std::get_if<std::string>(&row.value))
    return std::make_unique<toml::value<std::string>>(*s);
  switch (row.kind) {
    case KeyKind::kWholeNumber:
      return std::make_unique<toml::value<int64_t>>(2);
    case KeyKind::kFlag:
      return std::make_unique<toml::value<bool>>(true);
    case KeyKind::kTolerance:
      return std::make_unique<toml::value<double>>(0.1);
    case KeyKind::kText:
      return std::make_unique<toml::value<std::string>>(row.choices.empty() ? "any text"
                                                                            : row.choices.front());
    case KeyKind::kPath:
      return std::make_unique<toml::value<std::string>>("no such file.csv");
    case KeyKind::kNumberList:
    case KeyKind::kTable:
    case KeyKind::kTables:
      return nullptr;  // tried only where a scene has one
    case KeyKind::kNumber: {
      const double v = row.range.admits(1.0) ? 1.0 : 0.5 * (row.range.lower + row.range.upper);
      return std::make_unique<toml::value<double>>(v);
    }
  }
  return nullptr;
}

// The first base that takes the key at an admitted value; empty when none does.
std::string base_taking(const KeyDeclaration& row) {
  for (const auto& base : bases()) {
    auto v = admitted(base, row);
    if (v == nullptr) continue;
    const std::string text = with_value(base, row, std::move(*v));
    if (refusal_of(text) == "(no error)") return base;
  }
  return {};
}

// Values just outside what the row declares.
std::vector<std::unique_ptr<toml::node>> refused_values(const KeyDeclaration& row) {
  std::vector<std::unique_ptr<toml::node>> out;
  const auto number = [&](double v) { out.push_back(std::make_unique<toml::value<double>>(v)); };
  switch (row.kind) {
    case KeyKind::kNumber:
      if (std::isfinite(row.range.lower))
        number(row.range.lower_open ? row.range.lower : row.range.lower - 1.0);
      if (std::isfinite(row.range.upper))
        number(row.range.upper_open ? row.range.upper : 2.0 * row.range.upper + 1.0);
      number(std::nan(""));
      break;
    case KeyKind::kWholeNumber:
      out.push_back(std::make_unique<toml::value<int64_t>>(0));
      break;
    case KeyKind::kTolerance:
      number(0.0), number(2.0);
      break;
    case KeyKind::kPath:
    case KeyKind::kText:  // free text refuses only what is not text
      if (row.choices.empty())
        out.push_back(std::make_unique<toml::value<int64_t>>(1));
      else
        out.push_back(std::make_unique<toml::value<std::string>>("no such choice"));
      break;
    case KeyKind::kFlag:
      out.push_back(std::make_unique<toml::value<std::string>>("yes"));
      break;
    case KeyKind::kNumberList:
      out.push_back(std::make_unique<toml::array>(1.0, std::nan("")));
      break;
    case KeyKind::kTable:
    case KeyKind::kTables:  // a table's own keys are rows of their own
      break;
  }
  return out;
}

}  // namespace

TEST_CASE("data/scenes/README.md's key table is the declared one", "[dem][scene_keys]") {
  const std::string readme = io::read_file("data/scenes/README.md");
  const std::string begin = "<!-- BEGIN generated by `iwb dem keys` -->\n",
                    end = "<!-- END generated by `iwb dem keys` -->";
  const auto b = readme.find(begin), e = readme.find(end);
  REQUIRE(b != std::string::npos);
  REQUIRE(e != std::string::npos);
  // regenerate with: iwb dem keys, pasted between the two markers
  CHECK(readme.substr(b + begin.size(), e - b - begin.size()) ==
        io::markdown_table(dem::scene_keys()));
}

TEST_CASE(
    "every declared scene key is taken by the parser, and refused just outside its declared range",
    "[dem][scene_keys]") {
  for (const auto& row : dem::scene_keys()) {
    INFO(row.dotted() << " allowed " << row.allowed());
    const std::string base = base_taking(row);
    REQUIRE_FALSE(base.empty());  // no shipped smoke scene takes the key at a value its row admits
    for (auto& bad : refused_values(row)) {
      INFO("value " << io::describe(*bad));
      CHECK_THAT(refusal_of(with_value(base, row, std::move(*bad))),
                 Catch::Contains("key '" + row.dotted() + "'"));
    }
  }
}

TEST_CASE("the declarations list each key once, with a meaning", "[dem][scene_keys]") {
  std::set<std::string> seen;
  for (const auto& row : dem::scene_keys()) {
    CHECK(seen.insert(row.dotted()).second);
    CHECK_FALSE(row.meaning.empty());
  }
}
