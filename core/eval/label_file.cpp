// Labelled model lists: the CSV records checked for the header model_id,path,class.
#include "eval/label_file.hpp"

#include <set>

#include "common/errors.hpp"
#include "eval/csv_records.hpp"

namespace arg {

LabelSet parse_label_csv(std::string_view text) {
  LabelSet set;
  std::set<std::string> ids;
  bool header = true;
  for (const CsvRecord& record : parse_csv_records(text, "labels")) {
    const int number = record.line;
    const std::vector<std::string>& f = record.fields;
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
