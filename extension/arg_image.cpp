// The image decoder is a separate library: OpenImageIO costs every backend ~0.2 s and threads.
#include "arg_image.hpp"

#include <dlfcn.h>

#include "common/signals_blocked.hpp"
#include "io/image_decoder.hpp"
#include "io/read_mesh.hpp"

#include "arg_bridge.hpp"

namespace argpg {

void prepare_image_decoder(std::string_view mesh, std::string_view texture) {
  if (arg::image_decoder() != nullptr) return;
  if (texture.empty() && arg::detect_mesh_format(mesh) != arg::MeshFormat::Glb) return;
  // Not load_external_function: arg_image.so is a plain C++ library, not a PostgreSQL module.
  char path[MAXPGPATH];
  snprintf(path, sizeof path, "%s/arg_image%s", pkglib_path, DLSUFFIX);
  void* library;
  {
    // Libraries under OpenImageIO start threads as they load (log4cplus, four): with every
    // signal blocked here, no such thread can take the backend's signals.
    const arg::SignalsBlocked while_loading;
    library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
  }
  if (library == nullptr)
    ereport(ERROR, (errcode(ERRCODE_UNDEFINED_FILE),
                    errmsg("cannot load the image decoder \"%s\": %s", path, dlerror())));
  using Lookup = void* (*)();
  auto lookup = reinterpret_cast<Lookup>(dlsym(library, "arg_oiio_image_decoder"));
  if (lookup == nullptr)
    ereport(ERROR, (errcode(ERRCODE_UNDEFINED_FUNCTION),
                    errmsg("image decoder \"%s\" has no arg_oiio_image_decoder", path)));
  arg::set_image_decoder(reinterpret_cast<arg::ImageDecoder>(lookup()));
}

}  // namespace argpg
