// What argtool ingest loads: the meshes of a folder, each with its catalogue row when it has one.
#pragma once

#include <string>
#include <vector>

namespace argtool {

struct IngestItem {
  std::string file;                 // relative to the folder, '/'-separated
  std::string path;                 // the file to read
  std::vector<std::string> fields;  // one per column; the file column holds `file`; "" is NULL
};

struct IngestList {
  std::vector<std::string> columns;   // the catalogue's header (trimmed), or just "file"
  std::vector<IngestItem> items;      // every mesh file under the folder, in path order
  std::vector<std::string> problems;  // catalogue rows that describe no mesh of the folder
};

// Every .off .obj .ply .stl .glb file under `dir` is an item. With a catalogue (CSV with a
// header; "" for none), the column named file or path (case ignored) names each row's mesh,
// relative to `dir` or absolute, and the row gives that mesh's fields; a mesh it does not list
// gets NULLs. A row naming no mesh under `dir`, or one named before, is a problem (the first
// row wins). Throws std::runtime_error for a catalogue that cannot be read, has no file or
// path column, or a row whose field count differs from the header's.
IngestList list_ingest(const std::string& dir, const std::string& catalogue);

}  // namespace argtool
