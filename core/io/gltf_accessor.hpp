// Reading glTF accessors with every offset, stride and count checked against the buffers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "io/gltf.hpp"

namespace arg::io {

// A validated view of one accessor: construction throws InputError ("GLB: accessor N (what):
// ...") unless every element lies inside its buffer view and buffer. Sparse accessors are not
// supported.
class GltfAccessor {
 public:
  GltfAccessor(const tinygltf::Model& model, int accessor, const std::string& what);

  std::size_t count() const { return count_; }
  int components() const { return components_; }
  bool is_integer() const { return component_type_ != TINYGLTF_COMPONENT_TYPE_FLOAT; }
  // Component c of element i; normalized integers map to [0,1] or [-1,1].
  double value(std::size_t i, int c) const;
  // Element i of an integer scalar accessor (indices); throws if negative.
  std::uint32_t index(std::size_t i) const;

 private:
  const unsigned char* data_ = nullptr;
  std::size_t count_ = 0;
  std::size_t stride_ = 0;
  int components_ = 0;
  int component_type_ = 0;
  int component_size_ = 0;
  bool normalized_ = false;
  std::string what_;
};

}  // namespace arg::io
