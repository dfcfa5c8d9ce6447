// The one strict YAML layer (io/yaml_map.h): duplicate keys, finite numbers, the relative-path
// rule, and errors located by file:line:column and key path.
#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"
#include "tests/support/catch_input_error.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "io/yaml_map.h"

namespace motostab::io {
namespace {
namespace fs = std::filesystem;

std::string writeYaml(const std::string& name, const std::string& text) {
  static const fs::path dir = makeTempDir("yaml_map");
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p.string();
}

using motostab::test::catchInputError;

TEST(YamlMap, DuplicateKeysAnywhereAreRejectedAtTheSecond) {
  struct Case {
    std::string text, key;
    int line, column, firstLine;
  };
  const std::vector<Case> cases{
      {"a: 1\nb: 2\na: 3\n", "a", 3, 1, 1},
      {"m:\n  x: 1\n  y: 2\n  x: 3\n", "m.x", 4, 3, 2},
      {"l:\n  - {p: 1, q: 2}\n  - {p: 1, p: 2}\n", "l[1].p", 3, 12, 3},
      {"m: {n: {k: 1, k: 1}}\n", "m.n.k", 1, 15, 1},
  };
  for (const auto& c : cases) {
    const std::string file = writeYaml("dup.yaml", c.text);
    const InputError e = catchInputError([&] { loadYamlFile(file); });
    EXPECT_EQ(e.getLocation().key, c.key) << c.text;
    EXPECT_EQ(e.getLocation().line, c.line) << c.text;
    EXPECT_EQ(e.getLocation().column, c.column) << c.text;
    EXPECT_NE(e.getReason().find("duplicate key (first given on line " + std::to_string(c.firstLine) + ")"),
              std::string::npos)
        << e.what();
  }
}

TEST(YamlMap, DuplicateKeysInNodesBuiltElsewhere) {
  // A map built outside loadYamlFile (an override value, a plugin section) is checked when opened.
  const YAML::Node n = YAML::Load("{a: 1, a: 2}");
  EXPECT_THROW(YamlMap(n, "x.yaml", "sec"), InputError);
}

TEST(YamlMap, NonScalarKeyIsAnError) {
  const std::string file = writeYaml("key.yaml", "[1, 2]: 3\n");
  const InputError e = catchInputError([&] { loadYamlFile(file); });
  EXPECT_EQ(e.getLocation().line, 1);
}

// An unread key is an UnknownKey problem at its own line, column and path; a bad value is not; words
// added to the reason (where the value came from) keep both.
TEST(YamlMap, UnknownKeysAreKnownAsSuch) {
  YamlMap values = loadYamlFile(writeYaml("value.yaml", "w: abc\n"));
  const InputError bad = catchInputError([&] { values.getDouble("w"); });
  const std::string file = writeYaml("unknown.yaml", "sec:\n  v: 2\n  w: 3\n  colour: red\n");
  YamlMap root = loadYamlFile(file);
  YamlMap sec = root.getMap("sec");
  sec.getDouble("v");
  sec.getDouble("w");
  EXPECT_EQ(bad.getProblem(), InputProblem::Value);
  const InputError unknown = catchInputError([&] { sec.finish(); });
  EXPECT_EQ(unknown.getProblem(), InputProblem::UnknownKey);
  EXPECT_EQ(unknown.getLocation().key, "sec.colour");
  EXPECT_EQ(unknown.getLocation().line, 4);
  const InputError more = unknown.withReasonAdded(" (value from --set sec.colour=red)");
  EXPECT_EQ(more.getProblem(), InputProblem::UnknownKey);
  EXPECT_EQ(more.getLocation().line, 4);
  EXPECT_EQ(more.getReason(), "unknown key (value from --set sec.colour=red)");
  EXPECT_EQ(bad.withReasonAdded("!").getProblem(), InputProblem::Value);
}

TEST(YamlMap, NumbersMustBeFinite) {
  for (const char* bad : {".nan", ".NaN", "nan", ".inf", "-.inf", "inf", "1e999", "0x10", "1_000", "'abc'", "[1]", "{a: 1}", "~"}) {
    const std::string file = writeYaml("num.yaml", std::string("sec:\n  v: ") + bad + "\n  l: [1, 2]\n");
    YamlMap root = loadYamlFile(file);
    YamlMap sec = root.getMap("sec");
    const InputError e = catchInputError([&] { sec.getDouble("v"); });
    EXPECT_EQ(e.getLocation().key, "sec.v") << bad;
    EXPECT_EQ(e.getLocation().line, 2) << bad;
    EXPECT_EQ(e.getLocation().column, 3) << bad;
  }
  const std::string file = writeYaml("list.yaml", "l: [1, 2, .nan]\n");
  YamlMap root = loadYamlFile(file);
  const InputError e = catchInputError([&] { root.getDoubleList("l"); });
  EXPECT_EQ(e.getLocation().key, "l[2]");
  EXPECT_EQ(e.getLocation().column, 11);
}

// A delay or relaxation length is 0 (off) or at least its physical floor: 1e-300 gave a root of -2e300
// (or non-finite ones). Values drawn (seeded) on a log scale below and above the floor.
TEST(YamlMap, ZeroOrAtLeastAFloor) {
  std::mt19937 rng(1029);
  std::uniform_real_distribution<double> below(-300, -0.01), above(0, 3);
  const double floor = 1e-4;
  for (int i = 0; i < 20; ++i) {
    const double tiny = floor * std::pow(10.0, below(rng)), fine = floor * std::pow(10.0, above(rng));
    std::ostringstream text;
    text.precision(17);
    text << "sec:\n  zero: 0\n  tiny: " << tiny << "\n  fine: " << fine << "\n";
    YamlMap root = loadYamlFile(writeYaml("floor.yaml", text.str()));
    YamlMap sec = root.getMap("sec");
    EXPECT_EQ(sec.getZeroOrAtLeast("zero", floor, "s"), 0);
    EXPECT_EQ(sec.getZeroOrAtLeast("fine", floor, "s"), fine);
    EXPECT_EQ(sec.getZeroOrAtLeast("absent", floor, "s", 0.5), 0.5);
    const InputError e = catchInputError([&] { sec.getZeroOrAtLeast("tiny", floor, "s", 0.5); });
    EXPECT_EQ(e.getLocation().key, "sec.tiny");
    EXPECT_EQ(e.getLocation().line, 3);
    EXPECT_NE(e.getReason().find("must be 0 (off) or at least 0.0001 s"), std::string::npos) << e.what();
  }
}

TEST(YamlMap, RelativePathsAreRelativeToTheNamingFile) {
  const std::string file = writeYaml("paths.yaml", "a: data/x.csv\nb: /abs/y.csv\nc: [../z.so, ./w.so]\n");
  YamlMap m = loadYamlFile(file);
  const fs::path dir = fs::path(file).parent_path();
  EXPECT_EQ(m.getFilePath("a"), (dir / "data" / "x.csv").string());
  EXPECT_EQ(m.getFilePath("b"), "/abs/y.csv");
  const auto list = m.getFilePathList("c");
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0], (dir.parent_path() / "z.so").string());
  EXPECT_EQ(list[1], (dir / "w.so").string());
  m.finish();
  // A naming file in the working folder: the result keeps a folder ("./"), never a bare name.
  EXPECT_EQ(resolveRelativeTo("p.yaml", "./w.so"), "./w.so");
  EXPECT_EQ(resolveRelativeTo("p.yaml", "w.so"), "./w.so");
  EXPECT_EQ(resolveRelativeTo("sub/p.yaml", "../w.so"), "./w.so");
  EXPECT_EQ(resolveRelativeTo("sub/p.yaml", "w.so"), "sub/w.so");
  EXPECT_EQ(resolveRelativeTo("p.yaml", "lib/w.so"), "lib/w.so");
}

TEST(YamlMap, MapListsAreStrictPerElement) {
  const std::string file = writeYaml("maps.yaml", "items:\n  - {name: a, v: 1}\n  - {name: b, w: 2}\n");
  YamlMap root = loadYamlFile(file);
  auto items = root.getMapList("items");
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[0].getDouble("v"), 1.0);
  items[0].getString("name");
  items[0].finish();
  items[1].getString("name");
  const InputError e = catchInputError([&] { items[1].finish(); });
  EXPECT_EQ(e.getLocation().key, "items[1].w");
  EXPECT_EQ(e.getLocation().line, 3);
}

TEST(YamlMap, OverrideValuesAreCheckedYaml) {
  YAML::Node root = YAML::Load("a: {b: 1}");
  EXPECT_THROW(applyOverride(root, "a.b=[1,"), InputError);
  EXPECT_THROW(applyOverride(root, "a={c: 1, c: 2}"), InputError);
  applyOverride(root, "a.b=2.5");
  EXPECT_EQ(root["a"]["b"].as<double>(), 2.5);
}

// "Billion laughs": levels of lists of aliases to the level below. Each alias may expand only a node
// without aliases, so a second level is refused at its first alias, whatever the widths (drawn at
// random, seeded); one level of aliases is read as the nodes it names.
std::string makeAliasLevels(int levels, int width) {
  std::string text = "a0: &a0 [x";
  for (int k = 1; k < width; ++k) text += ", x";
  text += "]\n";
  for (int l = 1; l <= levels; ++l) {
    text += "a" + std::to_string(l) + ": &a" + std::to_string(l) + " [*a" + std::to_string(l - 1);
    for (int k = 1; k < width; ++k) text += ", *a" + std::to_string(l - 1);
    text += "]\n";
  }
  return text;
}

TEST(YamlMap, AliasesExpandAtMostOnce) {
  std::mt19937 rng(29);
  for (int trial = 0; trial < 5; ++trial) {
    const int width = std::uniform_int_distribution<int>(2, 12)(rng);
    const int levels = std::uniform_int_distribution<int>(2, 9)(rng);
    const std::string file = writeYaml("bomb" + std::to_string(trial) + ".yaml", makeAliasLevels(levels, width));
    const InputError e = catchInputError([&] { loadYamlFile(file); });
    EXPECT_EQ(e.getLocation().line, 3) << e.what();  // the first alias of level 2
    EXPECT_NE(std::string(e.what()).find("expanded at most once"), std::string::npos) << e.what();
    // The same through --set (the value is YAML text too).
    YAML::Node root = YAML::Load("a: 1");
    std::string oneLine;
    for (char c : makeAliasLevels(levels, width)) oneLine += c == '\n' ? ',' : c;
    oneLine.pop_back();
    EXPECT_THROW(applyOverride(root, "a={" + oneLine + "}"), InputError) << oneLine;
  }
  YamlMap one = loadYamlFile(writeYaml("one.yaml", makeAliasLevels(1, 3)));
  EXPECT_EQ(one.getStringList("a0").size(), 3u);
  EXPECT_EQ(one.getNode()["a1"].size(), 3u);
  EXPECT_EQ(one.getNode()["a1"][2][1].as<std::string>(), "x");
}

// A node budget bounds what one level of aliases can expand to: kMaxYamlNodes counting each alias as
// the nodes it names.
TEST(YamlMap, ExpandedNodesAreBounded) {
  // Nodes: the root mapping, keys "base" and "copies", the base list and its `width` items, the copies
  // list, and `width + 1` per alias of the base list. The most copies within the budget, and one more.
  const long width = 1000, fixed = 1 + 2 + (width + 1) + 1;
  const long most = (kMaxYamlNodes - fixed) / (width + 1);
  auto makeText = [&](long copies) {
    std::string text = "base: &b [0";
    for (long k = 1; k < width; ++k) text += ", 0";
    text += "]\ncopies:\n";
    for (long c = 0; c < copies; ++c) text += "  - *b\n";
    return text;
  };
  EXPECT_NO_THROW(loadYamlFile(writeYaml("wide_ok.yaml", makeText(most))));
  const InputError e = catchInputError([&] { loadYamlFile(writeYaml("wide.yaml", makeText(most + 1))); });
  EXPECT_NE(std::string(e.what()).find("more than 100000 YAML nodes"), std::string::npos) << e.what();
  EXPECT_EQ(e.getLocation().line, 2 + most + 1);  // at the alias that exceeds it
}

TEST(YamlMap, OneDocumentPerFile) {
  const InputError e = catchInputError([&] { loadYamlFile(writeYaml("two.yaml", "a: 1\n---\nb: 2\n")); });
  EXPECT_EQ(e.getLocation().line, 2);
  EXPECT_NE(std::string(e.what()).find("second YAML document"), std::string::npos) << e.what();
  EXPECT_NO_THROW(loadYamlFile(writeYaml("explicit.yaml", "---\na: 1\n...\n")));
  YAML::Node root = YAML::Load("a: 1");
  EXPECT_THROW(applyOverride(root, "a=1\n---\n2"), InputError);
}

// YAML files are regular files of bounded size (io/input_file.h).
TEST(YamlMap, OnlyRegularFiles) {
  EXPECT_THROW(loadYamlFile("/dev/zero"), InputError);
  EXPECT_THROW(loadYamlFile(makeTempDir("yaml_folder").string()), InputError);
}

}  // namespace
}  // namespace motostab::io
