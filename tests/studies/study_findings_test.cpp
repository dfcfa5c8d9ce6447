// calcStudyFindings on a synthetic study whose weave, wobble and swingarm branches are drawn at
// random: each figure is checked against the value worked out here from the drawn numbers.
#include <gtest/gtest.h>

#include <cmath>

#include "core/portable_random.h"
#include "studies/study_findings.h"

namespace motostab::studies {

using analysis::ModeBranch;
using core::PortableRandom;

namespace {

const std::vector<double> kSpeeds{4, 8, 12, 16, 17, 20, 23, 26, 30, 35};

// A variant whose weave real part is base + slope * speed and whose wobble is `wobble` (1/s) at every speed.
StudyVariant makeVariant(const std::string& name, double base, double slope, std::complex<double> wobble) {
  StudyVariant v;
  v.name = name;
  v.sweep.speeds = kSpeeds;
  using analysis::ModeLabel;
  ModeBranch weave{ModeLabel::Weave, std::vector<ModeLabel>(kSpeeds.size(), ModeLabel::Weave), {}, {}};
  ModeBranch wob{ModeLabel::Wobble, std::vector<ModeLabel>(kSpeeds.size(), ModeLabel::Wobble), {}, {}};
  for (double s : kSpeeds) {
    weave.eigenvalue.push_back({base + slope * s, 2 * M_PI * (1 + 0.05 * s)});
    wob.eigenvalue.push_back(wobble);
  }
  v.sweep.branches = {weave, wob};
  return v;
}

TEST(StudyFindings, FiguresFromTheBranches) {
  PortableRandom g(20251125);
  const double base = g.drawUniform(-2, -1), slope = g.drawUniform(0.01, 0.05), offset = g.drawUniform(0.1, 0.5);
  const std::complex<double> wobble0(-g.drawUniform(1, 3), 2 * M_PI * 9), wobble1 = wobble0 * 1.02;
  StudyResult st;
  st.nominal = {makeVariant("rigid", base, slope, wobble0), makeVariant("torsion", base - offset, slope, wobble1)};
  st.halved = {makeVariant("rigid", base, slope, wobble0), makeVariant("torsion", base - 2 * offset, slope, wobble1)};
  ModeBranch swing{analysis::ModeLabel::SwingarmTorsion, {}, {{-5, 2 * M_PI * 60}, {-6, 2 * M_PI * 61}}, {}};
  st.nominal[1].sweep.branches.push_back(swing);
  st.nominal[1].sweep.branches.back().eigenvalue.resize(kSpeeds.size(), {-6, 2 * M_PI * 61});

  const StudyFindings f = calcStudyFindings(st);
  // Wobble: 9 Hz (rigid) and 2 % more (torsion); the rigid real part is the larger; shift 2 %.
  EXPECT_NEAR(f.wobble.minFrequencyHz, 9.0, 1e-12);
  EXPECT_NEAR(f.wobble.maxFrequencyHz, 9.0 * 1.02, 1e-12);
  EXPECT_NEAR(f.wobble.maxRealPart, std::max(wobble0.real(), wobble1.real()), 1e-12);
  EXPECT_NEAR(f.wobble.maxRelativeShift, 0.02, 1e-12);
  // Weave of the rigid variant: 1 + 0.05 v Hz over the grid; lowest real part at 10 m/s and up is at 12 m/s.
  ASSERT_TRUE(f.weave.present);
  EXPECT_NEAR(f.weave.minFrequencyHz, 1 + 0.05 * 4, 1e-12);
  EXPECT_NEAR(f.weave.maxFrequencyHz, 1 + 0.05 * 35, 1e-12);
  EXPECT_DOUBLE_EQ(f.weave.mostStableSpeed, 12);
  EXPECT_NEAR(f.weave.mostStableRealPart, base + slope * 12, 1e-12);
  // Table: torsion only, 6 speeds; 17 m/s is on the grid.
  ASSERT_EQ(f.complianceEffect.size(), 6u);
  const auto& row = f.complianceEffect[1];
  EXPECT_EQ(row.variant, "torsion");
  EXPECT_DOUBLE_EQ(row.speed, 17);
  const double a0 = base + slope * 17;
  EXPECT_NEAR(row.identified, a0 - offset, 1e-12);
  EXPECT_NEAR(row.identifiedVsRigidPercent, -100 * offset / std::abs(a0), 1e-9);
  EXPECT_NEAR(row.halvedVsRigidPercent, -200 * offset / std::abs(a0), 1e-9);
  EXPECT_EQ(f.mostStable, "torsion");
  EXPECT_EQ(f.leastStable, "rigid");
  ASSERT_EQ(f.swingarmModes.size(), 1u);
  EXPECT_NEAR(f.swingarmModes[0].firstFrequencyHz, 60, 1e-12);
  EXPECT_NEAR(f.swingarmModes[0].lastFrequencyHz, 61, 1e-12);
  EXPECT_DOUBLE_EQ(f.swingarmModes[0].lastSpeed, 35);
}

TEST(StudyFindings, WeaveRealPartAtTheNearestGridSpeed) {
  const StudyVariant v = makeVariant("rigid", -1, 0.1, {-1, 50});
  EXPECT_DOUBLE_EQ(getWeaveRealPart(v, 18.9), -1 + 0.1 * 20);
  StudyVariant none;
  none.sweep.speeds = kSpeeds;
  EXPECT_TRUE(std::isnan(getWeaveRealPart(none, 10)));
}

}  // namespace
}  // namespace motostab::studies
