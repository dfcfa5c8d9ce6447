#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <fstream>
#include <utility>
#include <vector>

#include "tests/support/temp_dir.h"
#include "io/csv.h"
#include "io/input_error.h"
#include "io/result_error.h"

namespace {

std::filesystem::path writeTemp(const std::string& name, const std::string& text) {
  auto p = makeTempDir("csv") / name;
  std::ofstream(p) << text;
  return p;
}

TEST(Csv, ReadsCommentsHeaderAndRows) {
  auto p = writeTemp("motostab_csv_ok.csv", "# comment\nt_s,y\n0,1.5\n\n0.1,-2e-3\n");
  auto t = motostab::io::readCsv(p);
  ASSERT_EQ(t.header.size(), 2u);
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_DOUBLE_EQ(t.getColumn("y")[1], -2e-3);
  EXPECT_EQ(t.lineNumbers[1], 5);
}

TEST(Csv, BadCellNamesFileLineAndColumn) {
  auto p = writeTemp("motostab_csv_bad.csv", "t_s,y\n0,1\n0.1,abc\n");
  try {
    motostab::io::readCsv(p);
    FAIL() << "no error";
  } catch (const motostab::io::InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("motostab_csv_bad.csv:3:2"), std::string::npos) << m;
    EXPECT_NE(m.find("y"), std::string::npos) << m;
  }
}

TEST(Csv, RaggedRowIsAnError) {
  auto p = writeTemp("motostab_csv_ragged.csv", "a,b\n1,2\n3\n");
  EXPECT_THROW(motostab::io::readCsv(p), motostab::io::InputError);
}

// A column given twice would let one silently shadow the other: an error at the header, naming both.
TEST(Csv, DuplicatedColumnIsAnError) {
  auto p = writeTemp("motostab_csv_dup.csv", "# c\ntime_s, roll_rate ,steer_rate,roll_rate\n0,1,2,3\n");
  try {
    motostab::io::readCsv(p);
    FAIL() << "no error";
  } catch (const motostab::io::InputError& e) {
    EXPECT_EQ(e.getLocation().line, 2);
    EXPECT_EQ(e.getLocation().column, 4);
    EXPECT_EQ(e.getLocation().key, "roll_rate");
    EXPECT_NE(std::string(e.what()).find("columns 2 and 4"), std::string::npos) << e.what();
  }
}

// Spreadsheet programs save UTF-8 with a byte order mark: it is not part of the first column's name.
TEST(Csv, ByteOrderMarkIsSkipped) {
  auto p = writeTemp("motostab_csv_bom.csv", "\xEF\xBB\xBFspeed_mps,real\n1,2\n");
  const auto t = motostab::io::readCsv(p);
  EXPECT_EQ(t.header.front(), "speed_mps");
  EXPECT_EQ(t.getColumn("speed_mps").front(), 1.0);
}

// Spreadsheets quote fields (RFC 4180): a quoted header ("mode" was read as the name '"mode"', and its
// cells as numbers) and quoted cells are read as their text; an unclosed quote is an error at its column.
TEST(Csv, QuotedFieldsAreRead) {
  auto p = writeTemp("motostab_csv_quoted.csv", "\"speed_mps\", \"mode\" ,\"re,al\"\n5,\"weave\",\"-0.5\"\n6, \"say \"\"hi\"\"\" ,1\n");
  const auto t = motostab::io::readCsv(p, {"mode"});
  ASSERT_EQ(t.header, (std::vector<std::string>{"speed_mps", "mode", "re,al"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.text[0][0], "weave");
  EXPECT_EQ(t.text[1][0], "say \"hi\"");
  EXPECT_EQ(t.getColumn("re,al")[0], -0.5);
  for (const auto& [text, column] : std::vector<std::pair<std::string, int>>{{"a,b\n1,\"2\n", 3}, {"a,b\n1,\"2\"x\n", 6}, {"a,b\n1,2\"\n", 3}}) {
    try {
      motostab::io::readCsv(writeTemp("motostab_csv_open.csv", text));
      ADD_FAILURE() << text;
    } catch (const motostab::io::InputError& e) {
      EXPECT_EQ(e.getLocation().line, 2) << e.what();
      EXPECT_EQ(e.getLocation().column, column) << e.what();
    }
  }
}

TEST(Csv, OnlyRegularFiles) { EXPECT_THROW(motostab::io::readCsv("/dev/zero"), motostab::io::InputError); }

TEST(Csv, WriterRoundTripsDoublesExactly) {
  motostab::io::CsvWriter w({"x"});
  const double v = 0.1 + 0.2;
  w.beginRow().add(v);
  auto p = writeTemp("motostab_csv_rt.csv", w.getText());
  EXPECT_EQ(motostab::io::readCsv(p).rows[0][0], v);
}

// No "nan" or "inf" cell: a non-finite number is a ResultError naming its column and row (drawn at
// random among finite neighbours); addOrEmpty leaves the cell empty instead.
TEST(Csv, WriterRefusesNonFiniteNumbersNamingTheCell) {
  std::mt19937 rng(20261128);
  std::uniform_real_distribution<double> value(-1e6, 1e6);
  std::uniform_int_distribution<int> pick(0, 2);
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()};
  for (int trial = 0; trial < 20; ++trial) {
    const int rows = 1 + trial % 5, badRow = 1 + static_cast<int>(rng() % rows), badColumn = pick(rng);
    const std::vector<std::string> header{"speed_mps", "real", "imag"};
    std::vector<std::vector<double>> table(rows, std::vector<double>(3));
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < 3; ++c) table[r][c] = (r + 1 == badRow && c == badColumn) ? bad[trial % 3] : value(rng);
    motostab::io::CsvWriter w(header), lenient(header);
    for (const auto& row : table) {
      lenient.beginRow();
      for (double x : row) lenient.addOrEmpty(x);
    }
    std::string message;
    try {
      for (const auto& row : table) {
        w.beginRow();
        for (double x : row) w.add(x);
      }
    } catch (const motostab::io::ResultError& e) {
      message = e.what();
    }
    EXPECT_NE(message.find("column '" + header[badColumn] + "' of row " + std::to_string(badRow)), std::string::npos) << message;
    const std::string text = lenient.getText();
    EXPECT_EQ(text.find("nan"), std::string::npos);
    EXPECT_EQ(text.find("inf"), std::string::npos);
    std::vector<std::string> lines;
    for (size_t at = 0, next; at < text.size(); at = next + 1) lines.push_back(text.substr(at, (next = text.find('\n', at)) - at));
    ASSERT_EQ(lines.size(), static_cast<size_t>(rows + 1));
    EXPECT_EQ(motostab::io::splitFields(lines[badRow], ',').at(badColumn), "") << lines[badRow];
  }
}

}  // namespace
