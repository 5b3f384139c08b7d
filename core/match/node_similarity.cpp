// Loss and sim between two nodes or node groups (paper sections 3.3 and 4.1).
#include "match/node_similarity.hpp"

#include <algorithm>

namespace arg {

namespace {

template <class A, class B>
double sim_terms(const A& m, const B& n, double a, double l, double v, const Weights& w) {
  double s = w.alpha_s * a + w.beta_s * l;
  if (w.lambda_1 > 0) s += w.lambda_1 * v;
  if (w.lambda_2 > 0) s += w.lambda_2 * histogram_min(m.cords, n.cords);
  if (w.lambda_3 > 0)
    s += w.lambda_3 * 0.5 *
         (histogram_min(m.curv_mean, n.curv_mean) + histogram_min(m.curv_gauss, n.curv_gauss));
  if (w.lambda_4 > 0) s += w.lambda_4 * histogram_min(m.colour, n.colour) / 3.0;
  return s;
}

}  // namespace

void NodeMass::add(const ArgNode& n) {
  a += n.a, l += n.l, v += n.v;
  for (std::size_t k = 0; k < cords.size(); ++k) cords[k] += n.cords[k];
  for (std::size_t k = 0; k < curv_mean.size(); ++k)
    curv_mean[k] += n.curv_mean[k], curv_gauss[k] += n.curv_gauss[k];
  for (std::size_t k = 0; k < colour.size(); ++k) colour[k] += n.colour[k];
}

double node_sim(const NodeMass& m, const NodeMass& n, const Weights& w) {
  return sim_terms(m, n, std::min(m.a, n.a), std::min(m.l, n.l), std::min(m.v, n.v), w);
}

double node_sim(const ArgNode& m, const ArgNode& n, const Weights& w) {
  return sim_terms(m, n, std::min(m.a, n.a), std::min(m.l, n.l), std::min(m.v, n.v), w);
}

}  // namespace arg
