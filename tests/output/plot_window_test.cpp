// The axes of the eigenvalue plots (output/plot_window.h): fitted to the named modes, with the roots
// far outside them left off and counted in the legend; the generated gnuplot scripts of the sweep,
// speed x roll map and compare plots carry those ranges, speed marks, a colour bar per roll and
// escaped enhanced text. Spectra are drawn at random; the expectations are the rule itself.
#include <gtest/gtest.h>

#include "tests/support/text_file.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/portable_random.h"
#include "io/plot.h"
#include "output/map_output.h"
#include "output/plot_window.h"
#include "output/sweep_output.h"
#include "tests/support/temp_dir.h"

namespace motostab::output {
namespace {

using analysis::ModeBranch;
using analysis::ModeLabel;
using analysis::SweepResult;
using core::PortableRandom;
using cd = std::complex<double>;

const std::vector<ModeLabel> kNamed{ModeLabel::Weave, ModeLabel::Wobble, ModeLabel::Capsize, ModeLabel::Castor};

bool hasGnuplot() { return std::system("gnuplot --version >/dev/null 2>&1") == 0; }

// A complex pair (two branches) or a real root labelled `label` at every speed, its eigenvalue drawn
// along a straight path between two random ends.
void addRoot(std::vector<ModeBranch>& out, ModeLabel label, cd a, cd b, size_t n) {
  ModeBranch upper{label, std::vector<ModeLabel>(n, label), {}, {}}, lower = upper;
  for (size_t k = 0; k < n; ++k) {
    const cd l = a + (b - a) * (double(k) / double(n - 1));
    upper.eigenvalue.push_back({l.real(), std::abs(l.imag())});
    lower.eigenvalue.push_back({l.real(), -std::abs(l.imag())});
  }
  out.push_back(upper);
  if (a.imag() != 0 || b.imag() != 0) out.push_back(lower);
}

struct Spectrum {
  SweepResult sweep;
  int fastRoots = 0;         // roots far outside the named modes: they must leave the axes
  double fastest = 0;        // their most negative real part, 1/s
  double namedLeft = 0;      // the named points' extremes (with 0), 1/s and Hz
  double namedRight = 0, namedTop = 0;
};

// Weave, wobble, capsize and castor in plausible ranges, and fast tyre-like and high-frequency roots
// beyond three times the named span.
Spectrum drawSpectrum(PortableRandom& rng, size_t n) {
  Spectrum s;
  for (size_t k = 0; k < n; ++k) s.sweep.speeds.push_back(1.0 + k);
  auto& br = s.sweep.branches;
  const double pi2 = 2 * M_PI;
  addRoot(br, ModeLabel::Weave, cd(rng.drawUniform(-2, 4), pi2 * rng.drawUniform(0.2, 1)), cd(rng.drawUniform(-12, -1), pi2 * rng.drawUniform(2, 4.5)), n);
  addRoot(br, ModeLabel::Wobble, cd(rng.drawUniform(-30, -5), pi2 * rng.drawUniform(6, 10)), cd(rng.drawUniform(-5, 3), pi2 * rng.drawUniform(7, 13)), n);
  addRoot(br, ModeLabel::Capsize, cd(rng.drawUniform(-4, -1), 0), cd(rng.drawUniform(-0.1, 0.3), 0), n);
  addRoot(br, ModeLabel::Castor, cd(rng.drawUniform(-60, -20), 0), cd(rng.drawUniform(-20, -8), 0), n);
  for (const auto& b : br)
    for (const cd& l : b.eigenvalue)
      s.namedLeft = std::min(s.namedLeft, l.real()), s.namedRight = std::max(s.namedRight, l.real()),
      s.namedTop = std::max(s.namedTop, l.imag() / pi2);
  const double span = s.namedRight - s.namedLeft;
  s.fastRoots = 2 + static_cast<int>(rng.drawUniform(0, 4));
  for (int i = 0; i < s.fastRoots; ++i) {
    const double re = s.namedLeft - 3 * span - rng.drawUniform(0, 6e4);
    const bool oscillating = i % 2 == 1;
    const double f = oscillating ? pi2 * rng.drawUniform(1, 80) : 0;  // a pair stays a pair (counted once)
    addRoot(br, ModeLabel::FrontTyreRelaxation, cd(re, f), cd(re * 1.2, f), n);
    s.fastest = std::min(s.fastest, re * 1.2);
  }
  // A root inside the real range but far above the named frequencies (a swingarm mode).
  addRoot(br, ModeLabel::SwingarmTorsion, cd(s.namedLeft / 2, pi2 * 4 * s.namedTop), cd(s.namedLeft / 3, pi2 * 5 * s.namedTop), n);
  ++s.fastRoots;
  // A root close to the named ones stays inside the window: not counted.
  addRoot(br, ModeLabel::RearTyreRelaxation, cd(s.namedLeft / 2, 0), cd(s.namedLeft / 2, 0), n);
  return s;
}

TEST(PlotWindow, NamedModesInsideFastRootsOutsideAndCounted) {
  PortableRandom rng(20240611);
  for (int trial = 0; trial < 200; ++trial) {
    const Spectrum s = drawSpectrum(rng, 3 + trial % 20);
    const auto named = collectNamedPoints(s.sweep.branches, kNamed);
    const LocusWindow w = calcLocusWindow(named);
    for (const cd& l : named) ASSERT_TRUE(w.contains(l)) << l << " trial " << trial;
    // Fitted: no wider than the named span (with 0) plus the margins.
    const double span = s.namedRight - s.namedLeft;
    EXPECT_NEAR(w.real.lo, s.namedLeft - kPlotMargin * span, 1e-9 * span);
    EXPECT_NEAR(w.real.hi, s.namedRight + kPlotMargin * span, 1e-9 * span);
    EXPECT_NEAR(w.frequency.hi, (1 + kPlotMargin) * s.namedTop, 1e-9 * s.namedTop);
    EXPECT_LT(w.frequency.lo, 0);  // real roots sit on the axis, inside
    const HiddenRoots h = findHiddenRoots(w, collectOtherRoots(s.sweep.branches, kNamed));
    ASSERT_EQ(h.count, s.fastRoots) << "trial " << trial;
    EXPECT_DOUBLE_EQ(h.realMin, s.fastest);
    const std::string note = formatLocusNote(h);
    EXPECT_EQ(note.rfind(std::to_string(s.fastRoots) + " roots off the axes (real part ", 0), 0u) << note;
  }
}

TEST(PlotWindow, PerSpeedLabelsDecideWhatIsNamed) {
  // A branch that is the weave at some speeds and a fast root at others: only its weave points count.
  PortableRandom rng(7);
  const double weaveRe = rng.drawUniform(-3, 1), fastRe = rng.drawUniform(-5e4, -1e3);
  ModeBranch b{ModeLabel::Weave, {ModeLabel::Weave, ModeLabel::Other, ModeLabel::Weave}, {cd(weaveRe, 10), cd(fastRe, 10), cd(weaveRe, 12)}, {}};
  const LocusWindow w = calcLocusWindow(collectNamedPoints({b}, kNamed));
  EXPECT_FALSE(w.real.contains(fastRe));
  const HiddenRoots h = findHiddenRoots(w, collectOtherRoots({b}, kNamed));
  EXPECT_EQ(h.count, 1);
  EXPECT_EQ(h.realMin, fastRe);
  EXPECT_TRUE(formatLocusNote({}).empty());
  // The real-part axis: the hidden roots are those whose real part leaves it.
  const AxisRange r = calcAxisRange({weaveRe, 10, 12});
  EXPECT_EQ(findHiddenRealParts(r, {{cd(fastRe, 0)}, {cd(weaveRe, 0)}}).count, 1);
  EXPECT_EQ(formatRealPartNote(findHiddenRealParts(r, {{cd(fastRe, 0)}})).rfind("1 other root off the axes", 0), 0u);
}

TEST(PlotWindow, EnhancedTextIsEscaped) {
  EXPECT_EQ(io::gnuplotText("swingarm_torsion"), "'swingarm\\_torsion'");
  EXPECT_EQ(io::gnuplotText("a^b {c} @d &e ~f"), "'a\\^b \\{c\\} \\@d \\&e \\~f'");
  EXPECT_EQ(io::gnuplotText("rider's"), "'rider''s'");
}

// Every quoted text of a title, key entry or axis label in `script` whose line is in enhanced mode
// (no `noenhanced`) has each underscore escaped.
void expectNoBareUnderscore(const std::string& script, const std::string& what) {
  const std::regex text(R"((title|label \d+|[xy]label|cblabel) '((?:[^']|'')*)')");
  std::istringstream lines(script);
  int checked = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.find("noenhanced") != std::string::npos) continue;
    for (std::sregex_iterator it(line.begin(), line.end(), text), end; it != end; ++it, ++checked) {
      const std::string t = (*it)[2];
      for (size_t i = t.find('_'); i != std::string::npos; i = t.find('_', i + 1))
        EXPECT_TRUE(i > 0 && t[i - 1] == '\\') << what << ": bare underscore in " << t;
    }
  }
  EXPECT_GT(checked, 3) << what;
}

double parseRange(const std::string& script, const std::string& axis, int end) {
  const std::regex r("set " + axis + R"(range \[([^:\]]+):([^\]]+)\])");
  std::smatch m;
  EXPECT_TRUE(std::regex_search(script, m, r)) << axis;
  return std::stod(m[end].str());
}

TEST(PlotWindow, SweepScriptsCarryTheWindowTheNoteAndSpeedMarks) {
  if (!hasGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  PortableRandom rng(31);
  Spectrum s = drawSpectrum(rng, 12);
  s.sweep.criticalSpeeds = {{ModeLabel::SwingarmTorsion, 4.5, false}};  // a label with an underscore
  const auto dir = makeTempDir("plot_window_sweep");
  writeSweepOutputs(dir, "fast_tyres", s.sweep);
  const std::string locus = readText(dir / "root_locus.gp"), real = readText(dir / "real_part_vs_speed.gp");
  const LocusWindow w = calcLocusWindow(collectNamedPoints(s.sweep.branches, kNamed));
  EXPECT_DOUBLE_EQ(parseRange(locus, "x", 1), w.real.lo);
  EXPECT_DOUBLE_EQ(parseRange(locus, "x", 2), w.real.hi);
  EXPECT_DOUBLE_EQ(parseRange(locus, "y", 2), w.frequency.hi);
  EXPECT_NE(locus.find(std::to_string(s.fastRoots) + " roots off the axes"), std::string::npos) << locus;
  EXPECT_NE(locus.find("other roots"), std::string::npos);
  // Up to five speed marks on each of the four modes (first, last and three between), each inside the
  // window with its arrow, none on top of another (3 % of the axes apart).
  const std::regex mark(R"(set label (\d+) '([0-9.]+)' at ([^,]+), ([^ ]+) point)");
  std::vector<std::pair<double, double>> placed;
  for (std::sregex_iterator it(locus.begin(), locus.end(), mark), end; it != end; ++it) {
    const double x = std::stod((*it)[3]), y = std::stod((*it)[4]);
    EXPECT_TRUE(w.contains(cd(x, 2 * M_PI * y)));
    EXPECT_NE(locus.find("set arrow " + (*it)[1].str() + " from"), std::string::npos);
    placed.push_back({(x - w.real.lo) / (w.real.hi - w.real.lo), (y - w.frequency.lo) / (w.frequency.hi - w.frequency.lo)});
  }
  const size_t marks = placed.size() / 2;  // the body runs once per image format
  EXPECT_GE(marks, 8u) << locus;
  EXPECT_LE(marks, 20u);
  for (size_t i = 0; i < marks; ++i)
    for (size_t j = 0; j < i; ++j)
      EXPECT_FALSE(std::abs(placed[i].first - placed[j].first) < 0.03 && std::abs(placed[i].second - placed[j].second) < 0.03);
  EXPECT_NE(locus.find("'1' at"), std::string::npos);
  EXPECT_NE(locus.find("'12' at"), std::string::npos);
  // The real-part plot: the vertical axis fitted to the named real and imaginary parts, the fast roots counted.
  EXPECT_LT(parseRange(real, "y", 1), 0);
  EXPECT_GE(parseRange(real, "y", 1), s.namedLeft - kPlotMargin * (2 * M_PI * s.namedTop - s.namedLeft) - 1e-9);
  EXPECT_NE(real.find("other roots off the axes"), std::string::npos) << real;
  expectNoBareUnderscore(locus, "root_locus.gp");
  expectNoBareUnderscore(real, "real_part_vs_speed.gp");
  EXPECT_NE(real.find("'swingarm\\_torsion 4.500 m/s'"), std::string::npos);
  for (const char* f : {"root_locus.png", "root_locus.svg", "real_part_vs_speed.png"})
    EXPECT_GT(std::filesystem::file_size(dir / f), 10000u) << f;
}

TEST(PlotWindow, MapColoursEachRollByAPaletteWithAColourBar) {
  if (!hasGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  PortableRandom rng(77);
  analysis::TurnMapResult map;
  const int rolls = 2 + static_cast<int>(rng.drawUniform(0, 3));
  for (int j = 0; j < rolls; ++j) {
    map.rolls.push_back(j * 10 * M_PI / 180);
    map.sweeps.push_back(drawSpectrum(rng, 6).sweep);
  }
  const auto dir = makeTempDir("plot_window_map");
  writeTurnMapOutputs(dir, "map_test", map);
  const std::string loci = readText(dir / "root_loci.gp");
  EXPECT_NE(loci.find("lc palette z"), std::string::npos);
  EXPECT_EQ(loci.find("lc i+1"), std::string::npos);  // gnuplot's eight line colours repeat
  EXPECT_NE(loci.find("set cblabel 'roll angle (deg)'"), std::string::npos);
  EXPECT_DOUBLE_EQ(parseRange(loci, "cb", 1), 0);
  EXPECT_NEAR(parseRange(loci, "cb", 2), (rolls - 1) * 10, 1e-9);
  // Fitted to the weave and wobble of every roll.
  std::vector<cd> named;
  for (const auto& s : map.sweeps) {
    const auto p = collectNamedPoints(s.branches, {ModeLabel::Weave, ModeLabel::Wobble});
    named.insert(named.end(), p.begin(), p.end());
  }
  EXPECT_DOUBLE_EQ(parseRange(loci, "x", 1), calcLocusWindow(named).real.lo);
  expectNoBareUnderscore(loci, "root_loci.gp");
  expectNoBareUnderscore(readText(dir / "damping_map.gp"), "damping_map.gp");
  EXPECT_NE(readText(dir / "damping_map.gp").find("set cblabel 'damping ratio"), std::string::npos);
  for (const char* f : {"root_loci.png", "real_part_vs_speed.png", "damping_map.png"})
    EXPECT_GT(std::filesystem::file_size(dir / f), 10000u) << f;
}

}  // namespace
}  // namespace motostab::output
