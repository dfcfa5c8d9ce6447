// Identification from CSV files: errors name the file, line and column (the written outputs:
// tests/output/response_output_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/temp_dir.h"
#include "io/input_error.h"
#include "response/response_csv.h"

using motostab::io::InputError;
using motostab::response::CsvIdentificationRequest;
using motostab::response::identifyModesFromCsv;


namespace {

namespace fs = std::filesystem;

// A record with comments, the time in the second column: y = 0.2 + 1.3 e^{-0.5 t} cos(4 t + 0.6), 0..6 s.
fs::path writeRecord(const fs::path& dir) {
  std::ostringstream text;
  text << "# synthetic record\nindex,time_s,roll_rate,other\n";
  for (int i = 0; i <= 600; ++i) {
    const double t = 0.01 * i;
    text.precision(17);
    text << i << "," << t << "," << 0.2 + 1.3 * std::exp(-0.5 * t) * std::cos(4 * t + 0.6) << ",1\n";
  }
  const fs::path p = dir / "record.csv";
  std::ofstream(p) << text.str();
  return p;
}

CsvIdentificationRequest makeRequest(const fs::path& csv) {
  CsvIdentificationRequest r;
  r.csv = csv;
  r.timeColumn = "time_s";
  r.signalColumns = {"roll_rate"};
  return r;
}

// Runs `f`, expecting an InputError whose message contains every string of `parts`.
template <class F>
void expectInputError(F f, const std::vector<std::string>& parts) {
  try {
    f();
    FAIL() << "no error";
  } catch (const InputError& e) {
    for (const auto& p : parts) EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
  }
}

TEST(ResponseCsv, MissingSignalColumnNamesFileAndColumn) {
  const auto csv = writeRecord(makeTempDir("missing_signal"));
  auto r = makeRequest(csv);
  r.signalColumns = {"lean_rate"};
  expectInputError([&] { identifyModesFromCsv(r); }, {csv.string(), "lean_rate", "no such column"});
}

TEST(ResponseCsv, MissingTimeColumnNamesFileAndColumn) {
  const auto csv = writeRecord(makeTempDir("missing_time"));
  auto r = makeRequest(csv);
  r.timeColumn = "t";
  expectInputError([&] { identifyModesFromCsv(r); }, {csv.string(), ": t:", "no such column"});
}

TEST(ResponseCsv, DefaultTimeColumnIsTheFirst) {
  const auto csv = writeRecord(makeTempDir("default_time"));
  auto r = makeRequest(csv);
  r.timeColumn.clear();  // "index" (0..600) becomes the time: the frequency scales by 1/0.01
  const auto result = identifyModesFromCsv(r);
  ASSERT_FALSE(result.modes.empty());
  EXPECT_NEAR(result.modes[0].imag, 4.0 * 0.01, 1e-9);
}

TEST(ResponseCsv, MalformedCsvNamesFileAndLine) {
  const auto dir = makeTempDir("malformed");
  std::ofstream(dir / "bad.csv") << "# c\nt,y\n0,1\n0.1,2\n0.2,x\n";
  std::ofstream(dir / "short.csv") << "t,y\n0,1\n0.1\n";
  auto r = makeRequest(dir / "bad.csv");
  r.timeColumn = "t";
  r.signalColumns = {"y"};
  expectInputError([&] { identifyModesFromCsv(r); }, {(dir / "bad.csv").string() + ":5:2", "not a finite number"});
  r.csv = dir / "short.csv";
  expectInputError([&] { identifyModesFromCsv(r); }, {(dir / "short.csv").string() + ":3", "expected 2 cells"});
  r.csv = dir / "absent.csv";
  expectInputError([&] { identifyModesFromCsv(r); }, {(dir / "absent.csv").string(), "cannot open"});
}

TEST(ResponseCsv, NonIncreasingTimeNamesLineAndColumn) {
  const auto dir = makeTempDir("time_order");
  std::ofstream(dir / "t.csv") << "t,y\n0,1\n0.1,2\n0.1,3\n";
  auto r = makeRequest(dir / "t.csv");
  r.timeColumn = "t";
  r.signalColumns = {"y"};
  expectInputError([&] { identifyModesFromCsv(r); }, {(dir / "t.csv").string() + ":4:1: t", "not strictly increasing"});
}

TEST(ResponseCsv, WindowOutsideDataNamesFileAndColumns) {
  const auto csv = writeRecord(makeTempDir("window"));
  auto r = makeRequest(csv);
  motostab::response::setWindowFromText("5:9", csv.string(), r.options);
  expectInputError([&] { identifyModesFromCsv(r); }, {csv.string(), "roll_rate", "time_s", "outside the data"});
  r.options = {};
  motostab::response::setWindowFromText("2.00:2.03", csv.string(), r.options);  // 4 samples
  expectInputError([&] { identifyModesFromCsv(r); }, {csv.string(), "roll_rate", "samples"});
}

TEST(ResponseCsv, MalformedWindowText) {
  motostab::response::IdentificationOptions o;
  for (const char* text : {"9.9-12.5", "a:1", "1:", "3:2"})
    expectInputError([&] { motostab::response::setWindowFromText(text, "f.csv", o); }, {"f.csv", "--window"});
  motostab::response::setWindowFromText("9.9:12.5", "f.csv", o);
  EXPECT_EQ(o.windowStart, 9.9);
  EXPECT_EQ(o.windowEnd, 12.5);
}

}  // namespace
