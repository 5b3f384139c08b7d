// PANORAMA and the Laplace spectrum: blind to pose and scale (the spectrum to bending); they tell
// shapes apart.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "eval/baseline_descriptors.hpp"
#include "features/laplace_spectrum.hpp"
#include "features/panorama_descriptor.hpp"
#include "test_shapes.hpp"

namespace arg {
namespace {

Eigen::Matrix3d turn(double angle, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

std::vector<float> panorama_of(const Mesh& m) {
  return panorama_descriptor(posed_for_descriptors(m));
}

TEST(Panorama, ATurnedMovedScaledCopyIsNearAndAnotherShapeFar) {
  const Mesh capsule = test::capsule(2, 0.5);
  const Mesh copy = test::transformed(capsule, turn(0.9, {1, 2, 3}), {4, -1, 2}, 2.5);
  const std::vector<float> a = panorama_of(capsule), b = panorama_of(copy);
  ASSERT_EQ(a.size(), std::size_t(kPanoramaSize));
  const double near = panorama_distance(a, b);
  const double far = panorama_distance(a, panorama_of(test::torus()));
  EXPECT_LT(near, 0.02);
  EXPECT_GT(far, 5 * near);
  EXPECT_EQ(panorama_distance(a, a), 0.0);
  EXPECT_EQ(panorama_distance(a, {}), 1.0);
}

TEST(Panorama, TurningAViewAboutItsAxisLeavesTheFeaturesAsTheyAre) {
  // A turn about the axis shifts every row of a view by whole columns.
  PanoramicViews v = panoramic_views(posed_for_descriptors(test::torus(2, 0.4)), 16, 2.5);
  PanoramicViews shifted = v;
  for (auto& image : shifted.image)
    for (int y = 0; y < v.height; ++y)
      std::rotate(image.begin() + y * v.width, image.begin() + y * v.width + 5,
                  image.begin() + (y + 1) * v.width);
  const std::vector<float> a = panorama_features(v, 6, 4), b = panorama_features(shifted, 6, 4);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-6);
}

// The mean of the orientation images over the samples where a surface was seen.
double mean_facing(const PanoramicViews& v) {
  double sum = 0;
  int seen = 0;
  for (int a = 0; a < 3; ++a)
    for (std::size_t k = 0; k < v.image[std::size_t(2 * a)].size(); ++k)
      if (v.image[std::size_t(2 * a)][k] > 0) sum += v.image[std::size_t(2 * a + 1)][k], ++seen;
  return seen ? sum / seen : 0;
}

TEST(Panorama, NoiseThatScattersTheNormalsBarelyDarkensTheOrientationImages) {
  // A fine sphere, its vertices moved 0.3% of its size at random: every face's normal tilts
  // by several degrees, its extent barely moves.
  const Mesh sphere = test::sphere(120, 180);
  Mesh noisy = sphere;
  std::uint64_t state = 12345;
  auto unit = [&state] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / double(1ULL << 53) - 0.5;
  };
  for (Eigen::Index v = 0; v < noisy.V.rows(); ++v)
    for (int a = 0; a < 3; ++a) noisy.V(v, a) += 0.02 * unit();  // sd about 0.006 = 0.3% of 2
  const double clean = mean_facing(panoramic_views(sphere, 64, 2.5));
  const double rough = mean_facing(panoramic_views(noisy, 64, 2.5));
  EXPECT_GT(clean, 0.4);
  EXPECT_GT(rough, clean - 0.08) << clean << " " << rough;  // the normals alone: -0.11
}

// A w x h grid sheet, flat or rolled into a cylinder of radius `radius` (isometric: lengths on
// the sheet do not change).
Mesh sheet(double w, double h, int nx, int ny, double radius) {
  Mesh m;
  m.V.resize((nx + 1) * (ny + 1), 3);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double x = w * i / nx, y = h * j / ny;
      if (radius > 0)
        m.V.row(j * (nx + 1) + i) << radius * std::sin(x / radius), y,
            radius * (1 - std::cos(x / radius));
      else
        m.V.row(j * (nx + 1) + i) << x, y, 0;
    }
  m.F.resize(2 * nx * ny, 3);
  int f = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
      m.F.row(f++) << a, b, d;
      m.F.row(f++) << a, d, c;
    }
  return m;
}

TEST(LaplaceSpectrum, TheUnitSphereHasTheEigenvaluesOfTheSphericalHarmonics) {
  // -Delta Y_lm = l (l + 1) Y_lm on the unit sphere: 2 three times, then 6 five times. With area
  // 4 pi the stored values are lambda_i / i.
  const std::vector<float> s = laplace_spectrum(test::sphere(60, 90));
  ASSERT_EQ(s.size(), std::size_t(kSpectrumSize));
  for (int i = 1; i <= 3; ++i) EXPECT_NEAR(s[std::size_t(i - 1)] * i, 2.0, 0.04) << i;
  for (int i = 4; i <= 8; ++i) EXPECT_NEAR(s[std::size_t(i - 1)] * i, 6.0, 0.15) << i;
}

TEST(LaplaceSpectrum, BendingAndScalingChangeItLittleButProportionsDo) {
  const std::vector<float> flat = laplace_spectrum(sheet(M_PI, 1, 60, 20, 0));
  const std::vector<float> rolled = laplace_spectrum(sheet(M_PI, 1, 60, 20, 1.0));
  ASSERT_EQ(flat.size(), std::size_t(kSpectrumSize));
  EXPECT_LT(spectrum_distance(flat, rolled), 0.02);
  const Mesh capsule = test::capsule(2, 0.5);
  const std::vector<float> a = laplace_spectrum(capsule);
  const std::vector<float> b =
      laplace_spectrum(test::transformed(capsule, turn(0.4, {0, 1, 1}), {1, 2, 3}, 3.0));
  EXPECT_LT(spectrum_distance(a, b), 0.02);
  EXPECT_GT(spectrum_distance(a, laplace_spectrum(test::capsule(0.5, 0.5))), 0.2);
  EXPECT_EQ(spectrum_distance(a, a), 0.0);
  EXPECT_EQ(spectrum_distance(a, {}), 1.0);
}

TEST(LaplaceSpectrum, AMeshTooSmallHasNone) {
  EXPECT_TRUE(laplace_spectrum(test::sphere(4, 5)).empty());
}

}  // namespace
}  // namespace arg
