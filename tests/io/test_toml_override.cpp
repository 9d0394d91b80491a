// Setting a dotted key of a TOML document: the campaign's way of deriving job scenes.
#include <catch2/catch.hpp>

#include "common/errors.hpp"
#include "io/toml_override.hpp"
#include "io/toml_reader.hpp"

using namespace iwb;

TEST_CASE("set_dotted: the key lands in its own table, other keys keep their values", "[io]") {
  auto root = io::parse_toml_text("seed = 1\n[wall]\nheight_d50 = 0.5\n[plate]\nheight_d50 = 1.0\n",
                                  "base.toml");
  io::set_dotted(root, "wall.height_d50", 0.25, "t");
  io::set_dotted(root, "seed", std::int64_t{3}, "t");
  io::set_dotted(root, "boundary.type", std::string("CNS"), "t");  // a missing table is created
  const auto again = io::parse_toml_text(io::serialise(root), "again.toml");
  CHECK(again["wall"]["height_d50"].value<double>() == 0.25);
  CHECK(again["plate"]["height_d50"].value<double>() == 1.0);
  CHECK(again["seed"].value<std::int64_t>() == 3);
  CHECK(again["boundary"]["type"].value<std::string>() == "CNS");
}

TEST_CASE("set_dotted: a value in the path or a table at the key is refused with the key", "[io]") {
  auto root = io::parse_toml_text("seed = 1\n[wall]\nheight_d50 = 0.5\n", "base.toml");
  CHECK_THROWS_WITH(io::set_dotted(root, "seed.x", 1.0, "s.toml"),
                    Catch::Contains("s.toml") && Catch::Contains("'seed' is a value"));
  CHECK_THROWS_WITH(io::set_dotted(root, "wall", 1.0, "s.toml"),
                    Catch::Contains("cannot set 'wall' = 1.0"));
  CHECK_THROWS_AS(io::set_dotted(root, "wall.", 1.0, "s.toml"), InputError);
}

TEST_CASE("to_toml writes values as TOML does", "[io]") {
  CHECK(io::to_toml(0.5) == "0.5");
  CHECK(io::to_toml(2.0) == "2.0");
  CHECK(io::to_toml(std::int64_t{2}) == "2");
  CHECK(io::to_toml(true) == "true");
  CHECK(io::to_toml(std::string("CNL")) == "'CNL'");  // toml++ writes literal strings
}

// A grading is a list: the gradings campaign (data/sweeps/grains_cu*.toml) sets d_over_d50 and
// mass_fraction by an axis value; a list replaces a list, never a scalar or a table.
TEST_CASE("a list of numbers is read, written and set in place of the base's list", "[io]") {
  const auto doc = io::parse_toml_text("a = [0.5, 1, 1.7]\nb = [1, 'x']\nc = []\n", "v.toml");
  const auto a = io::toml_value_of(*doc.get("a"), "v.toml a");
  REQUIRE(std::holds_alternative<std::vector<double>>(a));
  CHECK(std::get<std::vector<double>>(a) == std::vector<double>{0.5, 1.0, 1.7});
  CHECK(io::to_toml(a) == "[0.5, 1, 1.7]");
  CHECK_THROWS_WITH(io::toml_value_of(*doc.get("b"), "v.toml b"),
                    Catch::Contains("v.toml b") && Catch::Contains("a list of numbers"));
  CHECK_THROWS_AS(io::toml_value_of(*doc.get("c"), "v.toml c"), InputError);
  auto root = io::parse_toml_text("[particles]\nd_over_d50 = [0.8, 1.0, 1.2]\nd50_mm = 2.0\n", "s");
  io::set_dotted(root, "particles.d_over_d50", std::vector<double>{0.3, 1.0, 2.2}, "t");
  const auto again = io::parse_toml_text(io::serialise(root), "again.toml");
  const auto* list = again["particles"]["d_over_d50"].as_array();
  REQUIRE(list != nullptr);
  CHECK(list->size() == 3);
  CHECK(list->get(2)->value<double>() == 2.2);
  CHECK_THROWS_WITH(io::set_dotted(root, "particles.d50_mm", std::vector<double>{1.0}, "t"),
                    Catch::Contains("cannot set"));
}
