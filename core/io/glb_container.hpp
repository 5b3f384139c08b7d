// Checking a GLB file's header, chunks and JSON before tinygltf parses it.
#pragma once

#include <cstddef>
#include <string_view>

namespace arg::io {

struct GlbChunks {
  std::string_view json;
  std::string_view bin;    // empty when there is no BIN chunk
  std::size_t length = 0;  // the length the header declares (trailing bytes are ignored)
};

// Validates the 12-byte header and the JSON and BIN chunk headers against the data size (GLB:
// byte offset N: ...). tinygltf 2.7 checks these too, but lets the BIN chunk end up to 8 bytes
// past the data.
GlbChunks check_glb_container(std::string_view bytes);

// Checks the JSON text before tinygltf sees it: nesting depth (tinygltf converts "extras" and
// "extensions" recursively), and the buffers: at most the first may use the BIN chunk (tinygltf
// copies the whole chunk for every buffer without a uri), others must be data: URIs (no
// external files), declared lengths must fit, and buffer views must lie inside their buffers.
void check_gltf_json(const GlbChunks& chunks);

}  // namespace arg::io
