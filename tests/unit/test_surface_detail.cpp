// Surface detail: a bumpy sphere moves further under smoothing than a smooth one, the histograms
// sum to one per scale, and a mesh without area gives zeros.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "eval/baseline_descriptors.hpp"
#include "features/surface_detail.hpp"
#include "test_shapes.hpp"

namespace arg {
namespace {

// The mean bin of one scale's histogram: where its mass sits on the log scale.
double mean_bin(const std::vector<float>& h, int scale, int bins) {
  double sum = 0;
  for (int b = 0; b < bins; ++b) sum += b * double(h[std::size_t(scale * bins + b)]);
  return sum;
}

TEST(SurfaceDetail, BumpsMoveFurtherThanASmoothSurface) {
  const Mesh smooth = posed_for_descriptors(test::sphere(60, 90));
  Mesh bumpy = test::sphere(60, 90);
  for (Eigen::Index v = 0; v < bumpy.V.rows(); ++v)  // ridges of 3% of the radius
    bumpy.V.row(v) *= 1 + 0.03 * std::sin(40 * bumpy.V(v, 2)) *
                              std::sin(7 * std::atan2(bumpy.V(v, 1), bumpy.V(v, 0)));
  const std::vector<float> a = surface_detail(smooth),
                           b = surface_detail(posed_for_descriptors(bumpy));
  ASSERT_EQ(a.size(), 32u);
  ASSERT_EQ(b.size(), 32u);
  for (int scale = 0; scale < 2; ++scale) {
    EXPECT_NEAR(std::accumulate(a.begin() + 16 * scale, a.begin() + 16 * (scale + 1), 0.0), 1.0,
                1e-5);
    EXPECT_NEAR(std::accumulate(b.begin() + 16 * scale, b.begin() + 16 * (scale + 1), 0.0), 1.0,
                1e-5);
    EXPECT_GT(mean_bin(b, scale, 16), mean_bin(a, scale, 16) + 2) << scale;  // 4 bins a decade
  }
}

TEST(SurfaceDetail, AMeshWithoutAreaGivesZeros) {
  Mesh flat = test::sphere(10, 12);
  flat.V.setZero();
  const std::vector<float> h = surface_detail(flat);
  ASSERT_EQ(h.size(), 32u);
  for (float x : h) EXPECT_EQ(x, 0.0f);
}

}  // namespace
}  // namespace arg
