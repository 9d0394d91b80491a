// Engine templates: every placeholder filled, a missing value fails before any engine runs.
#include <catch2/catch.hpp>

#include "common/template.hpp"

TEST_CASE("placeholders are replaced and a missing value is an error naming it", "[common]") {
  CHECK(iwb::render_template("a {{x}} b {{y}}{{x}}", {{"x", "1"}, {"y", "2"}, {"z", "3"}}, "t") ==
        "a 1 b 21");
  CHECK_THROWS_WITH(iwb::render_template("run {{steps}}", {{"step", "5"}}, "shear.in"),
                    Catch::Contains("shear.in") && Catch::Contains("'steps'"));
  CHECK_THROWS_WITH(iwb::render_template("run {{steps", {}, "t"), Catch::Contains("unclosed"));
}
