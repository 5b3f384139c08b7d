// argtool eval --per-class: each class's NN and FT, held out beside training and the peers.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "eval/label_file.hpp"
#include "eval/retrieval_metrics.hpp"

namespace argtool {

// What one set's table shows: arg under two sets of weights, and each peer.
struct PerClassColumns {
  std::string set;
  const arg::LabelSet* labels = nullptr;
  arg::RetrievalScores training;                 // --weights (default: the shipped ones)
  std::optional<arg::RetrievalScores> held_out;  // weights learnt without this set
  std::string training_weights, held_out_weights;
  std::string training_label;  // where the training weights came from, for the heading
  std::vector<std::pair<std::string, arg::RetrievalScores>> peers;  // by method name
  // The run's other --method methods (d2, profile, ...), scored on the same models.
  std::vector<std::pair<std::string, arg::RetrievalScores>> methods;
};

// A row per class in label order (size, held-out NN and FT, training NN and FT, each other
// method's FT, each peer's FT), then "all" (the means over every query). "-" where a class of one
// has nothing to find or the held-out weights are missing.
std::string per_class_text(const PerClassColumns& columns);

// The same numbers, unrounded: {set, training_weights, held_out_weights, classes: [{class,
// size, queries, training: {nn, ft}, held_out, methods and peers: {name: {nn, ft}}}], all:
// {...}}; held_out
// and a class of one's scores are null.
nlohmann::json per_class_json(const PerClassColumns& columns);

}  // namespace argtool
