#pragma once
// Progress lines on stderr for commands that take longer than a second or two.
#include <functional>
#include <string>

namespace iwb::app {

// Element-test increments: "increment k/n (p %), t s elapsed, ETA s", at most once a second and
// only once the run has taken a second; `what` names the counted thing ("run" for the samples of
// an assessment).
std::function<void(long, long)> increment_progress(const std::string& what = "increment");

// Engine lines: at most one every two seconds, and every change of stage (the word before ':').
std::function<void(const std::string&)> engine_progress();

// Engine lines between the steps of a longer job (validate): at most one every three seconds.
std::function<void(const std::string&)> sparse_engine_progress();

// Campaign lines (sweep, tradeoff): every line, indented.
void print_progress_line(const std::string& line);

}  // namespace iwb::app
