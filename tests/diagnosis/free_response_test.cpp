// A free response recorded while the bicycle slows down: the prediction with the speed varying along
// the trace (piecewise-frozen models, A quadratic in speed) reproduces an independent Runge-Kutta
// integration with the speed falling, where the window's mean speed does not.
#include "diagnosis/free_response.h"

#include <gtest/gtest.h>

#include <cmath>

#include "diagnosis/prediction.h"
#include "core/portable_random.h"
#include "io/number.h"
#include "scenario/parameter_overrides.h"
#include "tests/support/temp_dir.h"

#include <fstream>

namespace motostab::diagnosis {

using analysis::LinearModel;
using core::PortableRandom;
using io::InputError;
using io::formatShortest;

namespace {

const std::string kBenchmark = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

// The reference: x' = A(v(t)) x, v(t) = v0 - a t, integrated by classical Runge-Kutta (1 ms steps)
// with A(v) linear between the model's own linearisations every 0.02 m/s (their eigenvalues are the
// benchmark's, Meijaard et al. 2007 Table 2: tests/analysis/whipple_benchmark_test.cpp); roll and
// steer rate sampled every 10 ms for 3 s.
ResponseRun makeSlowingRun(const Predictor& p, double v0, double a, const Eigen::VectorXd& x0) {
  std::vector<double> grid;
  for (double v = v0 - 3 * a - 0.02; v < v0 + 0.03; v += 0.02) grid.push_back(v);
  const std::vector<LinearModel> models = p.calcLinearModels({}, grid);
  auto calcA = [&](double v) -> Eigen::MatrixXd {
    const size_t k = std::min<size_t>(static_cast<size_t>((v - grid[0]) / 0.02), grid.size() - 2);
    const double w = (v - grid[k]) / (grid[k + 1] - grid[k]);
    return (1 - w) * models[k].A + w * models[k + 1].A;
  };
  ResponseRun run;
  run.signals.resize(2);
  run.signals[0].column = "roll_rate", run.signals[0].quantity = Quantity::RollRate;
  run.signals[1].column = "steer_rate", run.signals[1].quantity = Quantity::SteerRate;
  const int roll = models[0].findState("roll_rate"), steer = models[0].findState("steer_rate");
  Eigen::VectorXd x = x0;
  const double h = 1e-3;
  auto f = [&](double t, const Eigen::VectorXd& y) -> Eigen::VectorXd { return calcA(v0 - a * t) * y; };
  for (int i = 0; i <= 300; ++i) {
    const double t = 0.01 * i;
    run.time.push_back(t);
    run.speeds.push_back(v0 - a * t);
    run.signals[0].values.push_back(x(roll));
    run.signals[1].values.push_back(x(steer));
    for (int s = 0; s < 10; ++s) {
      const double ts = t + s * h;
      const Eigen::VectorXd k1 = f(ts, x), k2 = f(ts + h / 2, x + h / 2 * k1), k3 = f(ts + h / 2, x + h / 2 * k2),
                            k4 = f(ts + h, x + h * k3);
      x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
  }
  for (double v : run.speeds) run.speed += v / run.speeds.size();
  return run;
}

double calcRmsError(const ResponseFit& fit, const ResponseRun& run) {
  double ss = 0;
  int n = 0;
  for (size_t j = 0; j < run.signals.size(); ++j)
    for (size_t i = 0; i < run.time.size(); ++i, ++n) ss += std::pow(fit.predicted[j][i] - run.signals[j].values[i], 2);
  return std::sqrt(ss / n);
}

TEST(FreeResponse, SlowingRunIsPredictedAlongItsSpeedTrace) {
  PortableRandom random(4848);
  const double v0 = random.drawUniform(5.0, 6.0), a = random.drawUniform(0.2, 0.4);  // m/s, m/s^2
  MeasuredData base;  // one row, for a predictor of the model's linearisations
  base.eigenvalues.resize(1);
  base.eigenvalues[0].speed = base.eigenvalues[0].speedMin = base.eigenvalues[0].speedMax = v0;
  const Predictor models(kBenchmark, {}, base);
  const LinearModel lin = models.calcLinearModels({}, {v0})[0];
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(lin.A.rows());
  for (const char* name : {"roll", "steer"}) x0(lin.findState(name)) = random.drawUniform(-0.02, 0.02);
  x0(lin.findState("roll_rate")) = random.drawUniform(-0.2, 0.2);
  x0(lin.findState("steer_rate")) = random.drawUniform(-0.5, 0.5);
  MeasuredData data;
  data.responses.push_back(makeSlowingRun(models, v0, a, x0));
  const ResponseRun& run = data.responses[0];
  const Prediction varying = Predictor(kBenchmark, {}, data).predict({}, {{1.0, 1.0}});
  MeasuredData frozen = data;
  frozen.responses[0].speeds.clear();  // the window's mean speed
  const Prediction mean = Predictor(kBenchmark, {}, frozen).predict({}, {{1.0, 1.0}});
  double scale = 0;
  for (double y : run.signals[1].values) scale = std::max(scale, std::abs(y));
  const double errVarying = calcRmsError(varying.responses[0], run), errMean = calcRmsError(mean.responses[0], run);
  EXPECT_LT(errVarying, 2e-3 * scale) << errVarying << " vs " << errMean;
  EXPECT_LT(errVarying, 0.1 * errMean) << errVarying << " vs " << errMean;
  EXPECT_EQ(getTraceSpeeds(run).size(), 3u);
  EXPECT_NEAR(getTraceSpeeds(run).front(), v0 - 3 * a, 1e-12);
}

// A speed record of its own (another sampling) is interpolated at the run's samples.
TEST(FreeResponse, SpeedTraceFileIsInterpolatedAtTheSamples) {
  PortableRandom random(5252);
  const auto dir = makeTempDir("speed_trace");
  std::ofstream run(dir / "run.csv"), trace(dir / "speed.csv");
  run << "t_s,roll_rate\n";
  for (int i = 0; i < 40; ++i) run << 0.01 * i << "," << random.drawUniform(-1, 1) << "\n";
  run.close();
  std::vector<double> tt, vv;
  trace << "t_s,v_mps\n";
  for (double t = -0.013; t < 0.5; t += random.drawUniform(0.02, 0.05)) {
    tt.push_back(t), vv.push_back(random.drawUniform(4.5, 5.5));
    trace << formatShortest(t) << "," << formatShortest(vv.back()) << "\n";
  }
  trace.close();
  auto write = [&](const std::string& window) {
    std::ofstream y(dir / "data.yaml");
    y << "responses:\n  - file: run.csv\n    time_column: t_s\n" << window
      << "    speed_trace: {file: speed.csv, time_column: t_s, speed_column: v_mps}\n"
      << "    signals:\n      - {column: roll_rate, quantity: roll_rate}\n";
  };
  write("");
  const MeasuredData data = loadMeasuredData((dir / "data.yaml").string());
  const ResponseRun& r = data.responses[0];
  ASSERT_EQ(r.speeds.size(), r.time.size());
  for (size_t i = 0; i < r.time.size(); ++i) {
    size_t k = 1;
    while (tt[k] < r.time[i]) ++k;
    const double expected = vv[k - 1] + (vv[k] - vv[k - 1]) * (r.time[i] - tt[k - 1]) / (tt[k] - tt[k - 1]);
    EXPECT_NEAR(r.speeds[i], expected, 1e-12);
  }
  // A trace that ends before the run's samples do.
  std::ofstream(dir / "speed.csv") << "t_s,v_mps\n0,5\n0.2,5\n";
  try {
    loadMeasuredData((dir / "data.yaml").string());
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("speed_trace.file"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace motostab::diagnosis
