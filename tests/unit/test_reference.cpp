// docs/REFERENCE.md names every key the weights and build options parsers accept (from the lists
// the parsers themselves read), with the default and range the code has, and nothing they refuse.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "common/build_options.hpp"
#include "match/weights.hpp"
#include "reference_doc.hpp"

using namespace arg;

namespace {

using Row = std::vector<std::string>;

bool has(const std::vector<std::string>& list, std::string_view x) {
  return std::find(list.begin(), list.end(), x) != list.end();
}

// The first row whose first cell has `name` as a code span, or nullptr.
const Row* row_naming(const std::vector<Row>& rows, std::string_view name) {
  for (const Row& row : rows)
    if (!row.empty() && has(test::code_spans(row[0]), name)) return &row;
  return nullptr;
}

// The code spans of a cell, none when the row is shorter.
std::vector<std::string> spans_of(const Row& row, std::size_t cell) {
  return cell < row.size() ? test::code_spans(row[cell]) : std::vector<std::string>{};
}

// "key=value key=value" (a canonical text) as a map.
std::map<std::string, std::string> values_of(const std::string& text) {
  std::map<std::string, std::string> values;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find(' ', at);
    if (end == std::string::npos) end = text.size();
    const std::string pair = text.substr(at, end - at);
    const std::size_t eq = pair.find('=');
    values[pair.substr(0, eq)] = pair.substr(eq + 1);
    at = end + 1;
  }
  return values;
}

// The table "Weight keys": a row per weight or switch, its first cell the symbol and its readable
// names, then the default (as format_weights writes it) and the range (a switch's words).
std::vector<std::string> weight_key_problems(const std::string& doc) {
  std::vector<std::string> problems;
  const std::vector<Row> rows = test::table_rows(test::section(doc, "Weight keys"));
  const auto defaults = values_of(format_weights(Weights{}));
  for (const WeightKey& k : weight_keys()) {
    const std::string name(k.name), symbol(k.symbol);
    const Row* row = row_naming(rows, name);
    if (!row) {
      problems.push_back("weight key " + name + ": no row of \"Weight keys\" names it");
      continue;
    }
    if (!has(spans_of(*row, 0), symbol))
      problems.push_back("weight key " + name + ": its row is not that of " + symbol);
    if (!has(spans_of(*row, 1), defaults.at(symbol)))
      problems.push_back("weight key " + name + ": the default is not `" + defaults.at(symbol) +
                         "`");
    for (std::string_view word : k.words)
      if (!has(spans_of(*row, 2), word))
        problems.push_back("weight key " + name + ": the range does not name `" +
                           std::string(word) + "`");
  }
  for (const Row& row : rows)
    for (const std::string& span : spans_of(row, 0))
      if (std::none_of(weight_keys().begin(), weight_keys().end(),
                       [&](const WeightKey& k) { return k.name == span; }))
        problems.push_back("weight key " + span + ": documented, but the parser refuses it");
  return problems;
}

// The table "Presets": a row per preset, its first cell the name (or names).
std::vector<std::string> preset_problems(const std::string& doc) {
  std::vector<std::string> problems;
  const std::vector<Row> rows = test::table_rows(test::section(doc, "Presets"));
  for (std::string_view preset : weight_presets())
    if (!row_naming(rows, preset))
      problems.push_back("preset " + std::string(preset) + ": no row of \"Presets\" names it");
  for (const Row& row : rows)
    for (const std::string& span : spans_of(row, 0))
      if (std::find(weight_presets().begin(), weight_presets().end(), span) ==
          weight_presets().end())
        problems.push_back("preset " + span + ": documented, but the parser refuses it");
  return problems;
}

// The table "Build options": a row per key, then its values ("lo to hi", or the words of a
// choice) and its default (as format_build_options writes it; threads as its number).
std::vector<std::string> build_option_problems(const std::string& doc) {
  std::vector<std::string> problems;
  const std::vector<Row> rows = test::table_rows(test::section(doc, "Build options"));
  auto defaults = values_of(format_build_options(BuildOptions{}));
  defaults["threads"] = std::to_string(BuildOptions{}.threads);
  for (const BuildOptionKey& k : build_option_keys()) {
    const std::string name(k.name);
    const Row* row = row_naming(rows, name);
    if (!row) {
      problems.push_back("build option " + name + ": no row of \"Build options\" names it");
      continue;
    }
    const std::string range = std::to_string(k.lo) + " to " + std::to_string(k.hi);
    if (k.words.empty() && (row->size() < 2 || (*row)[1].find(range) == std::string::npos))
      problems.push_back("build option " + name + ": the values are not \"" + range + "\"");
    for (std::string_view word : k.words)
      if (!has(spans_of(*row, 1), word))
        problems.push_back("build option " + name + ": the values do not name `" +
                           std::string(word) + "`");
    if (!has(spans_of(*row, 2), defaults.at(name)))
      problems.push_back("build option " + name + ": the default is not `" + defaults.at(name) +
                         "`");
  }
  for (const Row& row : rows)
    for (const std::string& span : spans_of(row, 0))
      if (std::none_of(build_option_keys().begin(), build_option_keys().end(),
                       [&](const BuildOptionKey& k) { return k.name == span; }))
        problems.push_back("build option " + span + ": documented, but the parser refuses it");
  return problems;
}

std::string listed(const std::vector<std::string>& problems) {
  std::string out;
  for (const std::string& p : problems) out += "\n  " + p;
  return out;
}

// `doc` with `from` replaced by `to` once (the test fails if `from` is not there).
std::string edited(std::string doc, const std::string& from, const std::string& to) {
  const std::size_t at = doc.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) doc.replace(at, from.size(), to);
  return doc;
}

// `doc` without the table row whose first cell starts with `first`.
std::string without_row(const std::string& doc, const std::string& first) {
  const std::size_t at = doc.find("\n| " + first);
  EXPECT_NE(at, std::string::npos) << first;
  if (at == std::string::npos) return doc;
  return doc.substr(0, at) + doc.substr(doc.find('\n', at + 1));
}

bool mentions(const std::vector<std::string>& problems, const std::string& what) {
  return std::any_of(problems.begin(), problems.end(),
                     [&](const std::string& p) { return p.rfind(what, 0) == 0; });
}

}  // namespace

TEST(Reference, IsThere) {
  EXPECT_GT(test::read_reference().size(), 1000u) << ARG_SOURCE_DIR "/docs/REFERENCE.md";
}

TEST(Reference, NamesEveryWeightKeyWithItsDefault) {
  const auto problems = weight_key_problems(test::read_reference());
  EXPECT_TRUE(problems.empty()) << "docs/REFERENCE.md:" << listed(problems);
}

TEST(Reference, NamesEveryPreset) {
  const auto problems = preset_problems(test::read_reference());
  EXPECT_TRUE(problems.empty()) << "docs/REFERENCE.md:" << listed(problems);
}

TEST(Reference, NamesEveryBuildOptionWithItsValuesAndDefault) {
  const auto problems = build_option_problems(test::read_reference());
  EXPECT_TRUE(problems.empty()) << "docs/REFERENCE.md:" << listed(problems);
}

// The checks above can fail: each edit of the reference below is caught.
TEST(Reference, ChecksCatchAMissingOrWrongEntry) {
  const std::string doc = test::read_reference();
  ASSERT_FALSE(doc.empty());
  EXPECT_TRUE(
      mentions(weight_key_problems(edited(doc, ", `curvature`", "")), "weight key curvature"));
  EXPECT_TRUE(mentions(weight_key_problems(without_row(doc, "`norm`")), "weight key norm"));
  EXPECT_TRUE(mentions(weight_key_problems(edited(doc, "| `lambda_3`", "| `lambda_3`, `shine`")),
                       "weight key shine"));
  EXPECT_TRUE(mentions(preset_problems(without_row(doc, "`mrg`")), "preset mrg"));
  EXPECT_TRUE(mentions(build_option_problems(without_row(doc, "`levels`")), "build option levels"));
  EXPECT_TRUE(
      mentions(build_option_problems(edited(doc, "`auto`, `mesh`, `proxy`", "`auto`, `mesh`")),
               "build option surface"));
  const std::vector<std::string> base_points =
      build_option_problems(edited(doc, "8 to 4096", "8 to 1024"));
  EXPECT_TRUE(mentions(base_points, "build option base_points")) << listed(base_points);
}
