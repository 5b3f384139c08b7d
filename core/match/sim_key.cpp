// Packing nodes into sim keys, and the group sim read from them.
#include "match/sim_key.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "graph/quantise.hpp"

namespace arg {

// The argument above needs each product rounded to a float (not held in x87 registers).
static_assert(FLT_EVAL_METHOD == 0, "float arithmetic in float");

static_assert(kCurvatureBins <= kCordBins, "codes_of decodes into kCordBins floats");

namespace {

// Codes of `count` (at most kCordBins) bins of a histogram of `total`, when format 3's decoder
// (bins_values) gives the bins back exactly from them.
bool codes_of(const float* bins, std::size_t count, float total, std::uint8_t* out) {
  const float step = code_step(total);
  for (std::size_t k = 0; k < count; ++k) {
    const float q = step > 0 ? std::nearbyint(bins[k] / step) : 0.0f;
    if (!(q >= 0.0f && q <= 255.0f)) return false;
    out[k] = std::uint8_t(q);
  }
  float back[kCordBins];
  bins_values(out, count, total, back);
  return std::memcmp(back, bins, sizeof(float) * count) == 0;
}

// histogram_min over codes: the same float bins and the same sum, in any order. With
// E = floor(log2(min(sx, sy))), a nonzero minimum (both codes >= 1) is a float of at least
// 2^E, so a multiple of 2^(E - 23), and below 255 min(sx, sy) < 2^(E + 9): eight of them and
// every partial sum are integers below 2^35 in units of 2^(E - 23), which a double holds
// exactly. Four running sums let the compiler use vector lanes.
template <std::size_t N>
double codes_min(const std::uint8_t* x, float sx, const std::uint8_t* y, float sy) {
#if defined(__SSE2__)
  // The same sums four codes at a time (every x86-64 has SSE2): lane q of the two double
  // pairs is part[q] below, each float product, minimum and double sum the same IEEE
  // operation, so the bits are those of the loop (test_sim_key.cpp checks them). It runs on
  // every pair of nodes a ranking compares.
  const __m128i zero = _mm_setzero_si128();
  const __m128 vx = _mm_set1_ps(sx), vy = _mm_set1_ps(sy);
  __m128d lo = _mm_setzero_pd(), hi = _mm_setzero_pd();  // part[0..1], part[2..3]
  for (std::size_t k = 0; k < N; k += 4) {
    std::int32_t wx, wy;
    std::memcpy(&wx, x + k, 4);
    std::memcpy(&wy, y + k, 4);
    const __m128i ix = _mm_unpacklo_epi16(_mm_unpacklo_epi8(_mm_cvtsi32_si128(wx), zero), zero);
    const __m128i iy = _mm_unpacklo_epi16(_mm_unpacklo_epi8(_mm_cvtsi32_si128(wy), zero), zero);
    const __m128 bx = _mm_mul_ps(_mm_cvtepi32_ps(ix), vx), by = _mm_mul_ps(_mm_cvtepi32_ps(iy), vy);
    // bx < by ? bx : by, which is what _mm_min_ps(bx, by) gives (its second operand unless
    // the first is smaller), NaN included.
    const __m128 m = _mm_min_ps(bx, by);
    lo = _mm_add_pd(lo, _mm_cvtps_pd(m));
    hi = _mm_add_pd(hi, _mm_cvtps_pd(_mm_movehl_ps(m, m)));
  }
  double part[4];
  _mm_storeu_pd(part, lo);
  _mm_storeu_pd(part + 2, hi);
#else
  double part[4] = {0, 0, 0, 0};
  for (std::size_t k = 0; k < N; k += 4)
    for (std::size_t q = 0; q < 4; ++q) {
      const float bx = float(x[k + q]) * sx, by = float(y[k + q]) * sy;
      part[q] += bx < by ? bx : by;
    }
#endif
  return (part[0] + part[1]) + (part[2] + part[3]);
}

}  // namespace

bool make_sim_keys(const ArgGraph& g, std::vector<SimKey>& out) {
  out.resize(g.nodes.size());
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const ArgNode& n = g.nodes[i];
    SimKey& k = out[i];
    k.a = n.a, k.l = n.l, k.v = n.v, k.step = code_step(n.a);
    std::uint8_t* code = k.code.data();
    if (!codes_of(n.cords.data(), kCordBins, n.a, code) ||
        !codes_of(n.curv_mean.data(), kCurvatureBins, n.a, code + kCordBins) ||
        !codes_of(n.curv_gauss.data(), kCurvatureBins, n.a, code + kCordBins + kCurvatureBins)) {
      out.clear();
      return false;
    }
  }
  return true;
}

double key_sim(const SimKey& m, const SimKey& n, const Weights& w) {
  // The terms of node_similarity.cpp's sim_terms, in its order.
  double s = w.alpha_s * double(std::min(m.a, n.a)) + w.beta_s * double(std::min(m.l, n.l));
  if (w.lambda_1 > 0) s += w.lambda_1 * double(std::min(m.v, n.v));
  const std::uint8_t *x = m.code.data(), *y = n.code.data();
  if (w.lambda_2 > 0) s += w.lambda_2 * codes_min<kCordBins>(x, m.step, y, n.step);
  if (w.lambda_3 > 0)
    s += w.lambda_3 * 0.5 *
         (codes_min<kCurvatureBins>(x + kCordBins, m.step, y + kCordBins, n.step) +
          codes_min<kCurvatureBins>(x + kCordBins + kCurvatureBins, m.step,
                                    y + kCordBins + kCurvatureBins, n.step));
  return s;
}

}  // namespace arg
