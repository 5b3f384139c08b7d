// The distance field library (arg_vdb.so, OpenVDB) is loaded on the first build that needs a
// watertight proxy: it is 56 MB of code with its own thread pools, which a backend that only
// compares ARGs, or builds closed meshes, should not pay for.
#include "arg_vdb.hpp"

#include <dlfcn.h>

#include <cstring>
#include <new>
#include <stdexcept>
#include <string>

#include "common/signals_blocked.hpp"
#include "mesh/distance_field.hpp"

#include "arg_bridge.hpp"

namespace argpg {

namespace {

arg::DistanceFieldFunction loaded = nullptr;

// Runs inside guarded() (the core calls it mid-build): it reports failure by throwing, never
// by ereport.
arg::DistanceField load_then_compute(const arg::Mesh& mesh, const arg::SampleGrid& grid,
                                     double band, const arg::StopRequested& stop) {
  if (loaded == nullptr) {
    char path[MAXPGPATH];
    snprintf(path, sizeof path, "%s/arg_vdb%s", pkglib_path, DLSUFFIX);
    void* library;
    {
      // Threads a library starts as it loads must not take the backend's signals.
      const arg::SignalsBlocked while_loading;
      library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    }
    if (library == nullptr) {
      const char* why = dlerror();
      if (why != nullptr && std::strstr(why, "annot allocate memory") != nullptr)
        throw std::bad_alloc();
      throw std::runtime_error(std::string("cannot load the distance field library \"") + path +
                               "\": " + (why ? why : "unknown error"));
    }
    using Lookup = void* (*)();
    auto lookup = reinterpret_cast<Lookup>(dlsym(library, "arg_vdb_distance_field"));
    if (lookup == nullptr)
      throw std::runtime_error(std::string("\"") + path + "\" has no arg_vdb_distance_field");
    loaded = reinterpret_cast<arg::DistanceFieldFunction>(lookup());
  }
  return loaded(mesh, grid, band, stop);
}

}  // namespace

void register_distance_field() {
  arg::set_distance_field(&load_then_compute);
}

}  // namespace argpg
