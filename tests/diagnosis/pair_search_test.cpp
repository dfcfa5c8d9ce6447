// The pair search (diagnosis/pair_search.h): merged candidates keep both members' overrides and give
// each parameter a unique name; on the benchmark bicycle a hidden compliant fork with a shorter trail
// (values drawn), whose effects on the weave and capsize rows partly cancel so that no single candidate
// qualifies, is found as the pair.
#include "diagnosis/pair_search.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/portable_random.h"
#include "io/number.h"
#include "run_hidden.h"

namespace motostab::diagnosis {

using core::PortableRandom;
using io::formatNumber;

namespace {

TEST(PairSearch, MergedCandidateHoldsBothMembers) {
  const Candidate fork{"fork_compliance", {"fork_compliance={stiffness_Nm_per_rad: 1e4}"}, {CandidateParameter()}};
  Candidate trail{"parameter:geometry.trail_m", {}, {CandidateParameter()}};
  Candidate fork2 = fork;
  fork2.parameters[0].name = "stiffness_Nm_per_rad", fork2.parameters[0].path = "fork_compliance.stiffness_Nm_per_rad";
  trail.parameters[0].name = "value", trail.parameters[0].path = "geometry.trail_m";
  const Candidate pair = mergeCandidates(fork2, trail);
  EXPECT_EQ(pair.name, "fork_compliance + parameter:geometry.trail_m");
  EXPECT_EQ(pair.fixedOverrides, fork.fixedOverrides);
  ASSERT_EQ(pair.parameters.size(), 2u);
  EXPECT_EQ(pair.parameters[0].name, "fork_compliance.stiffness_Nm_per_rad");
  EXPECT_EQ(pair.parameters[1].name, "geometry.trail_m");
  EXPECT_EQ(pair.parameters[1].path, "geometry.trail_m");
}

// Candidates: the pair's members and two parameters that also move the weave. The steer damper is
// left out: on these modes it mimics a compliant fork (it takes fork-compliance data alone).
TEST(PairSearch, CancellingForkComplianceAndTrailAreFoundTogether) {
  PortableRandom rng(6060);
  const double k = rng.drawUniform(18000, 22000), trail = 0.08 - rng.drawUniform(0.0035, 0.0045);
  testing::HiddenEffect h;
  h.scenario = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";
  h.seed = 6061;
  h.overrides = {"fork_compliance={stiffness_Nm_per_rad: " + formatNumber(k) + ", damping_Nms_per_rad: 0}",
                 "geometry.trail_m=" + formatNumber(trail)};  // Meijaard et al. 2007 Table 1: trail 0.08 m
  h.modes = {"weave", "capsize"};
  h.step = 0.25, h.relativeNoise = 0.005, h.absoluteNoise = 0.005;
  const DiagnosisResult r = testing::runHidden(
      h, "pair", true, {}, "fork_compliance,parameter:geometry.trail_m,parameter:geometry.wheelbase_m,parameter:front_frame.inertia_kgm2.zz", 2);
  for (const auto& f : r.candidates) EXPECT_FALSE(f.failed.empty()) << f.name << " qualifies alone: no pair needed";
  ASSERT_FALSE(r.pairs.empty());
  ASSERT_EQ(r.causes.size(), 1u);
  const FitSummary& named = r.causes[0].fit;
  std::vector<std::string> members = named.members;
  std::sort(members.begin(), members.end());
  EXPECT_EQ(members, (std::vector<std::string>{"fork_compliance", "parameter:geometry.trail_m"})) << named.name;
  ASSERT_EQ(named.parameters.size(), 2u);
  for (const ParameterEstimate& e : named.parameters) {
    const bool isTrail = e.name == "geometry.trail_m";
    EXPECT_TRUE(isTrail || e.name == "fork_compliance.stiffness_Nm_per_rad") << e.name;
    EXPECT_NEAR(e.value, isTrail ? trail : k, 3 * e.stderr_) << e.name;
  }
  EXPECT_LE(named.deltaBic, -10);
}

}  // namespace
}  // namespace motostab::diagnosis
