// The data variants of the robustness reruns (diagnosis/robustness.h).
#include "diagnosis/robustness.h"

#include <gtest/gtest.h>

namespace motostab::diagnosis {
namespace {

MeasuredEigenvalue makeRow(const std::string& file, double lo, double hi) {
  MeasuredEigenvalue e;
  e.where.file = file;
  e.speedMin = lo, e.speedMax = hi, e.speed = 0.5 * (lo + hi), e.hasRange = hi > lo;
  e.mode = "weave";
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

}  // namespace
}  // namespace motostab::diagnosis
