// The strict .tir reader: the MF 6.1 sample file of the ExternData library (tests/data/reference/
// MF61-sample-tir) and files broken on purpose, each an InputError naming file:line and the key.
#include <gtest/gtest.h>

#include "tests/support/text_file.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>

#include "../support/catch_input_error.h"
#include "../support/temp_dir.h"
#include "tyres/magic_formula.h"
#include "tyres/tir_file.h"

namespace motostab::tyres {

using io::InputError;

namespace {

const std::string kSample = std::string(MOTOSTAB_TEST_DATA_DIR) + "/reference/MF61-sample-tir/sample_MF61_ExternData.tir";

// The sample with the first line matching `pattern` replaced by `replacement` (the whole line).
std::string editLine(const std::string& pattern, const std::string& replacement) {
  std::string text = readText(kSample);
  std::smatch m;
  const std::regex re("(^|\n)(" + pattern + "[^\n]*)");
  EXPECT_TRUE(std::regex_search(text, m, re)) << pattern;
  return text.replace(m.position(2), m.length(2), replacement);
}

// The 1-based line of the first line starting with `prefix` in the sample.
int lineOf(const std::string& prefix) {
  std::istringstream in(readText(kSample));
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.rfind(prefix, 0) == 0) return n;
  return -1;
}

TEST(TirFile, ReadsTheSampleFile) {
  const TirFile f = TirFile::load(kSample);
  EXPECT_EQ(f.getFitType(), 61);
  // Values as printed in the file.
  EXPECT_EQ(f.getNumber("FNOMIN"), 4000);
  EXPECT_EQ(f.getNumber("UNLOADED_RADIUS"), 0.3135);
  EXPECT_EQ(f.getNumber("PKY1"), -15.324);
  EXPECT_EQ(f.getNumber("PHX1"), 2.1615e-04);
  EXPECT_EQ(f.getNumber("pky1"), -15.324) << "keys are case-insensitive";
  EXPECT_EQ(f.find("TYRESIDE")->text, "Left");
  EXPECT_FALSE(f.find("TYRESIDE")->isNumber);
  EXPECT_EQ(f.find("PKY1")->line, lineOf("PKY1"));
  EXPECT_EQ(f.find("PKY1")->section, "LATERAL_COEFFICIENTS");
  // [INERTIA] MASS is a number; [UNITS] MASS = 'kg' is kept apart.
  EXPECT_EQ(f.getNumber("MASS"), 9.3);
  // Every coefficient of MF 6.1 is there: the law builds.
  const auto law = makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(f, nullptr));
  EXPECT_EQ(law->getNominalLoad(), 4000);
}

TirFile parseBroken(const std::string& text) { return TirFile::parse(text, "broken.tir"); }

TEST(TirFile, BrokenFilesNameTheLineAndKey) {
  struct Case {
    std::string pattern, replacement, key, reason;
    int line;
  };
  const std::vector<Case> cases = {
      {"FITTYP", "FITTYP = 52", "FITTYP", "unsupported FITTYP 52", lineOf("FITTYP")},
      {"FITTYP", "FITTYP = 'MF61'", "FITTYP", "unsupported FITTYP", lineOf("FITTYP")},
      {"PKY4", "PKY4  2.0005", "", "malformed line", lineOf("PKY4")},
      {"PKY4", "PKY4 = nan", "PKY4", "malformed value 'nan'", lineOf("PKY4")},
      {"PKY4", "PKY4 = 2.0005 2", "PKY4", "malformed value", lineOf("PKY4")},
      {"PKY4", "PKY4 = 'two", "PKY4", "malformed value", lineOf("PKY4")},
      {"PKY4", "PKY4 = 2\nPKY4 = 3", "PKY4", "given twice", lineOf("PKY4") + 1},
      {"PKY4", "PKY4 = 2\n[VERTICAL]\nPKY4 = 3", "PKY4", "also given in [LATERAL_COEFFICIENTS]", lineOf("PKY4") + 2},
      {"\\[LATERAL_COEFFICIENTS\\]", "[LATERAL_COEFFICIENTS", "", "malformed section header", lineOf("[LATERAL_COEFFICIENTS]")},
      {" LENGTH", " LENGTH = 'mm'", "LENGTH", "unit 'mm' is not supported", lineOf(" LENGTH")},
  };
  for (const auto& c : cases) {
    const InputError e = test::catchInputError([&] { parseBroken(editLine(c.pattern, c.replacement)); });
    EXPECT_EQ(e.getLocation().file, "broken.tir") << c.replacement;
    EXPECT_EQ(e.getLocation().line, c.line) << c.replacement;
    EXPECT_EQ(e.getLocation().key, c.key) << c.replacement;
    EXPECT_NE(e.getReason().find(c.reason), std::string::npos) << e.what();
  }
  // The column is the value's: "PKY4 = nan" has its value in column 8.
  EXPECT_EQ(test::catchInputError([&] { parseBroken(editLine("PKY4", "PKY4 = nan")); }).getLocation().column, 8);
  EXPECT_EQ(TirFile::load(kSample).find("PKY1")->column, 28);
  const InputError none = test::catchInputError([&] { parseBroken(editLine("FITTYP", "$ no FITTYP")); });
  EXPECT_NE(none.getReason().find("missing [MODEL] FITTYP"), std::string::npos) << none.what();
}

// Every number of a .tir file is at most 1e12 in magnitude, as in YAML and --set (QDZ1 = 1e200 gave an
// aligning moment of 1e201 N m with exit 0; LFZO = 1e30 a failed trim). Coefficients and magnitudes
// drawn (seeded); 1e12 itself is read.
TEST(TirFile, MagnitudesAbove1e12AreRefusedAtTheirLine) {
  const std::vector<std::string> keys{"QDZ1", "LFZO", "PKY1", "FNOMIN", "PCY1", "QSY1", "VERTICAL_STIFFNESS"};
  std::mt19937 rng(1200);
  for (int i = 0; i < 8; ++i) {
    const std::string key = keys[std::uniform_int_distribution<size_t>(0, keys.size() - 1)(rng)];
    std::ostringstream value;
    value << (i % 2 ? "-" : "") << std::pow(10.0, std::uniform_real_distribution<double>(12.01, 300)(rng));
    const InputError e = test::catchInputError([&] { parseBroken(editLine(key + " ", key + " = " + value.str())); });
    EXPECT_EQ(e.getLocation().line, lineOf(key + " ")) << value.str();
    EXPECT_EQ(e.getLocation().key, key) << value.str();
    EXPECT_EQ(e.getLocation().column, static_cast<int>(key.size()) + 4) << value.str();
    EXPECT_NE(e.getReason().find("a magnitude above 1e12"), std::string::npos) << e.what();
  }
  EXPECT_EQ(parseBroken(editLine("QDZ1 ", "QDZ1 = -1e12")).find("QDZ1")->number, -1e12);
}

TEST(TirFile, MissingOrUnsupportedCoefficientsAreErrorsOfTheFile) {
  const auto dir = makeTempDir("TirFile_Missing");
  // A coefficient the equations need, missing: named, at the file.
  for (const std::string key : {"PKY4", "QSY8", "RVY6", "FNOMIN"}) {
    const TirFile f = parseBroken(editLine(key + " ", "$ removed"));
    const InputError e = test::catchInputError([&] { makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(f, nullptr)); });
    EXPECT_EQ(e.getLocation().key, key);
    EXPECT_EQ(e.getLocation().file, "broken.tir");
    EXPECT_NE(e.getReason().find("missing coefficient"), std::string::npos) << e.what();
  }
  // A scaling factor may be missing (1); so may QSX12-14 (0, files converted from MF 5.2), which are
  // read when given: a nonzero QSX13 is not reported unused.
  EXPECT_NO_THROW(makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(parseBroken(editLine("LKY ", "$ removed")), nullptr)));
  EXPECT_NO_THROW(makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(parseBroken(editLine("QSX13", "$ removed")), nullptr)));
  const TirFile f = parseBroken(editLine("QSX13", "QSX13 = 0.5"));
  const auto source = makeTirSource(f, nullptr);
  makeTyreForceLaw(MagicFormulaVariant::MF61, *source);
  for (const auto& u : source->listUnused()) EXPECT_EQ(u.find("QSX13"), std::string::npos) << u;
  // The units must be stated; a pressure unit other than pascal is refused.
  const InputError noUnit = test::catchInputError([&] { parseBroken(editLine(" LENGTH", "$ removed")); });
  EXPECT_EQ(noUnit.getLocation().key, "LENGTH");
  const InputError bar = test::catchInputError([&] { parseBroken(editLine(" TIME", " TIME = 'second'\n PRESSURE = 'bar'")); });
  EXPECT_EQ(bar.getLocation().key, "PRESSURE");
  // A file that does not exist.
  const InputError absent = test::catchInputError([&] { TirFile::load((dir / "none.tir").string()); });
  EXPECT_NE(absent.getReason().find("cannot open"), std::string::npos);
}

// Only a regular file of at most TirFile::kMaxBytes is read: a device (tyre /dev/zero ran out of memory
// with std::bad_alloc), a folder or a huge file is an InputError at the path.
TEST(TirFile, OnlyRegularFilesOfBoundedSizeAreRead) {
  const auto dir = makeTempDir("TirFile_Regular");
  std::vector<std::string> refused = {dir.string()};
  if (std::filesystem::exists("/dev/zero")) refused.push_back("/dev/zero");
  const auto big = dir / "big.tir";
  {
    std::ofstream out(big);
    out << readText(kSample);
    out << std::string(TirFile::kMaxBytes, '$');
  }
  refused.push_back(big.string());
  for (const auto& path : refused) {
    const InputError e = test::catchInputError([&] { TirFile::load(path); });
    EXPECT_EQ(e.getLocation().file, path) << e.what();
  }
}

TEST(TirFile, TablesAndCommentsAreNotKeys) {
  const std::string text = readText(kSample) +
                           "$ a table section as MF-Tyre files have\n[SHAPE]\n{radial width}\n 1.0 0.0\n 1.0 0.4 $ row\n"
                           "! header comment\n";
  const TirFile f = parseBroken(text);
  EXPECT_EQ(f.getFitType(), 61);
  EXPECT_EQ(f.find("RADIAL"), nullptr);
  // A non-numeric row after a table header is malformed.
  const InputError e = test::catchInputError([&] { parseBroken(text + "[SHAPE2]\n{radial width}\n 1.0 zero\n"); });
  EXPECT_NE(e.getReason().find("malformed line"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace motostab::tyres
