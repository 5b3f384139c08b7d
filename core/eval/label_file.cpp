// A small strict CSV reader for labelled model lists.
#include "eval/label_file.hpp"

#include <set>

#include "common/errors.hpp"

namespace arg {

namespace {

std::vector<std::string> split_csv_line(std::string_view line, int number) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"')
        fields.back() += '"', ++i;
      else if (c == '"')
        quoted = false;
      else
        fields.back() += c;
    } else if (c == '"' && fields.back().empty()) {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  if (quoted) throw InputError("labels: line " + std::to_string(number) + ": unterminated quote");
  return fields;
}

}  // namespace

LabelSet parse_label_csv(std::string_view text) {
  LabelSet set;
  std::set<std::string> ids;
  int number = 0;
  std::size_t pos = 0;
  bool header = true;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty()) continue;
    std::vector<std::string> f = split_csv_line(line, number);
    if (header) {
      if (f.size() != 3 || f[0] != "model_id" || f[1] != "path" || f[2] != "class")
        throw InputError("labels: line " + std::to_string(number) +
                         ": header must be model_id,path,class");
      header = false;
      continue;
    }
    if (f.size() != 3)
      throw InputError("labels: line " + std::to_string(number) + ": expected 3 fields, found " +
                       std::to_string(f.size()));
    for (const auto& x : f)
      if (x.empty()) throw InputError("labels: line " + std::to_string(number) + ": empty field");
    if (!ids.insert(f[0]).second)
      throw InputError("labels: line " + std::to_string(number) + ": repeated model_id " + f[0]);
    int c = -1;
    for (std::size_t k = 0; k < set.classes.size(); ++k)
      if (set.classes[k] == f[2]) c = int(k);
    if (c < 0) c = int(set.classes.size()), set.classes.push_back(f[2]);
    set.models.push_back({f[0], f[1], f[2]});
    set.class_of.push_back(c);
  }
  if (header) throw InputError("labels: empty file (expected the header model_id,path,class)");
  return set;
}

}  // namespace arg
