// The swingarm study's halved variants carry their scale factors as doubles: the scenario each
// variant is built from holds the factor drawn here to the bit (as text, "0.707107" lost 2.8e-7).
#include <gtest/gtest.h>

#include "core/portable_random.h"
#include "io/yaml_map.h"
#include "scenario/scenario_source.h"
#include "studies/study.h"

namespace motostab::studies {

using core::PortableRandom;
using scenario::Scenario;
using scenario::ScenarioSource;

namespace {

const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

TEST(StudyOverrides, ScaleFactorsKeepFullPrecision) {
  PortableRandom random(1811);
  StudyOptions opt;
  opt.variants = {"torsion"};
  opt.stiffnessScale = random.drawUniform(0.3, 0.7);
  opt.dampingScale = 1.0 / std::sqrt(2.0);
  opt.shapeSpeeds = {};
  opt.sweep.start = 10, opt.sweep.stop = 10.2, opt.sweep.step = 0.1;
  opt.threads = 2;
  const long opened = io::getYamlFileOpenCount(kEnduro);
  const ScenarioSource source(kEnduro);
  const StudyResult r = runStudy(source, opt);
  EXPECT_EQ(io::getYamlFileOpenCount(kEnduro) - opened, 1) << "the study reads its scenario once";
  ASSERT_EQ(r.halved.size(), 1u);
  const Scenario s = ScenarioSource(kEnduro).load(r.halved[0].overrides);
  EXPECT_EQ(s.swingarm.compliance, "torsion");
  EXPECT_EQ(s.swingarm.params["stiffness_scale"].as<double>(), opt.stiffnessScale);
  EXPECT_EQ(s.swingarm.params["damping_scale"].as<double>(), opt.dampingScale);
  EXPECT_EQ(r.halved[0].sweep.speeds.size(), 3u);
}

}  // namespace
}  // namespace motostab::studies
