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

}  // namespace

IngestList list_ingest(const std::string& dir, const std::string& catalogue) {
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

}  // namespace argtool
