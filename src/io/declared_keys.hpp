#pragma once
// Keys of an input file declared once, as rows (issue 33), like a model's ParameterSpec: the key,
// its kind, unit, range, default, when it is needed and what it means. The reader takes every
// range and default from the rows, and the documentation's key tables are generated from them
// (`markdown_table`), so that no default or range is written twice and a README cannot drift.
//
// A limit that depends on other keys (an output spacing at most the travel) cannot be a constant:
// its row says it in `limit`, and the reader narrows the row's range there, where both are known.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "common/range.hpp"
#include "io/toml_reader.hpp"

namespace iwb::io {

enum class KeyKind {
  kNumber,       // finite, within `range`
  kWholeNumber,  // an integer in [1, 1e8]
  kText,         // one of `choices` (any text when `choices` is empty)
  kFlag,         // true or false
  kNumberList,   // an array of finite numbers
  kTolerance,    // a relative tolerance in (0, 1], or "not needed" (io::read_tolerance)
  kPath,         // a file, relative to the file that names it
  kTable,        // an inline table, whose keys the reader declares in `limit`
  kTables,       // an array of tables, whose keys are rows of the table "<table>.<key>"
};

// When a key must be given.
enum class Need {
  kRequired,
  kOptional,     // the declared default applies (or, without one, the `default_note` says what)
  kConditional,  // needed or allowed only as `when` says
};

using DefaultValue = std::variant<std::monostate, double, std::string, bool>;

struct KeyDeclaration {
  std::string table = {};  // "particles"; empty at the file's top level
  std::string key = {};
  KeyKind kind = KeyKind::kNumber;
  std::string unit = {};  // "mm", "kPa"; empty for a ratio or a name
  Range range = {};       // numbers: the allowed values (whole numbers: [1, 1e8])
  std::vector<std::string> choices = {};
  Need need = Need::kOptional;
  DefaultValue value = {};        // the default when the key is absent (monostate: none)
  std::string default_note = {};  // a default derived from other keys, said in words
  std::string when = {};          // kConditional: "CNS", "one of displacement_mm, amplitude_mm"
  std::string limit = {};    // a bound set by other keys, checked by the reader where it is known
  std::string meaning = {};  // one line

  std::string dotted() const { return table.empty() ? key : table + "." + key; }
  std::string allowed() const;       // "(0, 100] mm", "\"cdt\", \"epsd2\"", "true or false"
  std::string default_text() const;  // "0.5", "required", "derived: ..."
};

using KeyDeclarations = std::vector<KeyDeclaration>;

// The declared row of table.key; std::logic_error when the code asks for a key it never declared.
const KeyDeclaration& declared(const KeyDeclarations& rows, const std::string& table,
                               const std::string& key);

// The dotted keys of the rows that name files (a campaign rewrites them when it moves a file's
// text).
std::vector<std::string> path_keys(const KeyDeclarations& rows);

// The rows as a Markdown table (key | allowed | default | meaning), in declaration order.
std::string markdown_table(const KeyDeclarations& rows);
// The rows as JSON: one object per key (table, key, allowed, default, need, meaning, and the
// range's bounds and the choices where they apply), for tools that write scene files.
nlohmann::json to_json(const KeyDeclarations& rows);

// A TableReader that takes each key's range, choices and default from its declaration. Messages
// are those of TableReader: "file: key 'shear.cycles' = 0 must be a whole number in [1, 1e8]".
class DeclaredTable {
 public:
  DeclaredTable(TableReader reader, const KeyDeclarations& rows, std::string table);

  // A number: required, or its declared default when absent.
  double number(const std::string& key);
  // The same within a limit set by other keys (intersected with the declared range).
  double number(const std::string& key, const Range& limit);
  // A number whose absence means something other than a constant default (derived, or unused).
  std::optional<double> optional_number(const std::string& key);
  std::optional<double> optional_number(const std::string& key, const Range& limit);
  int whole_number(const std::string& key);
  std::optional<int> optional_whole_number(const std::string& key);
  std::string text(const std::string& key);  // checked against the declared choices
  std::optional<std::string> optional_text(const std::string& key);  // the same, or absent
  std::string path(const std::string& key);  // as written: the caller resolves it
  bool flag(const std::string& key);
  std::vector<double> numbers(const std::string& key);  // empty when absent
  std::optional<TableReader> table(const std::string& key);
  std::vector<TableReader> tables(const std::string& key);  // empty when absent

  TableReader& reader() { return reader_; }
  std::string where(const std::string& key) const { return reader_.where(key); }
  std::string where() const { return reader_.where(); }
  bool has(const std::string& key) const { return reader_.has(key); }
  std::string one_of(const std::vector<std::string>& keys) { return reader_.one_of(keys); }
  void finish() const { reader_.finish(); }

 private:
  const KeyDeclaration& row(const std::string& key, KeyKind kind) const;

  TableReader reader_;
  const KeyDeclarations* rows_;
  std::string table_;
};

}  // namespace iwb::io
