// CSV text to records of fields: the one reader of the project's CSV files (labels, catalogues).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace arg {

struct CsvRecord {
  int line = 0;  // 1-based line the record starts on
  std::vector<std::string> fields;
};

// Splits CSV text (RFC 4180) into records. A field may be double-quoted, and then holds commas,
// line breaks and quotes written twice; a quote inside an unquoted field is kept as it is.
// Records end at LF or CRLF; blank lines are skipped, and a UTF-8 byte order mark before the
// first record is dropped. Throws InputError "<what>: line N: unterminated quote" naming the
// line the quoted field starts on.
std::vector<CsvRecord> parse_csv_records(std::string_view text, std::string_view what);

}  // namespace arg
