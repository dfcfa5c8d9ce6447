// The BicycleParameters reader is strict (scenario/bicycle_parameters.h): a name given twice, a sigma
// that is not a finite decimal number, an unknown name, an empty repeat are errors at the file's line,
// where the last value used to win, `+/-abc` was dropped, `+/-0x10` read as 16 and `IBxY` ignored.
// The lines and names are drawn at random (seeded) from the measured benchmark files, so each run
// checks other lines than the ones a reader could special-case.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "tests/apps/cli_support.h"
#include "tests/support/catch_input_error.h"
#include "tests/support/temp_dir.h"
#include "io/input_error.h"
#include "scenario/bicycle_parameters.h"
#include "scenario/bicycle_parameters_uncertainty.h"
#include "scenario/scenario.h"

namespace motostab::scenario {
namespace {

namespace fs = std::filesystem;
using io::InputError;
using motostab::test::catchInputError;

const std::string kBicycles = std::string(MOTOSTAB_TEST_DATA_DIR) + "/measured-data/BicycleParameters/data/bicycles/";
const char* const kBikes[] = {"Benchmark", "Browser", "Silver", "Pista", "Crescendo", "Rigid"};

std::vector<std::string> readLines(const std::string& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

std::string writeLines(const fs::path& file, const std::vector<std::string>& lines) {
  std::ofstream out(file);
  for (const auto& l : lines) out << l << "\n";
  return file.string();
}

std::string nameOf(const std::string& line) {
  std::string n = line.substr(0, line.find('='));
  n.erase(n.find_last_not_of(" \t") + 1);
  return n;
}

struct Mutation {
  std::vector<std::string> lines;
  int line;          // 1-based line the error must name
  std::string name;  // parameter it must name
  std::string needle;
};

// One bad file from a measured one: a parameter repeated at the end, a sigma replaced by text, by a
// hexadecimal or negative number, a name with one letter's case flipped, or an empty repeat.
Mutation mutate(std::vector<std::string> lines, int kind, std::mt19937& rng) {
  const int i = std::uniform_int_distribution<int>(0, static_cast<int>(lines.size()) - 1)(rng);
  const std::string name = nameOf(lines[i]), value = lines[i].substr(lines[i].find('=') + 1);
  const std::string prefix = name + " = " + value.substr(0, value.find("+/-"));
  switch (kind) {
    case 0:
      lines.push_back(lines[i]);
      return {lines, static_cast<int>(lines.size()), name, "given twice (first on line " + std::to_string(i + 1) + ")"};
    case 1:
      lines[i] = prefix + "+/-abc";
      return {lines, i + 1, name, "'abc'"};
    case 2:
      lines[i] = prefix + "+/-0x10";
      return {lines, i + 1, name, "'0x10'"};
    case 3:
      lines[i] = prefix + "+/--0.01";
      return {lines, i + 1, name, "'-0.01'"};
    case 4: {
      std::string flipped = name;  // the last letter's case flipped, e.g. IBxy -> IBxY
      char& c = flipped.back();
      c = std::isupper(static_cast<unsigned char>(c)) ? static_cast<char>(std::tolower(c)) : static_cast<char>(std::toupper(c));
      lines[i] = flipped + " = " + value;
      return {lines, i + 1, flipped, "unknown parameter name"};
    }
    default:
      lines[i] = prefix + ",," + value;
      return {lines, i + 1, name, "not a finite number: ''"};
  }
}

TEST(BicycleParametersStrict, MalformedLinesAreErrorsAtTheirLine) {
  std::mt19937 rng(29);
  const fs::path dir = makeTempDir("bp_strict");
  int checked = 0;
  for (const char* bike : kBikes) {
    const auto lines = readLines(kBicycles + bike + "/Parameters/" + bike + "Benchmark.txt");
    ASSERT_GT(lines.size(), 20u) << bike;
    for (int kind = 0; kind < 6; ++kind)
      for (int trial = 0; trial < 3; ++trial) {
        const Mutation m = mutate(lines, kind, rng);
        const std::string file = writeLines(dir / (std::string(bike) + std::to_string(kind) + ".txt"), m.lines);
        const InputError e = catchInputError([&] { readBicycleParameterFile(file); });
        EXPECT_EQ(e.getLocation().file, file);
        EXPECT_EQ(e.getLocation().line, m.line) << e.what();
        EXPECT_EQ(e.getLocation().key, m.name) << e.what();
        EXPECT_NE(std::string(e.what()).find(m.needle), std::string::npos) << e.what() << "\n(expected " << m.needle << ")";
        EXPECT_THROW(readBicycleParameterSigmas(file), InputError);  // the sigmas, from the same reader
        ++checked;
      }
  }
  EXPECT_EQ(checked, 6 * 6 * 3);
}

// Every name in the measured files is known; values and sigmas are read as written (repeats averaged,
// their sigma sqrt(sum sigma^2) / n: an independent calculation here).
TEST(BicycleParametersStrict, MeasuredFilesReadAsWritten) {
  const fs::path dir = makeTempDir("bp_values");
  const std::string file = writeLines(dir / "r.txt", {"w = 1.02+/-0.01, 1.04+/-0.02", "c = 0.08", "lam = 0.314+/-0.0"});
  const auto p = readBicycleParameterFile(file);
  EXPECT_DOUBLE_EQ(p.at("w").value, 1.03);
  EXPECT_DOUBLE_EQ(p.at("w").sigma, std::sqrt(0.01 * 0.01 + 0.02 * 0.02) / 2);
  EXPECT_EQ(p.at("c").sigma, 0.0);
  EXPECT_EQ(p.at("lam").line, 3);
  for (const char* bike : kBikes)
    EXPECT_NO_THROW(readBicycleParameterFile(kBicycles + bike + "/Parameters/" + bike + "Benchmark.txt")) << bike;
}

// `import` validates before it writes: a failed import leaves the earlier output as it was and names
// the parameter file's line, not a line of the scenario it would have written; it replaces only a
// scenario it wrote itself, never one of its inputs.
TEST(BicycleParametersStrict, ImportValidatesBeforeWriting) {
  const fs::path dir = makeTempDir("bp_import");
  const std::string good = kBicycles + std::string("Benchmark/Parameters/BenchmarkBenchmark.txt");
  std::string output;
  const std::string out = (dir / "bike.yaml").string();
  ASSERT_EQ(test::runMotostab({"import", good, "--format", "bicycleparameters", "--out", out}, dir.string(), output), 0)
      << output;
  const std::string before = test::readLog(out);
  auto lines = readLines(good);
  int massLine = 0;
  for (size_t i = 0; i < lines.size(); ++i)
    if (nameOf(lines[i]) == "mH") lines[i] = "mH = -4+/-0.1", massLine = static_cast<int>(i + 1);
  ASSERT_GT(massLine, 0);
  const std::string bad = writeLines(dir / "bad.txt", lines);
  EXPECT_EQ(test::runMotostab({"import", bad, "--format", "bicycleparameters", "--out", out}, dir.string(), output), 2);
  EXPECT_NE(output.find("bad.txt:" + std::to_string(massLine) + ": mH: must be positive"), std::string::npos) << output;
  EXPECT_EQ(test::readLog(out), before);
  // A file the user wrote, and the parameter file itself, are never replaced.
  std::ofstream(dir / "mine.yaml") << "name: mine\n";
  EXPECT_EQ(test::runMotostab({"import", good, "--format", "bicycleparameters", "--out", (dir / "mine.yaml").string()},
                              dir.string(), output),
            2);
  EXPECT_NE(output.find("not written by motostab"), std::string::npos) << output;
  EXPECT_EQ(test::readLog((dir / "mine.yaml").string()), "name: mine\n");
  const std::string copy = writeLines(dir / "copy.txt", readLines(good));
  EXPECT_EQ(test::runMotostab({"import", copy, "--format", "bicycleparameters", "--out", copy}, dir.string(), output), 2);
  EXPECT_NE(output.find("an input of this run"), std::string::npos) << output;
  EXPECT_EQ(readLines(copy), readLines(good));
  for (const auto& e : fs::directory_iterator(dir))  // no temporary left
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

}  // namespace
}  // namespace motostab::scenario
