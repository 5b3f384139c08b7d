// A texture's coordinates carried onto the prepared surface through each face's origin.
#include "pipeline/surface_texture.hpp"

#include <cmath>
#include <cstdint>

#include "common/errors.hpp"

namespace arg {

namespace {

// Each input triangle's number travels through the preparation in its colour, which every stage
// carries with its face (clean_mesh, face_subset, the proxy's source face) and mixes for a face
// it makes (fill_holes, bridge_pieces: means of the rim's faces). Three integers below 2^24,
// exact in a float; the third is a hash of the number, which a mean of several faces' codes
// does not match (but for a chance of 2^-20 per made face, which then shows a wrong spot).
constexpr std::uint32_t kLow = 4096;
float check_code(std::uint32_t f) {
  return float(((f * 2654435761u) >> 8) & 0xFFFFFu);
}

FaceColours origin_codes(Eigen::Index faces) {
  FaceColours codes(faces, 3);
  for (Eigen::Index f = 0; f < faces; ++f) {
    const auto n = std::uint32_t(f);
    codes.row(f) << float(n / kLow), float(n % kLow), check_code(n);
  }
  return codes;
}

// The input triangle a face's code names, or -1 for a face the preparation made.
int origin_of(const FaceColours& codes, Eigen::Index f, Eigen::Index input_faces) {
  const float high = codes(f, 0), low = codes(f, 1);
  if (!(high >= 0 && low >= 0 && low < float(kLow)) || high != std::floor(high) ||
      low != std::floor(low) || double(high) * kLow + low >= double(input_faces))
    return -1;
  const auto n = std::uint32_t(high) * kLow + std::uint32_t(low);
  return codes(f, 2) == check_code(n) ? int(n) : -1;
}

// The barycentric coordinates of p's projection on triangle (a, b, c), negative ones set to
// zero and the rest scaled to sum to 1; the centroid's for a triangle without area.
Eigen::Vector3d clamped_weights(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d u = b - a, v = c - a, w = p - a;
  const double uu = u.dot(u), uv = u.dot(v), vv = v.dot(v), wu = w.dot(u), wv = w.dot(v);
  const double det = uu * vv - uv * uv;
  if (!(det > 1e-30 * (uu + vv) * (uu + vv))) return Eigen::Vector3d::Constant(1.0 / 3);
  const double s = (vv * wu - uv * wv) / det, t = (uu * wv - uv * wu) / det;
  Eigen::Vector3d weights(1 - s - t, s, t);
  weights = weights.cwiseMax(0.0);
  const double sum = weights.sum();
  return sum > 0 ? Eigen::Vector3d(weights / sum) : Eigen::Vector3d::Constant(1.0 / 3);
}

// Colours of the faces without an origin: the mean of their known neighbours' (through shared
// vertices), pass after pass inwards; any left (no known face in reach) take the mean of all.
void colour_made_faces(Mesh& mesh, std::vector<char> known, const StopRequested& stop) {
  const Eigen::Index nf = mesh.F.rows();
  for (bool changed = true; changed;) {
    check_interrupt(stop);
    changed = false;
    FaceColours vertex_sum = FaceColours::Zero(mesh.V.rows(), 3);
    std::vector<int> vertex_count(std::size_t(mesh.V.rows()), 0);
    for (Eigen::Index f = 0; f < nf; ++f) {
      if (!known[std::size_t(f)]) continue;
      for (int k = 0; k < 3; ++k) {
        vertex_sum.row(mesh.F(f, k)) += mesh.C.row(f);
        ++vertex_count[std::size_t(mesh.F(f, k))];
      }
    }
    std::vector<char> now = known;
    for (Eigen::Index f = 0; f < nf; ++f) {
      if (known[std::size_t(f)]) continue;
      Eigen::RowVector3f sum = Eigen::RowVector3f::Zero();
      int count = 0;
      for (int k = 0; k < 3; ++k) {
        sum += vertex_sum.row(mesh.F(f, k));
        count += vertex_count[std::size_t(mesh.F(f, k))];
      }
      if (count == 0) continue;
      mesh.C.row(f) = sum / float(count);
      now[std::size_t(f)] = 1;
      changed = true;
    }
    known = std::move(now);
  }
  Eigen::RowVector3f mean = Eigen::RowVector3f::Zero();
  int count = 0;
  for (Eigen::Index f = 0; f < nf; ++f)
    if (known[std::size_t(f)]) mean += mesh.C.row(f), ++count;
  for (Eigen::Index f = 0; f < nf; ++f)
    if (!known[std::size_t(f)])
      mesh.C.row(f) = count ? Eigen::RowVector3f(mean / float(count)) : mean;
}

}  // namespace

NodePositions node_positions_with_texture(const Mesh& input, const std::vector<float>& input_uv,
                                          const BuildOptions& options, SurfaceTexture* texture,
                                          const StopRequested& stop, ShownSurface shown) {
  const Eigen::Index input_faces = input.F.rows();
  if (input_uv.size() != 6 * std::size_t(input_faces))
    throw InputError("texture coordinates: " + std::to_string(input_uv.size()) + " numbers for " +
                     std::to_string(input_faces) + " triangles (6 each)");
  if (input_faces >= Eigen::Index(kLow) * kLow)
    throw LimitError("texture coordinates: more than " + std::to_string(kLow * kLow) +
                     " triangles to carry onto the surface");
  Mesh coded = input;
  coded.C = origin_codes(input_faces);
  NodePositions out = node_positions(coded, options, stop, shown);
  Mesh& surface = out.mesh;
  const Eigen::Index nf = surface.F.rows();
  // Every stage carries colours when the input has them: without, no face has an origin.
  std::vector<int> origin(std::size_t(nf), -1);
  if (surface.C.rows() == nf)
    for (Eigen::Index f = 0; f < nf; ++f)
      origin[std::size_t(f)] = origin_of(surface.C, f, input_faces);

  SurfaceTexture carried;
  carried.uv.assign(6 * std::size_t(nf), 0.0f);
  carried.textured.assign(std::size_t(nf), 0);
  carried.origin = origin;
  // The input's corners in the surface's frame (only their positions are used: a mirroring
  // pose's turned faces do not matter here).
  const Vertices posed = apply_pose(input, out.pose).V;
  for (Eigen::Index f = 0; f < nf; ++f) {
    poll_interrupt(std::size_t(f), stop);
    const int from = origin[std::size_t(f)];
    if (from < 0) continue;
    const float* uv = &input_uv[6 * std::size_t(from)];
    bool finite = true;
    for (int i = 0; i < 6; ++i) finite = finite && std::isfinite(uv[i]);
    if (!finite) continue;
    const Eigen::Vector3d a = posed.row(input.F(from, 0)).transpose(),
                          b = posed.row(input.F(from, 1)).transpose(),
                          c = posed.row(input.F(from, 2)).transpose();
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d w =
          clamped_weights(surface.V.row(surface.F(f, k)).transpose(), a, b, c);
      for (int i = 0; i < 2; ++i)
        carried.uv[6 * std::size_t(f) + 2 * std::size_t(k) + std::size_t(i)] =
            float(w[0] * uv[i] + w[1] * uv[2 + i] + w[2] * uv[4 + i]);
    }
    carried.textured[std::size_t(f)] = 1;
  }

  // The codes give way to the input's colours (or to none, as node_positions gives).
  if (input.has_colour()) {
    std::vector<char> known(std::size_t(nf), 0);
    for (Eigen::Index f = 0; f < nf; ++f) {
      const int from = origin[std::size_t(f)];
      if (from < 0) continue;
      surface.C.row(f) = input.C.row(from);
      known[std::size_t(f)] = 1;
    }
    colour_made_faces(surface, std::move(known), stop);
  } else {
    surface.C.resize(0, 3);
  }

  if (texture) *texture = std::move(carried);
  return out;
}

}  // namespace arg
