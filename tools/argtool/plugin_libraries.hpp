// arg_image.so (OpenImageIO) and arg_vdb.so (OpenVDB) loaded on first use, so that commands
// that need neither start fast.
#pragma once

#include <string>

#include "io/image.hpp"

namespace argtool {

// Makes the core's image decoder and distance field stand-ins that load their library (beside
// the argtool executable, or at $ARG_IMAGE_LIBRARY / $ARG_VDB_LIBRARY) the first time a
// texture is decoded or a watertight proxy is made.
void register_lazy_plugins();

// arg::write_png from arg_image.so, loaded the same way.
void write_png(const arg::Image& image, const std::string& path);

}  // namespace argtool
