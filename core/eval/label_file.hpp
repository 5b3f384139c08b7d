// Labelled model lists for the quality harness: CSV with the header model_id,path,class.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace arg {

struct LabelledModel {
  std::string id, path, label;  // path as written in the file (relative to the file's folder)
};

struct LabelSet {
  std::vector<LabelledModel> models;
  std::vector<std::string> classes;  // distinct labels in order of first appearance
  std::vector<int> class_of;         // per model, index into classes
};

// Parses the CSV text. Fields may be double-quoted ("" inside quotes is a quote). Throws
// InputError naming the line for a wrong header, a wrong field count, an empty field or a
// repeated model_id.
LabelSet parse_label_csv(std::string_view text);

}  // namespace arg
