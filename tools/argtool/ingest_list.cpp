// Matching a catalogue's rows to the mesh files of a folder, by path relative to the folder.
#include "ingest_list.hpp"

#include <cctype>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "command_registry.hpp"
#include "eval/csv_records.hpp"
#include "mesh_files.hpp"

namespace argtool {

namespace fs = std::filesystem;

namespace {

std::string trimmed(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t");
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(" \t") - begin + 1);
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The items' strings again, allocated one after another once every temporary of the listing is
// freed. Listed as they are, each item's strings sit between blocks the listing freed (paths,
// map nodes, catalogue records): a folder of 100,000 meshes left 100,000 free chunks, and glibc's
// mallinfo2, which the build's memory cap reads (core/common/heap_usage.cpp), walks every one
// of them: 3 ms a reading, a tenth of an ingest's time. Copied through one flat buffer, the
// freed blocks merge and the copies take consecutive memory.
IngestList repacked(IngestList list) {
  std::string chars;
  std::vector<std::size_t> ends;  // of each string in chars: file, path, then the fields
  const std::size_t fields = list.columns.size();
  for (const IngestItem& item : list.items) {
    chars += item.file;
    ends.push_back(chars.size());
    chars += item.path;
    ends.push_back(chars.size());
    for (const std::string& field : item.fields) {
      chars += field;
      ends.push_back(chars.size());
    }
  }
  const std::size_t n = list.items.size();
  std::vector<IngestItem>().swap(list.items);
  list.items.reserve(n);
  std::size_t at = 0, e = 0;
  const auto next = [&] {
    std::string s = chars.substr(at, ends[e] - at);
    at = ends[e++];
    return s;
  };
  for (std::size_t i = 0; i < n; ++i) {
    IngestItem item;
    item.file = next();
    item.path = next();
    item.fields.reserve(fields);
    for (std::size_t k = 0; k < fields; ++k) item.fields.push_back(next());
    list.items.push_back(std::move(item));
  }
  return list;
}

IngestList gather_items(const std::string& dir, const std::string& catalogue) {
  IngestList list;
  const fs::path base = fs::absolute(dir).lexically_normal();
  std::map<std::string, std::size_t> item_of;  // relative path -> index in items
  for (const fs::path& rel : mesh_files_under(base)) {
    item_of[rel.generic_string()] = list.items.size();
    list.items.push_back({rel.generic_string(), (base / rel).string(), {}});
  }
  std::size_t file_column = 0;
  if (catalogue.empty()) {
    list.columns = {"file"};
  } else {
    const std::vector<arg::CsvRecord> records =
        arg::parse_csv_records(read_file_bytes(catalogue), catalogue);
    if (records.empty()) throw std::runtime_error(catalogue + ": empty (expected a header)");
    for (const std::string& name : records[0].fields) list.columns.push_back(trimmed(name));
    file_column = list.columns.size();
    for (std::size_t c = 0; c < list.columns.size() && file_column == list.columns.size(); ++c)
      if (lower(list.columns[c]) == "file" || lower(list.columns[c]) == "path") file_column = c;
    if (file_column == list.columns.size())
      throw std::runtime_error(catalogue + ": no file or path column naming each row's mesh");
    std::map<std::size_t, int> line_of;  // item -> catalogue line that described it
    for (std::size_t r = 1; r < records.size(); ++r) {
      const arg::CsvRecord& record = records[r];
      const std::string where = catalogue + ": line " + std::to_string(record.line) + ": ";
      if (record.fields.size() != list.columns.size())
        throw std::runtime_error(where + std::to_string(record.fields.size()) +
                                 " fields where the header has " +
                                 std::to_string(list.columns.size()));
      const std::string named = trimmed(record.fields[file_column]);
      const fs::path rel = (base / named).lexically_normal().lexically_relative(base);
      const auto found = named.empty() ? item_of.end() : item_of.find(rel.generic_string());
      if (found == item_of.end()) {
        list.problems.push_back(where + "'" + named + "' is not a mesh file under " + dir);
        continue;
      }
      if (line_of.count(found->second)) {
        list.problems.push_back(where + "'" + named + "' was described on line " +
                                std::to_string(line_of[found->second]) + " already");
        continue;
      }
      line_of[found->second] = record.line;
      list.items[found->second].fields = record.fields;
    }
  }
  for (IngestItem& item : list.items) {
    item.fields.resize(list.columns.size());
    item.fields[file_column] = item.file;
  }
  return list;
}

}  // namespace

IngestList list_ingest(const std::string& dir, const std::string& catalogue) {
  return repacked(gather_items(dir, catalogue));
}

}  // namespace argtool
