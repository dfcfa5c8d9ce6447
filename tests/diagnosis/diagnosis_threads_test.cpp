// The diagnosis's worker threads (candidate fits, their cross-validation, and the folds of the
// extended model's cross-validation): two threads give exactly the one-thread result. Small on
// purpose: ThreadSanitizer runs it (./test.sh --tsan, ctest -R 'Parallel|Threads|SweepWorker').
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "diagnosis/diagnosis.h"
#include "hidden_effect.h"

namespace motostab::diagnosis {

using io::formatNumber;

namespace {

namespace fs = std::filesystem;

TEST(DiagnosisThreads, TwoThreadsGiveTheOneThreadResult) {
  testing::HiddenEffect h;
  h.scenario = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";
  h.seed = 4711;
  h.overrides = {"steer_damper={damping_Nms_per_rad: " + formatNumber(testing::Draw(4712).uniform(0.2, 0.4)) + "}"};
  h.start = 4, h.stop = 6, h.step = 0.5;
  const fs::path dir = fs::temp_directory_path() / ("motostab-threads-" + std::to_string(::getpid()));
  const MeasuredData data = loadMeasuredData(testing::writeHiddenEffectData(h, dir, true));
  fs::remove_all(dir);
  DiagnosisOptions opt;
  opt.candidates = {"steer_damper", "parameter:geometry.trail_m", "parameter:geometry.wheelbase_m"};
  opt.maxCauses = 1;
  opt.folds = 3;
  opt.threads = 1;
  const DiagnosisResult one = runDiagnosis(h.scenario, data, opt);
  opt.threads = 2;
  const DiagnosisResult two = runDiagnosis(h.scenario, data, opt);
  ASSERT_EQ(one.candidates.size(), two.candidates.size());
  for (size_t i = 0; i < one.candidates.size(); ++i) {
    EXPECT_EQ(one.candidates[i].name, two.candidates[i].name);
    EXPECT_EQ(one.candidates[i].chi2, two.candidates[i].chi2);
    EXPECT_EQ(one.candidates[i].cvRms, two.candidates[i].cvRms);
    EXPECT_EQ(one.candidates[i].foldRms, two.candidates[i].foldRms);
  }
  EXPECT_EQ(one.causes.size(), two.causes.size());
  EXPECT_EQ(one.extended.cvRms, two.extended.cvRms);
}

}  // namespace
}  // namespace motostab::diagnosis
