// Loading the plug-in libraries on demand: linked, OpenImageIO and OpenVDB bring about 280
// shared libraries, 65,000 relocations and four logging threads into every run, about 0.1 s
// that `argtool --help`, `info` or `sim` have no use for.
#include "plugin_libraries.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/image_decoder.hpp"
#include "mesh/distance_field.hpp"

namespace argtool {

namespace {

// One plug-in: its file, the environment variable that overrides where it is, and the
// addresses its exported functions return, filled in once by the first caller.
struct Plugin {
  const char* file;
  const char* variable;
  std::vector<const char*> symbols;
  std::vector<void*> addresses;
  std::string error;  // why it could not be loaded
  std::once_flag loaded;
};

Plugin image_plugin{"arg_image.so",
                    "ARG_IMAGE_LIBRARY",
                    {"arg_oiio_image_decoder", "arg_oiio_png_writer"},
                    {},
                    {},
                    {}};
Plugin vdb_plugin{"arg_vdb.so", "ARG_VDB_LIBRARY", {"arg_vdb_distance_field"}, {}, {}, {}};

// The variable's path; else the file beside the program (a build tree); else in lib/argtool
// beside the program's bin (an installed argtool: /usr/bin and /usr/lib/argtool).
std::string plugin_path(const Plugin& plugin) {
  if (const char* path = std::getenv(plugin.variable); path != nullptr && *path != '\0')
    return path;
  std::error_code failed;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", failed);
  const std::filesystem::path dir = failed ? std::filesystem::path(".") : self.parent_path();
  const std::filesystem::path beside = dir / plugin.file;
  const std::filesystem::path installed = dir.parent_path() / "lib" / "argtool" / plugin.file;
  return (std::filesystem::exists(beside, failed) || !std::filesystem::exists(installed, failed)
              ? beside
              : installed)
      .string();
}

// The address of the plug-in's `index`-th function; throws, naming the file, if it cannot be
// loaded (every later call throws the same).
void* plugin_function(Plugin& plugin, std::size_t index) {
  std::call_once(plugin.loaded, [&plugin] {
    const std::string path = plugin_path(plugin);
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      plugin.error = "cannot load " + path + ": " + dlerror();
      return;
    }
    using Lookup = void* (*)();
    for (const char* symbol : plugin.symbols) {
      auto lookup = reinterpret_cast<Lookup>(dlsym(handle, symbol));
      if (lookup == nullptr) {
        plugin.error = path + " has no " + symbol + " (a build of another version?)";
        return;
      }
      plugin.addresses.push_back(lookup());
    }
  });
  if (!plugin.error.empty()) throw std::runtime_error(plugin.error);
  return plugin.addresses.at(index);
}

arg::Image decode_lazily(std::string_view bytes, const char* format, const arg::Limits& limits) {
  return reinterpret_cast<arg::ImageDecoder>(plugin_function(image_plugin, 0))(bytes, format,
                                                                               limits);
}

arg::DistanceField distance_field_lazily(const arg::Mesh& mesh, const arg::SampleGrid& grid,
                                         double band, const arg::StopRequested& stop) {
  return reinterpret_cast<arg::DistanceFieldFunction>(plugin_function(vdb_plugin, 0))(mesh, grid,
                                                                                      band, stop);
}

}  // namespace

void register_lazy_plugins() {
  arg::set_image_decoder(&decode_lazily);
  arg::set_distance_field(&distance_field_lazily);
}

void write_png(const arg::Image& image, const std::string& path) {
  using WritePng = void (*)(const arg::Image&, const std::string&);
  reinterpret_cast<WritePng>(plugin_function(image_plugin, 1))(image, path);
}

}  // namespace argtool
