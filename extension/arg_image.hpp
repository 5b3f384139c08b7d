// Loading the image decoder (arg_image.so, OpenImageIO) only when a build needs one.
#pragma once

#include <string_view>

namespace argpg {

// Before a build: when `texture` is not empty or the mesh is a GLB (embedded textures), loads
// $libdir/arg_image and registers its decoder with the core, once per backend. May ereport
// (library missing), so call it outside guarded().
void prepare_image_decoder(std::string_view mesh, std::string_view texture);

}  // namespace argpg
