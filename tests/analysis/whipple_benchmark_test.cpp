// The Whipple bicycle against Meijaard, Papadopoulos, Ruina, Schwab (2007), "Linearized dynamics
// equations for the balance and steer of a bicycle: a benchmark and review", Proc. R. Soc. A
// 463:1955-1982 (Table 2 eigenvalues and critical speeds; Appendix A M, C1, K0, K2).
#include <gtest/gtest.h>

#include <iostream>

#include <algorithm>
#include <complex>
#include <set>
#include <utility>
#include <vector>

#include "analysis/sweep.h"
#include "tests/support/benchmark_equations.h"
#include "scenario/scenario.h"

namespace motostab::analysis {

using scenario::loadScenario;
using vehicle::Input;
using vehicle::VehicleModel;

namespace {

using cd = std::complex<double>;

const std::string kScenario = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

struct Row {
  double v;
  cd weave;  // one member of the pair (or first real root at v = 0)
  cd weave2;
  double capsize, castor;
};
// Meijaard et al. (2007) Table 2.
const Row kTable2[] = {
    {0, {3.13164324790656, 0}, {5.53094371765393, 0}, -3.13164324790656, -5.53094371765393},
    {1, {3.52696170990070, 0.80774027519930}, {3.52696170990070, -0.80774027519930}, -3.13423125066578, -7.11008014637442},
    {2, {2.68234517512745, 1.68066296590675}, {2.68234517512745, -1.68066296590675}, -3.07158645641514, -8.67387984831735},
    {3, {1.70675605663975, 2.31582447384325}, {1.70675605663975, -2.31582447384325}, -2.63366137253667, -10.35101467245920},
    {4, {0.41325331521125, 3.07910818603206}, {0.41325331521125, -3.07910818603206}, -1.42944427361326, -12.15861426576450},
    {5, {-0.77534188219585, 4.46486771378823}, {-0.77534188219585, -4.46486771378823}, -0.32286642900409, -14.07838969279820},
    {6, {-1.52644486584142, 5.87673060598709}, {-1.52644486584142, -5.87673060598709}, -0.00406690076970, -16.08537123098030},
    {7, {-2.13875644258362, 7.19525913329805}, {-2.13875644258362, -7.19525913329805}, 0.10268170574766, -18.15788466125262},
    {8, {-2.69348683581097, 8.46037971396931}, {-2.69348683581097, -8.46037971396931}, 0.14327879765713, -20.27940894394569},
    {9, {-3.21675402252485, 9.69377351531791}, {-3.21675402252485, -9.69377351531791}, 0.15790184030917, -22.43788559040858},
    {10, {-3.72016840437287, 10.90681139476287}, {-3.72016840437287, -10.90681139476287}, 0.16105338653172, -24.62459635017404},
};

class WhippleBenchmark : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = new VehicleModel(loadScenario(kScenario));
    SweepOptions opt;
    opt.start = 0, opt.stop = 10, opt.step = 0.5;
    sweep_ = new SweepResult(runSweep(*model_, opt));
  }
  static void TearDownTestSuite() {
    delete sweep_;
    delete model_;
  }
  // One-to-one assignment at speed index k: the expected (label, eigenvalue) pairs are matched to
  // branches with the same label at that speed greedily by distance, each branch used once (greedy
  // with removal). Returns the branch of each expected entry (nullptr when none is left).
  static std::vector<const ModeBranch*> assignOneToOne(const std::vector<std::pair<ModeLabel, cd>>& expected, size_t k) {
    struct Pair {
      double distance;
      size_t e, b;
    };
    std::vector<Pair> pairs;
    for (size_t e = 0; e < expected.size(); ++e)
      for (size_t b = 0; b < sweep_->branches.size(); ++b)
        if (sweep_->branches[b].labels[k] == expected[e].first)
          pairs.push_back({std::abs(sweep_->branches[b].eigenvalue[k] - expected[e].second), e, b});
    std::sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) { return x.distance < y.distance; });
    std::vector<const ModeBranch*> out(expected.size(), nullptr);
    std::vector<bool> branchUsed(sweep_->branches.size(), false);
    for (const Pair& p : pairs)
      if (!out[p.e] && !branchUsed[p.b]) out[p.e] = &sweep_->branches[p.b], branchUsed[p.b] = true;
    return out;
  }
  static VehicleModel* model_;
  static SweepResult* sweep_;
};
VehicleModel* WhippleBenchmark::model_ = nullptr;
SweepResult* WhippleBenchmark::sweep_ = nullptr;

TEST_F(WhippleBenchmark, EigenvaluesMatchTable2WithLabels) {
  double worst = 0;
  for (const Row& r : kTable2) {
    const size_t k = static_cast<size_t>(std::lround(r.v / 0.5));
    ASSERT_NEAR(sweep_->speeds[k], r.v, 1e-12);
    const std::vector<std::pair<ModeLabel, cd>> expected = {
        {ModeLabel::Weave, r.weave}, {ModeLabel::Weave, r.weave2}, {ModeLabel::Capsize, r.capsize}, {ModeLabel::Castor, r.castor}};
    const auto assigned = assignOneToOne(expected, k);
    for (size_t e = 0; e < expected.size(); ++e) {
      const ModeBranch* b = assigned[e];
      ASSERT_NE(b, nullptr) << toString(expected[e].first) << " at v=" << r.v << ": no branch of that label left";
      EXPECT_LE(std::abs(b->eigenvalue[k] - expected[e].second), 1e-8)
          << toString(expected[e].first) << " at v=" << r.v << ": " << b->eigenvalue[k];
      worst = std::max(worst, std::abs(b->eigenvalue[k] - expected[e].second));
    }
    // The fifth eigenvalue is the neutral forward-speed mode.
    int neutral = 0;
    for (const auto& b : sweep_->branches)
      if (b.labels[k] == ModeLabel::Neutral) {
        ++neutral;
        EXPECT_LT(std::abs(b.eigenvalue[k]), 1e-9);
      }
    EXPECT_EQ(neutral, 1);
  }
  std::cout << "Whipple sweep (second-order differences): worst eigenvalue error against Table 2 " << worst << "\n";
}

TEST_F(WhippleBenchmark, CriticalSpeedsMatchTable2) {
  double weave = NAN, capsize = NAN;
  for (const auto& c : sweep_->criticalSpeeds) {
    if (c.mode == analysis::ModeLabel::Weave) {
      weave = c.speed;
      EXPECT_TRUE(c.stabilising);
    }
    if (c.mode == analysis::ModeLabel::Capsize) {
      capsize = c.speed;
      EXPECT_FALSE(c.stabilising);
    }
  }
  EXPECT_NEAR(weave, 4.29238253634111, 1e-8);
  EXPECT_NEAR(capsize, 6.02426201538837, 1e-8);
  EXPECT_EQ(sweep_->criticalSpeeds.size(), 2u);
}

TEST_F(WhippleBenchmark, CyclicColumnsAreZero) {
  // A step of 1e-3 (no tyre to lift off the ground here): the columns' round-off, eps |ydot| / step, is
  // then 100 times below the default step's (1.3e-9).
  LinearizeOptions lo;
  lo.step = 1e-3;
  for (double v : {0.0, 2.5, 6.0, 9.5}) {
    const LinearModel lin = linearize(*model_, calcTrim(*model_, v), lo);
    std::set<std::string> removed;
    for (const auto& [name, col] : lin.removedColumns) {
      removed.insert(name);
      EXPECT_LT(col.lpNorm<Eigen::Infinity>(), 1e-9) << name << " at v=" << lin.speed;
    }
    for (const char* n : {"x", "y", "rear_wheel_angle", "front_wheel_angle"}) EXPECT_TRUE(removed.count(n)) << n;
  }
}

// M q'' + v C1 q' + (g K0 + v^2 K2) q = f with q = [phi, delta], the published matrices of
// tests/support/benchmark_equations.h (benchmark: steer positive right,
// ours positive left, so S = diag(1, -1) maps one onto the other).
TEST_F(WhippleBenchmark, LinearEquationsReproduceMC1K0K2) {
  const testing::Benchmark ref = testing::getTable1Matrices();
  const Eigen::Matrix2d &Mref = ref.M, &C1ref = ref.C1, &K0ref = ref.K0, &K2ref = ref.K2;
  const Eigen::Matrix2d S = Eigen::Vector2d(1, -1).asDiagonal();
  const double g = 9.81;
  auto blocks = [&](double v, Eigen::Matrix2d& M, Eigen::Matrix2d& C, Eigen::Matrix2d& K) {
    const LinearModel lin = linearize(*model_, calcTrim(*model_, v));
    const int q[2] = {lin.findState("roll"), lin.findState("steer")};
    const int u[2] = {lin.findState("roll_rate"), lin.findState("steer_rate")};
    Eigen::Matrix2d Binv, Aq, Au;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        Binv(i, j) = lin.B(u[i], j == 0 ? static_cast<int>(Input::RollTorque) : static_cast<int>(Input::SteerTorque));
        Aq(i, j) = lin.A(u[i], q[j]);
        Au(i, j) = lin.A(u[i], u[j]);
      }
    const Eigen::Matrix2d Mm = Binv.inverse();
    M = S * Mm * S;
    K = S * (-Mm * Aq) * S;
    C = S * (-Mm * Au) * S;
  };
  auto relErr = [](const Eigen::Matrix2d& a, const Eigen::Matrix2d& ref) {
    return (a - ref).lpNorm<Eigen::Infinity>() / ref.lpNorm<Eigen::Infinity>();
  };
  Eigen::Matrix2d M0, C0, K0, M5, C5, K5;
  blocks(0.0, M0, C0, K0);
  blocks(5.0, M5, C5, K5);
  EXPECT_LT(relErr(M0, Mref), 1e-8) << M0;
  EXPECT_LT(relErr(M5, Mref), 1e-8) << M5;
  EXPECT_LT(relErr(K0 / g, K0ref), 1e-8) << K0 / g;
  EXPECT_LT(relErr(C5 / 5.0, C1ref), 1e-8) << C5 / 5.0;
  EXPECT_LT(relErr((K5 - K0) / 25.0, K2ref), 1e-8) << (K5 - K0) / 25.0;
  EXPECT_LT(C0.lpNorm<Eigen::Infinity>(), 1e-9);
}

}  // namespace
}  // namespace motostab::analysis
