// Two models side by side with their matched nodes at one level linked and coloured by pair.
#pragma once

#include <string>
#include <vector>

#include "match/similarity.hpp"
#include "pipeline/node_positions.hpp"
#include "render/canvas.hpp"
#include "render/rasterise_mesh.hpp"
#include "render/view_camera.hpp"

namespace arg {

struct MatchPictureOptions {
  int panel = 512;  // width and height of each model's picture
  int level = 2;
  Eigen::Matrix3d view = view_rotation(0, 0);  // applied to both models in their own frames
  Shading shading = Shading::Smooth;
  std::string title_a, title_b;    // captions of the two panels
  std::vector<std::string> notes;  // text lines under the panels (scores, explanations)
  int ranked_labels = 3;           // the best pairs get their rank written next to both nodes
};

struct MatchPicture {
  Image image;
  int links = 0;      // lines drawn between matched nodes
  int matched_a = 0;  // nodes of A at the level that belong to a match
  int matched_b = 0;
};

// Each model in its own aligned frame, seen from `options.view`, on a neutral surface; the groups
// matched at `options.level` (rows of `matches` as filled by arg_similarity(A, B, ...)) ranked by
// their sim, best first, and coloured by rank: both ends of a pair share a colour, unmatched nodes
// stay white, and each matched row is a line from A's node to B's. Throws InputError for a
// level either model lacks.
MatchPicture render_match_picture(const NodePositions& a, const NodePositions& b,
                                  const std::vector<MatchPair>& matches,
                                  const MatchPictureOptions& options);

}  // namespace arg
