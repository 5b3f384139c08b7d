// The tinygltf implementation, compiled without stb_image and without file system access.

// Compiled here rather than linked from Debian's libtinygltf.so, whose default callbacks decode
// images with stb_image and read external files: images are decoded by OpenImageIO instead, and
// a mesh from the database never names a file.
// tinygltf 2.7's writer functions use std::ofstream even with TINYGLTF_NO_FS; they are never
// called, but they must compile.
#include <fstream>

#define TINYGLTF_IMPLEMENTATION
#include "io/gltf.hpp"
