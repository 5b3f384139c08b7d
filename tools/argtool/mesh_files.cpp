// Mesh files by extension, the same list as the demo's catalogue and the Python client's loader.
#include "mesh_files.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace argtool {

namespace fs = std::filesystem;

bool is_mesh_file(const fs::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl" || ext == ".glb";
}

std::vector<fs::path> mesh_files_under(const fs::path& dir) {
  std::vector<fs::path> found;
  for (auto it =
           fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied);
       it != fs::recursive_directory_iterator(); ++it) {
    std::error_code ec;
    if (it->is_regular_file(ec) && is_mesh_file(it->path()))
      found.push_back(it->path().lexically_relative(dir));
  }
  std::sort(found.begin(), found.end());  // fs::path compares part by part
  return found;
}

}  // namespace argtool
