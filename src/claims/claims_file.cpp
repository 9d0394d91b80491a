#include <fmt/core.h>

#include <limits>
#include <set>

#include "claims/claims.hpp"
#include "common/errors.hpp"
#include "io/toml_reader.hpp"

namespace iwb::claims {

namespace {

std::vector<std::string> patterns(io::TableReader& t, const std::string& key) {
  const auto* node = t.node(key);
  const auto* array = node ? node->as_array() : nullptr;
  if (array == nullptr || array->empty())
    throw InputError(
        fmt::format("{}: should be a non-empty list of run directories", t.where(key)));
  std::vector<std::string> out;
  for (const auto& e : *array) {
    const auto s = e.value<std::string>();
    if (!s || s->empty())
      throw InputError(fmt::format("{}: {}: should be a run directory (a string)", t.where(key),
                                   io::describe(e)));
    out.push_back(*s);
  }
  return out;
}

std::string one_of(io::TableReader& t, const std::string& key,
                   const std::vector<std::string>& allowed) {
  const auto v = t.text(key);
  for (const auto& a : allowed)
    if (v == a) return v;
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "\"" : ", \"") + a + "\"";
  throw InputError(fmt::format("{}: \"{}\": should be one of {}", t.where(key), v, list));
}

Claim read_claim(io::TableReader& t) {
  Claim c;
  c.id = t.text("id");
  c.says = t.text("says");
  c.quantity = t.text("quantity");
  c.relative_to = t.optional_text("relative_to").value_or("");
  c.quantity_b = t.optional_text("quantity_b").value_or(c.quantity);
  c.relative_to_b = t.optional_text("relative_to_b").value_or(c.relative_to);
  const std::pair<const std::string*, const char*> pointers[] = {
      {&c.quantity, "quantity"},
      {&c.relative_to, "relative_to"},
      {&c.quantity_b, "quantity_b"},
      {&c.relative_to_b, "relative_to_b"}};
  for (const auto& [pointer, key] : pointers)
    if (!pointer->empty() && pointer->front() != '/')
      throw InputError(
          fmt::format("{}: \"{}\": should be a JSON pointer into summary.json "
                      "(\"/cyclic/cycles/0/friction_ratio\")",
                      t.where(key), *pointer));
  if (c.relative_to.empty() != c.relative_to_b.empty())
    throw InputError(fmt::format("{}: both groups are relative changes or neither",
                                 t.where(c.relative_to.empty() ? "relative_to_b" : "relative_to")));
  c.a = patterns(t, "a");
  c.b = patterns(t, "b");
  c.expect = one_of(t, "expect", {"b > a", "b < a", "b != a", "b = a"});
  if (c.equality())
    c.margin =
        t.number_in("margin", Range{0.0, std::numeric_limits<double>::infinity(), false, false});
  c.flagged = one_of(t, "flagged", {"exclude", "include"});
  if (t.optional_text("unsteady")) c.unsteady = one_of(t, "unsteady", {"exclude", "include"});
  t.finish();
  return c;
}

}  // namespace

ClaimsFile read_claims(const std::filesystem::path& file) {
  const auto table = io::parse_toml_file(file.string());
  io::TableReader top(table, file.string());
  ClaimsFile out;
  out.file = file;
  out.q = top.number_in("q", Range{0.0, 1.0, true, true});
  std::set<std::string> ids;
  for (auto& t : top.array_of_tables("claim")) {
    out.claims.push_back(read_claim(t));
    if (!ids.insert(out.claims.back().id).second)
      throw InputError(fmt::format("{}: \"{}\": another claim has this id", t.where("id"),
                                   out.claims.back().id));
  }
  if (out.claims.empty()) throw InputError(fmt::format("{}: no [[claim]] to test", file.string()));
  top.finish();
  return out;
}

}  // namespace iwb::claims
