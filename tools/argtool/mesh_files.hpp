// Which files are meshes argtool reads, by name, and the meshes of a folder.
#pragma once

#include <filesystem>
#include <vector>

namespace argtool {

// .off .obj .ply .stl .glb, in any case: the formats the builder reads.
bool is_mesh_file(const std::filesystem::path& path);

// Every mesh file under `dir` (its subfolders too, following no folder links), as paths
// relative to it, sorted part by part (a/b.off before a-c.off). Unreadable folders are passed
// over.
std::vector<std::filesystem::path> mesh_files_under(const std::filesystem::path& dir);

}  // namespace argtool
