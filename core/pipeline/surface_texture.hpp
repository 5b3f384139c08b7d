// A texture's coordinates carried from the mesh as read onto the surface its ARG is built on.
#pragma once

#include <vector>

#include "common/build_options.hpp"
#include "common/limits.hpp"
#include "mesh/mesh.hpp"
#include "pipeline/node_positions.hpp"

namespace arg {

struct SurfaceTexture {
  std::vector<float> uv;       // 6 per face of the surface: (s, t) at corners 0, 1, 2
  std::vector<char> textured;  // per face: 1 when uv holds its coordinates, 0 (and uv 0) if not
  std::vector<int> origin;     // per face: the input triangle it comes from, -1 for one made
};

// node_positions(input, options, stop, shown), and in `texture` the input's texture coordinates
// (`input_uv`, 6 per row of input.F, NaN for a triangle without) on each face of the surface it
// returns. A face takes them from the input triangle it comes from (cleaning, the pose and the
// proxy keep each face's origin), at that triangle's point with the face corner's barycentric
// coordinates (clamped into it): the corner itself for a face the cleaning kept, the nearby point
// for a proxy's face. Faces the preparation made (filled holes, tubes between pieces) have none.
// The surface's colours, when the input has some, are its faces' origins' colours, and for faces
// made the mean of their neighbours' (node_positions mixes those of the rim instead). Mesh,
// mu and levels are node_positions' own. Throws like it, and InputError when input_uv is not 6
// per triangle.
NodePositions node_positions_with_texture(const Mesh& input, const std::vector<float>& input_uv,
                                          const BuildOptions& options, SurfaceTexture* texture,
                                          const StopRequested& stop = {},
                                          ShownSurface shown = ShownSurface::Built);

}  // namespace arg
