// The per-class tables of argtool eval, as text for people and JSON for scripts.
#include "per_class_table.hpp"

#include <algorithm>
#include <cstdio>

#include "peer_matrices.hpp"

namespace argtool {

namespace {

// One score as the table prints it: three decimals, or "-" when there is nothing to show.
std::string cell(bool shown, double x, int width) {
  char buf[32];
  if (shown)
    std::snprintf(buf, sizeof buf, "%*.3f", width, x);
  else
    std::snprintf(buf, sizeof buf, "%*s", width, "-");
  return buf;
}

nlohmann::json scores(bool shown, double nn, double ft) {
  return shown ? nlohmann::json{{"nn", nn}, {"ft", ft}} : nlohmann::json(nullptr);
}

}  // namespace

std::string per_class_text(const PerClassColumns& k) {
  const arg::LabelSet& labels = *k.labels;
  std::size_t name_width = 5;
  for (const std::string& c : labels.classes) name_width = std::max(name_width, c.size());
  std::vector<int> size(labels.classes.size(), 0);
  for (int c : labels.class_of) ++size[std::size_t(c)];
  char buf[256];
  std::string out = "per class: " + k.set + " (held out: weights learnt without " + k.set +
                    (k.held_out ? "" : ", not given (--weights-per-set)") +
                    "; training: " + k.training_label + ")\n";
  std::snprintf(buf, sizeof buf, "%-*s %5s %8s %8s %9s %9s", int(name_width), "class", "size",
                "held NN", "held FT", "train NN", "train FT");
  out += buf;
  // The other methods' columns, then the peers', each as wide as its heading.
  std::vector<std::string> headings;
  for (const auto& m : k.methods) headings.push_back(m.first + " FT");
  for (const auto& p : k.peers) headings.push_back(peer_heading(p.first) + " FT");
  std::vector<int> widths;
  for (const std::string& h : headings) {
    widths.push_back(std::max(7, int(h.size())));
    std::snprintf(buf, sizeof buf, " %*s", widths.back(), h.c_str());
    out += buf;
  }
  out += '\n';
  auto row = [&](const std::string& name, int n, bool shown, double hnn, double hft, double tnn,
                 double tft, const std::vector<double>& peer_ft) {
    std::snprintf(buf, sizeof buf, "%-*s %5d", int(name_width), name.c_str(), n);
    out += buf;
    out += " " + cell(shown && k.held_out.has_value(), hnn, 8) + " " +
           cell(shown && k.held_out.has_value(), hft, 8);
    out += " " + cell(shown, tnn, 9) + " " + cell(shown, tft, 9);
    for (std::size_t i = 0; i < peer_ft.size(); ++i)
      out += " " + cell(shown, peer_ft[i], widths[i]);
    out += '\n';
  };
  for (std::size_t c = 0; c < labels.classes.size(); ++c) {
    std::vector<double> peer_ft;
    for (const auto& m : k.methods) peer_ft.push_back(m.second.ft_per_class[c]);
    for (const auto& p : k.peers) peer_ft.push_back(p.second.ft_per_class[c]);
    const double hnn = k.held_out ? k.held_out->nn_per_class[c] : 0;
    const double hft = k.held_out ? k.held_out->ft_per_class[c] : 0;
    row(labels.classes[c], size[c], k.training.queries_per_class[c] > 0, hnn, hft,
        k.training.nn_per_class[c], k.training.ft_per_class[c], peer_ft);
  }
  std::vector<double> peer_ft;
  for (const auto& m : k.methods) peer_ft.push_back(m.second.ft);
  for (const auto& p : k.peers) peer_ft.push_back(p.second.ft);
  row("all", int(labels.class_of.size()), true, k.held_out ? k.held_out->nn : 0,
      k.held_out ? k.held_out->ft : 0, k.training.nn, k.training.ft, peer_ft);
  return out;
}

nlohmann::json per_class_json(const PerClassColumns& k) {
  const arg::LabelSet& labels = *k.labels;
  std::vector<int> size(labels.classes.size(), 0);
  for (int c : labels.class_of) ++size[std::size_t(c)];
  nlohmann::json classes = nlohmann::json::array();
  for (std::size_t c = 0; c < labels.classes.size(); ++c) {
    const bool shown = k.training.queries_per_class[c] > 0;
    nlohmann::json methods = nlohmann::json::object(), peers = nlohmann::json::object();
    for (const auto& m : k.methods)
      methods[m.first] = scores(shown, m.second.nn_per_class[c], m.second.ft_per_class[c]);
    for (const auto& p : k.peers)
      peers[p.first] = scores(shown, p.second.nn_per_class[c], p.second.ft_per_class[c]);
    classes.push_back(
        {{"class", labels.classes[c]},
         {"size", size[c]},
         {"queries", k.training.queries_per_class[c]},
         {"training", scores(shown, k.training.nn_per_class[c], k.training.ft_per_class[c])},
         {"held_out", scores(shown && k.held_out, k.held_out ? k.held_out->nn_per_class[c] : 0,
                             k.held_out ? k.held_out->ft_per_class[c] : 0)},
         {"methods", methods},
         {"peers", peers}});
  }
  nlohmann::json methods = nlohmann::json::object(), peers = nlohmann::json::object();
  for (const auto& m : k.methods) methods[m.first] = scores(true, m.second.nn, m.second.ft);
  for (const auto& p : k.peers) peers[p.first] = scores(true, p.second.nn, p.second.ft);
  return {{"set", k.set},
          {"training_weights", k.training_weights},
          {"held_out_weights",
           k.held_out ? nlohmann::json(k.held_out_weights) : nlohmann::json(nullptr)},
          {"classes", classes},
          {"all",
           {{"size", labels.class_of.size()},
            {"training", scores(true, k.training.nn, k.training.ft)},
            {"held_out", scores(bool(k.held_out), k.held_out ? k.held_out->nn : 0,
                                k.held_out ? k.held_out->ft : 0)},
            {"methods", methods},
            {"peers", peers}}}};
}

}  // namespace argtool
