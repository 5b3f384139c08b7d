// The CSV reader: quoted fields across lines, CRLF, blank lines, the byte order mark, errors.
#include <gtest/gtest.h>

#include "eval/csv_records.hpp"
#include "input_error.hpp"

namespace arg {

using Fields = std::vector<std::string>;

TEST(CsvRecords, SplitsFieldsAndKeepsQuotedCommasQuotesAndLineBreaks) {
  const auto r = parse_csv_records(
      "\xEF\xBB\xBF"
      "file,title\r\na.off,\"Jug, \"\"blue\"\"\"\r\n\r\n\"b c.ply\",\"two\nlines\"\nx\"y,\n",
      "cat");
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0].fields, (Fields{"file", "title"}));
  EXPECT_EQ(r[1].fields, (Fields{"a.off", "Jug, \"blue\""}));
  EXPECT_EQ(r[2].fields, (Fields{"b c.ply", "two\nlines"}));
  EXPECT_EQ(r[3].fields, (Fields{"x\"y", ""}));
  // Each record knows the line it starts on, past blank lines and line breaks in quotes.
  EXPECT_EQ(r[0].line, 1);
  EXPECT_EQ(r[1].line, 2);
  EXPECT_EQ(r[2].line, 4);
  EXPECT_EQ(r[3].line, 6);
}

TEST(CsvRecords, ALastRecordWithoutLineBreakAndAnEmptyText) {
  const auto r = parse_csv_records("a,b\n1,2", "cat");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[1].fields, (Fields{"1", "2"}));
  EXPECT_TRUE(parse_csv_records("", "cat").empty());
  EXPECT_TRUE(parse_csv_records("\n\r\n", "cat").empty());
}

TEST(CsvRecords, AnUnterminatedQuoteNamesTheLineItOpensOn) {
  EXPECT_EQ(input_error_of([] { parse_csv_records("a,b\n1,\"open\n\n", "cat.csv"); }),
            "cat.csv: line 2: unterminated quote");
}

}  // namespace arg
