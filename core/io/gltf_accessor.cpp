// Reading glTF accessors with every offset, stride and count checked against the buffers.
#include "io/gltf_accessor.hpp"

#include <algorithm>
#include <cstring>

#include "io/polygon_soup.hpp"

namespace arg::io {

namespace {

int component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
    case TINYGLTF_TYPE_MAT2:
      return 4;
    case TINYGLTF_TYPE_MAT3:
      return 9;
    case TINYGLTF_TYPE_MAT4:
      return 16;
    default:
      return 0;
  }
}

}  // namespace

GltfAccessor::GltfAccessor(const tinygltf::Model& model, int accessor, const std::string& what)
    : what_("accessor " + std::to_string(accessor) + " (" + what + ")") {
  auto fail = [&](const std::string& message) { throw_input_error("GLB", what_, message); };
  if (accessor < 0 || std::size_t(accessor) >= model.accessors.size()) fail("does not exist");
  const tinygltf::Accessor& a = model.accessors[std::size_t(accessor)];
  if (a.sparse.isSparse) fail("sparse accessors are not supported");
  component_type_ = a.componentType;
  component_size_ = component_size(a.componentType);
  components_ = component_count(a.type);
  normalized_ = a.normalized;
  if (component_size_ == 0) fail("unknown component type " + std::to_string(a.componentType));
  if (components_ == 0) fail("unknown element type " + std::to_string(a.type));
  count_ = a.count;
  if (count_ == 0) return;
  if (a.bufferView < 0 || std::size_t(a.bufferView) >= model.bufferViews.size()) {
    fail("has no valid buffer view");
  }
  const tinygltf::BufferView& view = model.bufferViews[std::size_t(a.bufferView)];
  if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size()) {
    fail("its buffer view has no valid buffer");
  }
  const std::vector<unsigned char>& buffer = model.buffers[std::size_t(view.buffer)].data;
  if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
    fail("its buffer view lies outside the buffer");
  }
  const std::size_t element = std::size_t(components_) * std::size_t(component_size_);
  stride_ = view.byteStride == 0 ? element : view.byteStride;
  if (stride_ < element) fail("byte stride is smaller than an element");
  // (count - 1) * stride + element <= byteLength - byteOffset, without overflow.
  if (a.byteOffset > view.byteLength || element > view.byteLength - a.byteOffset ||
      (count_ - 1) > (view.byteLength - a.byteOffset - element) / stride_) {
    fail(std::to_string(count_) + " elements run past the end of the buffer view");
  }
  data_ = buffer.data() + view.byteOffset + a.byteOffset;
}

double GltfAccessor::value(std::size_t i, int c) const {
  const unsigned char* p = data_ + i * stride_ + std::size_t(c) * std::size_t(component_size_);
  switch (component_type_) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      std::int8_t v;
      std::memcpy(&v, p, 1);
      return normalized_ ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized_ ? p[0] / 255.0 : p[0];
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      std::int16_t v;
      std::memcpy(&v, p, 2);
      return normalized_ ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized_ ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_INT: {
      std::int32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    default: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

std::uint32_t GltfAccessor::index(std::size_t i) const {
  if (!is_integer() || components_ != 1 || normalized_) {
    throw_input_error("GLB", what_, "indices must be integer scalars");
  }
  const double v = value(i, 0);
  if (v < 0) throw_input_error("GLB", what_, "negative index at element " + std::to_string(i));
  return static_cast<std::uint32_t>(v);
}

}  // namespace arg::io
