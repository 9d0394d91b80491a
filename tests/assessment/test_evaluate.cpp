// Many runs at once (issue 17, item 3): results come back in the rows' order whatever the number
// of threads, and the progress counter sees every run once.
#include <catch2/catch.hpp>
#include <cmath>
#include <set>
#include <thread>

#include "assessment/evaluate.hpp"

using namespace iwb::assessment;

TEST_CASE("rows are evaluated in parallel and returned in their order", "[assessment]") {
  std::vector<std::vector<double>> rows;
  for (int i = 0; i < 400; ++i) rows.push_back({double(i), 0.5 * i});
  const Quantities f = [](const std::vector<double>& x) {
    double s = 0.0;  // some work, so that the threads interleave
    for (int k = 0; k < 20000; ++k) s += std::sin(x[0] + k);
    return std::vector<double>{x[0] * x[1], s};
  };
  const auto one = evaluate_rows(rows, f, 1);
  const auto many = evaluate_rows(rows, f, 4);
  REQUIRE(many.size() == rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    CHECK(many[i][0] == 0.5 * double(i) * double(i));
    CHECK(many[i][1] == one[i][1]);
  }
}

TEST_CASE("progress counts every run once, from several threads", "[assessment]") {
  std::vector<std::vector<double>> rows(1000, std::vector<double>{1.0});
  std::set<long> seen;
  long last_total = 0;
  const auto f =
      with_progress([](const std::vector<double>& x) { return x; }, long(rows.size()),
                    [&](long done, long total) { seen.insert(done), last_total = total; });
  evaluate_rows(rows, f, 4);
  CHECK(seen.size() == rows.size());
  CHECK(*seen.begin() == 1);
  CHECK(*seen.rbegin() == long(rows.size()));
  CHECK(last_total == long(rows.size()));
}
