// The store of linear models shared by a diagnosis (diagnosis/sweep_cache.h): a prediction taken
// from it is the prediction computed anew, to the bit; keys tell apart doubles one ulp apart; a
// failure is stored and rethrown; an evicted chain is computed again, identical; and a whole
// diagnosis (search, folds, profiles, robustness reruns) gives the same causes and values with the
// reuse on and off, on one and two threads. ThreadSanitizer runs the threaded store test
// (SweepCacheThreads) and the diagnosis on two threads with the store (diagnosis_threads_test.cpp).
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include "diagnosis/diagnosis.h"
#include "hidden_effect.h"
#include "scenario/scenario_source.h"

namespace motostab::diagnosis {
namespace {

namespace fs = std::filesystem;
using scenario::ParameterOverrides;
using scenario::ScenarioSource;

const std::string kBenchmark = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

// Weave rows at 4-6 m/s and one free-response run at a drawn speed of the benchmark bicycle with a
// hidden steer damper; returns the measured-data file (in `dir`).
std::string writeData(const fs::path& dir, uint64_t seed, double& runSpeed) {
  testing::HiddenEffect h;
  h.scenario = kBenchmark;
  h.seed = seed;
  testing::Draw draw(seed + 1);
  h.overrides = {"steer_damper={damping_Nms_per_rad: " + io::formatNumber(draw.uniform(0.2, 0.4)) + "}"};
  h.start = 4, h.stop = 6, h.step = 0.5;
  h.runSamples = 100;
  runSpeed = draw.uniform(4.2, 5.8);
  return testing::writeHiddenEffectData(h, dir, true, {runSpeed});
}

fs::path makeTempDir(const std::string& name) {
  return fs::temp_directory_path() / ("motostab-sweep-cache-" + name + "-" + std::to_string(::getpid()));
}

void expectSamePrediction(const Prediction& a, const Prediction& b) {
  ASSERT_EQ(a.eigenvalues.size(), b.eigenvalues.size());
  for (size_t i = 0; i < a.eigenvalues.size(); ++i) EXPECT_EQ(a.eigenvalues[i], b.eigenvalues[i]) << "row " << i;
  ASSERT_EQ(a.responses.size(), b.responses.size());
  for (size_t r = 0; r < a.responses.size(); ++r) {
    EXPECT_EQ(a.responses[r].predicted, b.responses[r].predicted);
    EXPECT_EQ(a.responses[r].gains, b.responses[r].gains);
    EXPECT_EQ(a.responses[r].offsets, b.responses[r].offsets);
  }
  EXPECT_EQ(a.numLinear, b.numLinear);
}

TEST(SweepCache, PredictionsFromTheStoreEqualNewOnes) {
  const fs::path dir = makeTempDir("predict");
  double runSpeed = 0;
  const MeasuredData data = loadMeasuredData(writeData(dir, 811, runSpeed));
  fs::remove_all(dir);
  const auto source = ScenarioSource::open(kBenchmark);
  auto cache = std::make_shared<SweepCache>();
  const Predictor cached(source, {}, data, cache), fresh(source, {}, data);
  const std::vector<std::vector<double>> sigma{{1.0, 1.0}};
  testing::Draw draw(812);
  for (int k = 0; k < 3; ++k) {  // drawn changes of the bicycle, fast and exact predictions
    ParameterOverrides ov({"steer_damper={damping_Nms_per_rad: 0}"});
    ov.set("geometry.trail_m", 0.08 + draw.uniform(-0.01, 0.01));
    ov.set("steer_damper.damping_Nms_per_rad", draw.uniform(0.0, 0.5));
    for (bool exact : {false, true}) {
      const Prediction first = cached.predict(ov, sigma, exact);
      const long hits = cache->getCounters().hits;
      const Prediction again = cached.predict(ov, sigma, exact);
      EXPECT_EQ(cache->getCounters().hits, hits + 1);  // from the store
      const Prediction anew = fresh.predict(ov, sigma, exact);
      expectSamePrediction(first, anew);
      expectSamePrediction(again, anew);
    }
  }
  // The reference sweep and the node choice are shared by a second predictor on the same rows.
  const long computed = cache->getCounters().builds;
  const Predictor second(source, {}, data, cache);
  EXPECT_EQ(cache->getCounters().builds, computed);
  EXPECT_EQ(second.getNodes(), cached.getNodes());
}

TEST(SweepCache, KeysAreExact) {
  ParameterOverrides a, b, c;
  const double v = testing::Draw(813).uniform(0.05, 0.1);
  a.set("geometry.trail_m", v);
  b.set("geometry.trail_m", std::nextafter(v, 1.0));
  c.set("geometry.trail_m", v);
  const std::vector<double> speeds{4, 5}, nudged{4, std::nextafter(5.0, 6.0)};
  EXPECT_EQ(SweepCache::makeKey("chain", a, speeds), SweepCache::makeKey("chain", c, speeds));
  EXPECT_NE(SweepCache::makeKey("chain", a, speeds), SweepCache::makeKey("chain", b, speeds));
  EXPECT_NE(SweepCache::makeKey("chain", a, speeds), SweepCache::makeKey("chain", a, nudged));
  EXPECT_NE(SweepCache::makeKey("chain", a, speeds), SweepCache::makeKey("reference", a, speeds));
}

analysis::SweepResult makeFake(double value) {
  analysis::SweepResult s;
  s.speeds = {value};
  s.models.resize(1);
  s.models[0].A = Eigen::MatrixXd::Constant(40, 40, value);  // 12.8 kB
  return s;
}

TEST(SweepCacheThreads, OneComputationPerKeyAcrossThreadsFailuresKeptEvictedRecomputed) {
  SweepCache cache(30000);  // room for two fakes
  std::atomic<int> runs{0};
  const auto compute = [&] {
    ++runs;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return makeFake(1.5);
  };
  std::shared_ptr<const analysis::SweepResult> r1, r2;
  std::thread t1([&] { r1 = cache.get("a", 1, compute); }), t2([&] { r2 = cache.get("a", 1, compute); });
  t1.join(), t2.join();
  EXPECT_EQ(runs, 1);
  EXPECT_EQ(r1, r2);
  const auto fail = [&]() -> analysis::SweepResult { ++runs; throw std::runtime_error("no trim"); };
  EXPECT_THROW(cache.get("bad", 1, fail), std::runtime_error);
  EXPECT_THROW(cache.get("bad", 1, fail), std::runtime_error);
  EXPECT_EQ(runs, 2);
  cache.get("b", 1, [] { return makeFake(2.5); });
  cache.get("c", 1, [] { return makeFake(3.5); });  // evicts "a", the least recently used
  EXPECT_LE(cache.getCounters().bytes, 30000u);
  const auto again = cache.get("a", 1, compute);
  EXPECT_EQ(runs, 3);
  EXPECT_EQ(again->models[0].A, r1->models[0].A);
  const SweepCache::Counters c = cache.getCounters();
  EXPECT_EQ(c.lookups, 7);
  EXPECT_EQ(c.hits, 2);
  EXPECT_EQ(c.builds, 5);
}

void expectSameFit(const FitSummary& a, const FitSummary& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.chi2, b.chi2) << a.name;
  EXPECT_EQ(a.bic, b.bic) << a.name;
  EXPECT_EQ(a.cvRms, b.cvRms) << a.name;
  EXPECT_EQ(a.foldRms, b.foldRms) << a.name;
  ASSERT_EQ(a.parameters.size(), b.parameters.size());
  for (size_t i = 0; i < a.parameters.size(); ++i) {
    EXPECT_EQ(a.parameters[i].value, b.parameters[i].value) << a.name;
    EXPECT_EQ(a.parameters[i].stderr_, b.parameters[i].stderr_) << a.name;
    EXPECT_EQ(a.parameters[i].profileLow, b.parameters[i].profileLow) << a.name;
    EXPECT_EQ(a.parameters[i].profileHigh, b.parameters[i].profileHigh) << a.name;
  }
}

void expectSameDiagnosis(const DiagnosisResult& a, const DiagnosisResult& b) {
  ASSERT_EQ(a.candidates.size(), b.candidates.size());
  for (size_t i = 0; i < a.candidates.size(); ++i) expectSameFit(a.candidates[i], b.candidates[i]);
  ASSERT_EQ(a.causes.size(), b.causes.size());
  for (size_t i = 0; i < a.causes.size(); ++i) expectSameFit(a.causes[i].fit, b.causes[i].fit);
  expectSameFit(a.extended, b.extended);
  expectSameFit(a.baseline, b.baseline);
  EXPECT_EQ(a.predictedAfter, b.predictedAfter);
  ASSERT_EQ(a.robustness.size(), b.robustness.size());
  for (size_t k = 0; k < a.robustness.size(); ++k) {
    EXPECT_EQ(a.robustness[k].causes, b.robustness[k].causes);
    EXPECT_EQ(a.robustness[k].verdict, b.robustness[k].verdict);
    ASSERT_EQ(a.robustness[k].fits.size(), b.robustness[k].fits.size());
    for (size_t i = 0; i < a.robustness[k].fits.size(); ++i) expectSameFit(a.robustness[k].fits[i], b.robustness[k].fits[i]);
  }
}

TEST(SweepCache, DiagnosisWithReuseOnAndOffOneAndTwoThreadsIsTheSame) {
  const fs::path dir = makeTempDir("diagnosis");
  double runSpeed = 0;
  const MeasuredData data = loadMeasuredData(writeData(dir, 4711, runSpeed));
  fs::remove_all(dir);
  DiagnosisOptions opt;
  opt.candidates = {"steer_damper", "parameter:geometry.trail_m"};
  opt.maxCauses = 1;
  opt.folds = 3;
  opt.robustness = true;  // reruns with the eigenvalues and the run left out
  opt.candidateTableCv = false;
  opt.threads = 1;
  opt.reuseLinearModels = false;
  const DiagnosisResult off = runDiagnosis(kBenchmark, data, opt);
  opt.reuseLinearModels = true;
  opt.sweepCache = std::make_shared<SweepCache>();
  const DiagnosisResult on = runDiagnosis(kBenchmark, data, opt);
  const SweepCache::Counters c = opt.sweepCache->getCounters();
  opt.threads = 2;
  opt.sweepCache = nullptr;
  const DiagnosisResult two = runDiagnosis(kBenchmark, data, opt);
  ASSERT_EQ(off.causes.size(), 1u);  // the hidden damper is found (the comparison is not of empty results)
  EXPECT_EQ(off.causes[0].fit.name, "steer_damper");
  EXPECT_EQ(off.robustness.size(), 2u);
  expectSameDiagnosis(off, on);
  expectSameDiagnosis(off, two);
  EXPECT_GT(c.hits, c.lookups / 10);  // the reuse does save work here
}

}  // namespace
}  // namespace motostab::diagnosis
