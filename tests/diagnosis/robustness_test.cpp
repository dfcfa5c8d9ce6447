// The data variants of the robustness reruns (diagnosis/robustness.h).
#include "diagnosis/robustness.h"

#include <gtest/gtest.h>

#include "core/portable_random.h"

namespace motostab::diagnosis {

using core::PortableRandom;

namespace {

MeasuredEigenvalue makeRow(const std::string& file, double lo, double hi) {
  MeasuredEigenvalue e;
  e.where.file = file;
  e.speedMin = lo, e.speedMax = hi, e.speed = 0.5 * (lo + hi), e.hasRange = hi > lo;
  e.mode = analysis::ModeLabel::Weave;
  return e;
}

TEST(Robustness, EachSourceLeftOutAndRangesAtMidSpeeds) {
  MeasuredData d;
  d.eigenvalueFiles = {"/x/a.csv", "/x/b.csv"};
  d.eigenvalues = {makeRow("/x/a.csv", 4, 4.6), makeRow("/x/a.csv", 5, 5), makeRow("/x/b.csv", 6, 6)};
  d.responses.resize(2);
  d.responses[0].file = "/x/run1.csv", d.responses[1].file = "/x/run2.csv";
  const auto v = makeRobustnessVariants(d);
  ASSERT_EQ(v.size(), 5u);
  EXPECT_EQ(v[0].leftOut, "eigenvalues: a.csv");
  EXPECT_EQ(v[0].data.eigenvalues.size(), 1u);
  EXPECT_EQ(v[0].data.eigenvalueFiles, std::vector<std::string>{"/x/b.csv"});
  EXPECT_EQ(v[1].data.eigenvalues.size(), 2u);
  EXPECT_EQ(v[2].leftOut, "response run 1: run1.csv");
  ASSERT_EQ(v[2].data.responses.size(), 1u);
  EXPECT_EQ(v[2].data.responses[0].file, "/x/run2.csv");
  EXPECT_EQ(v[3].data.responses[0].file, "/x/run1.csv");
  EXPECT_EQ(v[4].leftOut, "speed ranges -> mid speeds");
  EXPECT_FALSE(v[4].data.eigenvalues[0].hasRange);
  EXPECT_DOUBLE_EQ(v[4].data.eigenvalues[0].speed, 4.3);
  EXPECT_DOUBLE_EQ(v[4].data.eigenvalues[0].speedMin, 4.3);
}

TEST(Robustness, NoVariantThatLeavesNothingOrChangesNothing) {
  MeasuredData d;
  d.eigenvalueFiles = {"/x/a.csv"};
  d.eigenvalues = {makeRow("/x/a.csv", 4, 4), makeRow("/x/a.csv", 5, 5)};
  EXPECT_TRUE(makeRobustnessVariants(d).empty());
}

FitSummary makeFit(const std::string& name, double value, double se, bool profile) {
  FitSummary f;
  f.name = name;
  ParameterEstimate e;
  e.name = "value", e.value = value, e.stderr_ = se;
  if (profile) e.hasProfile = true, e.profileLow = value - 2 * se, e.profileHigh = value + 2.1 * se;
  f.parameters = {e};
  return f;
}

RobustnessRun makeRun(const std::vector<FitSummary>& fits) {
  RobustnessRun r;
  for (const auto& f : fits) r.causes.push_back(f.name), r.fits.push_back(f);
  return r;
}

// The verdicts of robustness.h on made-up causes, values drawn: fragile only for another first cause
// or the same one with a value outside the full data's interval.
TEST(Robustness, VerdictsFollowTheFirstCauseAndItsInterval) {
  PortableRandom rng(4242);
  for (int trial = 0; trial < 20; ++trial) {
    const double v = rng.drawUniform(0.1, 1), se = rng.drawUniform(0.01, 0.05);
    Cause full{makeFit("steer_damper", v, se, true), {makeFit("fork_compliance", v, se, false)}};
    const std::vector<Cause> causes{full};
    // The same cause within the interval (the variant's own interval overlapping): same.
    RobustnessRun same = makeRun({makeFit("steer_damper", v + rng.drawUniform(-3, 3) * se, se, false)});
    EXPECT_EQ(judgeRobustness(causes, same), RobustnessVerdict::Same);
    // Beyond both intervals (4.2 + 1.96 stderr away at least): value differs, fragile.
    RobustnessRun moved = makeRun({makeFit("steer_damper", v + (rng.drawUniform() < 0.5 ? -1 : 1) * rng.drawUniform(4.5, 8) * se, se, false)});
    moved.verdict = judgeRobustness(causes, moved);
    EXPECT_EQ(moved.verdict, RobustnessVerdict::ValueDiffers);
    EXPECT_TRUE(moved.isFragile());
    // Nothing named with less data: lost power, not fragile.
    RobustnessRun none;
    none.verdict = judgeRobustness(causes, none);
    EXPECT_EQ(none.verdict, RobustnessVerdict::LostPower);
    EXPECT_FALSE(none.isFragile());
    // The look-alike the full data listed: not fragile.
    RobustnessRun alike = makeRun({makeFit("fork_compliance", v, se, false)});
    alike.verdict = judgeRobustness(causes, alike);
    EXPECT_EQ(alike.verdict, RobustnessVerdict::Indistinguishable);
    EXPECT_FALSE(alike.isFragile());
    // Another cause: fragile; a failed search: no verdict, not fragile.
    RobustnessRun other = makeRun({makeFit("parameter:geometry.trail_m", v, se, false)});
    other.verdict = judgeRobustness(causes, other);
    EXPECT_TRUE(other.isFragile());
    RobustnessRun failed;
    failed.error = "trim failed";
    EXPECT_EQ(judgeRobustness(causes, failed), RobustnessVerdict::Failed);
    // The full data named nothing: a variant naming something is another cause.
    EXPECT_EQ(judgeRobustness({}, other), RobustnessVerdict::OtherCause);
    EXPECT_EQ(judgeRobustness({}, none), RobustnessVerdict::Same);
  }
}

TEST(Robustness, FragileResultNeedsAFragileRun) {
  DiagnosisResult r;
  RobustnessRun lost, alike;
  lost.verdict = RobustnessVerdict::LostPower, alike.verdict = RobustnessVerdict::Indistinguishable;
  r.robustness = {lost, alike};
  EXPECT_FALSE(r.isFragile());
  RobustnessRun other;
  other.verdict = RobustnessVerdict::OtherCause;
  r.robustness.push_back(other);
  EXPECT_TRUE(r.isFragile());
}

}  // namespace
}  // namespace motostab::diagnosis
