// The eigenvalues-against-speed plot of `motostab sweep` (real_part_vs_speed.gp/.png/.svg): the
// figure of Meijaard, Papadopoulos, Ruina, Schwab (2007), "Linearized dynamics equations for the
// balance and steer of a bicycle: a benchmark and review", Proc. R. Soc. A 463, Fig. 3, with the
// critical speeds of their Table 2 (weave 4.29238253634111 m/s, capsize 6.02426201538837 m/s) marked
// and the range between them shaded. The script is parsed back; the images are rendered by gnuplot.
#include <gtest/gtest.h>

#include "tests/support/text_file.h"

#include <algorithm>
#include <complex>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <map>
#include <set>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/portable_random.h"
#include "nlohmann/json.hpp"
#include "output/sweep_output.h"
#include "scenario/scenario.h"
#include "tests/support/temp_dir.h"
#include "tests/support/text_csv.h"

namespace motostab::output {

using analysis::ModeBranch;
using analysis::SweepOptions;
using analysis::SweepResult;
using analysis::runSweep;
using core::PortableRandom;
using scenario::loadScenario;
using vehicle::VehicleModel;
namespace {

using cd = std::complex<double>;

constexpr double kWeaveSpeed = 4.29238253634111;    // Meijaard et al. (2007), Table 2
constexpr double kCapsizeSpeed = 6.02426201538837;  // Meijaard et al. (2007), Table 2

struct Marks {
  std::vector<std::pair<std::string, double>> lines;  // label text, speed of each vertical line
  std::vector<std::pair<double, double>> shaded;      // shaded speed ranges
  std::vector<std::string> labels;                    // every label's text
};

// The vertical lines (set arrow), their labels and the shaded rectangles (set object rect) of a script.
Marks parseMarks(const std::string& script) {
  Marks m;
  const std::regex arrow(R"(set arrow (\d+) from ([^,]+), graph 0 to ([^,]+), graph 1)");
  const std::regex label(R"(set label (\d+) '([^']*)' at ([^,]+),)");
  const std::regex rect(R"(set object (\d+) rect from ([^,]+), graph 0 to ([^,]+), graph 1)");
  std::map<int, double> arrowAt;
  std::map<int, std::string> labelText;
  for (std::sregex_iterator it(script.begin(), script.end(), arrow), end; it != end; ++it) {
    EXPECT_EQ((*it)[2], (*it)[3]) << "a vertical line";
    arrowAt[std::stoi((*it)[1])] = std::stod((*it)[2]);
  }
  for (std::sregex_iterator it(script.begin(), script.end(), label), end; it != end; ++it) {
    if (!labelText.count(std::stoi((*it)[1]))) m.labels.push_back((*it)[2]);
    labelText[std::stoi((*it)[1])] = (*it)[2];
  }
  for (const auto& [tag, v] : arrowAt) m.lines.push_back({labelText[tag], v});
  std::set<std::string> seen;  // the body runs once per image format: count each object once
  for (std::sregex_iterator it(script.begin(), script.end(), rect), end; it != end; ++it)
    if (seen.insert((*it)[1]).second) m.shaded.push_back({std::stod((*it)[2]), std::stod((*it)[3])});
  return m;
}

bool hasGnuplot() { return std::system("gnuplot --version >/dev/null 2>&1") == 0; }

// A complete PNG: the signature first and the IEND chunk (with its CRC) last; a complete SVG ends its root.
void expectCompleteImages(const std::filesystem::path& dir, const std::string& stem) {
  const std::string png = readText(dir / (stem + ".png"));
  ASSERT_GT(png.size(), 20000u) << "a 1000 x 700 figure";
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png.substr(png.size() - 12), std::string("\0\0\0\0IEND\xae\x42\x60\x82", 12));
  const std::string svg = readText(dir / (stem + ".svg"));
  EXPECT_NE(svg.find("</svg>", svg.size() - 16), std::string::npos);
}

TEST(SweepPlot, WhippleBenchmarkMarksWeaveAndCapsizeAndShadesTheStableRange) {
  if (!hasGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml"));
  SweepOptions opt;
  opt.start = 0, opt.stop = 10, opt.step = 0.25;
  const SweepResult sweep = runSweep(model, opt);
  const auto dir = makeTempDir("sweep_plot_whipple");
  writeSweepOutputs(dir, "whipple-benchmark", sweep);
  const std::string script = readText(dir / "real_part_vs_speed.gp");
  const Marks marks = parseMarks(script);

  // One labelled line per critical speed of the analysis, at its speed to the last digit.
  ASSERT_EQ(sweep.criticalSpeeds.size(), 2u);
  ASSERT_EQ(marks.lines.size(), sweep.criticalSpeeds.size()) << script;
  std::map<std::string, double> lineAt;  // label text -> speed
  for (const auto& [text, v] : marks.lines) lineAt[text] = v;
  for (const auto& c : sweep.criticalSpeeds) {
    std::ostringstream text;
    text << toString(c.mode) << " " << std::fixed << std::setprecision(3) << c.speed << " m/s";
    ASSERT_TRUE(lineAt.count(text.str())) << text.str() << "\n" << script;
    EXPECT_EQ(lineAt[text.str()], c.speed);
  }
  ASSERT_TRUE(lineAt.count("weave 4.292 m/s") && lineAt.count("capsize 6.024 m/s")) << script;
  EXPECT_NEAR(lineAt["weave 4.292 m/s"], kWeaveSpeed, 1e-3);
  EXPECT_NEAR(lineAt["capsize 6.024 m/s"], kCapsizeSpeed, 1e-3);

  // The shaded range runs from the weave to the capsize speed.
  ASSERT_EQ(marks.shaded.size(), 1u) << script;
  EXPECT_EQ(marks.shaded[0].first, lineAt["weave 4.292 m/s"]);
  EXPECT_EQ(marks.shaded[0].second, lineAt["capsize 6.024 m/s"]);
  EXPECT_NE(std::find(marks.labels.begin(), marks.labels.end(), "stable 4.292 - 6.024 m/s"), marks.labels.end());
  std::ifstream summaryFile(dir / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summaryFile);
  ASSERT_EQ(summary.at("stable_speed_ranges_mps").size(), 1u);
  EXPECT_NEAR(summary["stable_speed_ranges_mps"][0][0].get<double>(), kWeaveSpeed, 1e-3);
  EXPECT_NEAR(summary["stable_speed_ranges_mps"][0][1].get<double>(), kCapsizeSpeed, 1e-3);

  // Axis labels with units.
  EXPECT_NE(script.find("set xlabel 'forward speed v (m/s)'"), std::string::npos);
  EXPECT_NE(script.find("set ylabel 'eigenvalue: real part (1/s, solid), imaginary part (rad/s, dashed)'"),
            std::string::npos);

  // Each plotted line takes one branch's rows of eigenvalues.csv (every N::B): the rows it picks carry
  // the mode named in its title, in speed order. The weave's imaginary part is at Table 2's 4.46486771378823
  // rad/s at 5 m/s (grid index 20).
  const TextCsv csv = readTextCsv(dir / "eigenvalues.csv");
  ASSERT_EQ(csv.find("mode"), 1);
  const std::regex series(R"('eigenvalues.csv' every (\d+)::(\d+) using 1:(.+?) with lines .*? title '(\w+), (real|imaginary) part')");
  std::set<std::string> drawn;
  for (std::sregex_iterator it(script.begin(), script.end(), series), end; it != end; ++it) {
    const size_t n = std::stoul((*it)[1]), b = std::stoul((*it)[2]);
    ASSERT_EQ(n, sweep.branches.size());
    for (size_t k = 0; k < sweep.speeds.size(); ++k) {
      const auto& row = csv.rows[k * n + b];
      ASSERT_EQ(row[1], (*it)[4].str());
      ASSERT_EQ(parseCell(row[0]), sweep.speeds[k]);
    }
    drawn.insert((*it)[4].str() + " " + (*it)[5].str());
    EXPECT_EQ((*it)[3].str(), (*it)[5] == "real" ? "3" : "(abs($4) > 1e-9 ? abs($4) : NaN)");  // real, |imag| columns
    if ((*it)[4] == "weave" && (*it)[5] == "imaginary") {
      EXPECT_NEAR(std::abs(parseCell(csv.rows[20 * n + b][3])), 4.46486771378823, 1e-6);
    }
  }
  EXPECT_EQ(drawn, (std::set<std::string>{"weave real", "weave imaginary", "capsize real", "castor real"}));
  expectCompleteImages(dir, "real_part_vs_speed");
}

TEST(SweepPlot, NoStableRangeIsNotShadedAndIsSaid) {
  if (!hasGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  PortableRandom rng(1982);
  SweepResult s;
  const double step = rng.drawUniform(0.1, 0.5);
  for (int k = 0; k < 30; ++k) s.speeds.push_back(k * step);
  // A weave that stabilises at a random speed, and a capsize mode unstable everywhere.
  const double a = rng.drawUniform(2 * step, 20 * step);
  using analysis::ModeLabel;
  const std::vector<ModeLabel> weaves(s.speeds.size(), ModeLabel::Weave), capsizes(s.speeds.size(), ModeLabel::Capsize);
  ModeBranch w1{ModeLabel::Weave, weaves, {}, {}}, w2{ModeLabel::Weave, weaves, {}, {}}, capsize{ModeLabel::Capsize, capsizes, {}, {}};
  for (double v : s.speeds) {
    w1.eigenvalue.push_back(cd(a - v, 2 + v)), w2.eigenvalue.push_back(cd(a - v, -2 - v));
    capsize.eigenvalue.push_back(cd(rng.drawUniform(0.01, 1), 0));
  }
  s.branches = {w1, capsize, w2};
  s.criticalSpeeds = {{ModeLabel::Weave, a, true}};
  const auto dir = makeTempDir("sweep_plot_unstable");
  writeSweepOutputs(dir, "always-capsizing", s);
  const std::string script = readText(dir / "real_part_vs_speed.gp");
  const Marks marks = parseMarks(script);
  EXPECT_TRUE(marks.shaded.empty()) << script;
  EXPECT_EQ(script.find("set object"), std::string::npos);
  std::ostringstream range;
  range << "no stable speed range in 0.0 - " << std::fixed << std::setprecision(1) << s.speeds.back() << " m/s";
  EXPECT_NE(std::find(marks.labels.begin(), marks.labels.end(), range.str()), marks.labels.end()) << script;
  ASSERT_EQ(marks.lines.size(), 1u);
  EXPECT_EQ(marks.lines[0].second, a);
  std::ifstream summaryFile(dir / "summary.json");
  EXPECT_TRUE(nlohmann::json::parse(summaryFile).at("stable_speed_ranges_mps").empty());
  EXPECT_NE(formatSweepTable(s).find("No stable speed range in 0.00 - "), std::string::npos);
  expectCompleteImages(dir, "real_part_vs_speed");
}

}  // namespace
}  // namespace motostab::output
