// A small strict CSV reader: quoted fields may span lines, as spreadsheets write them.
#include "eval/csv_records.hpp"

#include "common/errors.hpp"

namespace arg {

std::vector<CsvRecord> parse_csv_records(std::string_view text, std::string_view what) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::vector<CsvRecord> records;
  CsvRecord record;
  int line = 1;
  int quote_line = 0;       // the line an open quoted field started on; 0 outside quotes
  bool at_start = true;     // nothing of the current record read yet
  bool field_fresh = true;  // nothing of the current field read yet (a quote may open it)
  auto end_record = [&] {
    if (!at_start) records.push_back(std::move(record));
    record = CsvRecord();
    at_start = field_fresh = true;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (at_start) {
      if (c == '\n') {  // a blank line
        ++line;
        continue;
      }
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') continue;
      record.line = line;
      record.fields.emplace_back();
      at_start = false;
    }
    std::string& field = record.fields.back();
    if (quote_line) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quote_line = 0;
      } else {
        if (c == '\n') ++line;
        field += c;
      }
    } else if (c == '"' && field_fresh) {
      quote_line = line;
      field_fresh = false;
    } else if (c == ',') {
      record.fields.emplace_back();
      field_fresh = true;
    } else if (c == '\n' || (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n')) {
      if (c == '\r') ++i;
      ++line;
      end_record();
    } else {
      field += c;
      field_fresh = false;
    }
  }
  if (quote_line)
    throw InputError(std::string(what) + ": line " + std::to_string(quote_line) +
                     ": unterminated quote");
  end_record();
  return records;
}

}  // namespace arg
