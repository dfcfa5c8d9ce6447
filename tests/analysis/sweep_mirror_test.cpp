// One evaluation per lateral column group on laterally symmetric vehicles (checkMirrorSymmetry):
// f(y0 - h d) is the mirror image of f(y0 + h d) at a symmetric trim, so the central difference
// needs only the first. References: the same sweep with central differences throughout
// (mirrorLateralColumns = false), which the grouping and Whipple tests validate, and a model made
// asymmetric at second order only, which the check must refuse.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <sstream>

#include "core/portable_random.h"
#include "analysis/sweep.h"
#include "plugins/builtin.h"
#include "tests/uncertainty/test_support.h"

namespace motostab::analysis {

using core::PortableRandom;
using plugins::BuildContext;
using plugins::PluginRegistry;
using plugins::makeBuiltinRegistry;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::ModelExtension;
using vehicle::VehicleModel;

namespace {

const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

// The four model extensions (steer damper, fork compliance, rider lean, tyre contact) with stiffnesses and
// dampings drawn at random (seeded).
std::vector<std::string> drawExtensions(PortableRandom& g) {
  auto draw = [&](double a, double b) {
    std::ostringstream s;
    s.precision(17);
    s << g.drawUniform(a, b);
    return s.str();
  };
  return {"steer_damper={damping_Nms_per_rad: " + draw(2, 10) + "}",
          "fork_compliance={stiffness_Nm_per_rad: " + draw(2e4, 8e4) + ", damping_Nms_per_rad: " + draw(5, 40) +
              ", torsion: {stiffness_Nm_per_rad: " + draw(3e4, 9e4) + ", damping_Nms_per_rad: " + draw(2, 20) + "}}",
          "rider_lean={hinge_height_m: 0.75, mass_kg: " + draw(30, 50) +
              ", com_m: [0.45, 0, 1.05], inertia_kgm2: {xx: 2.0, yy: 2.1, zz: 0.7, xy: 0, xz: 0, yz: 0}, "
              "stiffness_Nm_per_rad: " + draw(1000, 4000) + ", damping_Nms_per_rad: " + draw(30, 90) + "}",
          "contact.preset=bicycle"};
}

SweepResult sweep(const VehicleModel& model, bool mirror) {
  SweepOptions opt;
  opt.start = 0, opt.stop = 40, opt.step = 1;
  opt.mirrorLateralColumns = mirror;
  return runSweep(model, opt);
}

// Largest |lambda_a - nearest lambda_b| / max(1, |lambda_a|) over every speed.
double compareEigenvalues(const SweepResult& a, const SweepResult& b) {
  double worst = 0;
  for (size_t k = 0; k < a.models.size(); ++k)
    for (int i = 0; i < a.models[k].eigenvalues.size(); ++i) {
      double best = INFINITY;
      for (int j = 0; j < b.models[k].eigenvalues.size(); ++j)
        best = std::min(best, std::abs(a.models[k].eigenvalues[i] - b.models[k].eigenvalues[j]));
      worst = std::max(worst, best / std::max(1.0, std::abs(a.models[k].eigenvalues[i])));
    }
  return worst;
}

// The grouping of a sweep's linearisations at speeds i and j, and the trim at j to check it on.
ColumnGrouping groupAt(const VehicleModel& model, const SweepResult& s, size_t i, size_t j, TrimResult& trim) {
  trim = restoreTrim(model, s.trims[j]);
  return calcColumnGrouping({&s.models[i], &s.models[j]});
}

// Every model's eigensystem against a dense solve of its A (Eigen's EigenSolver on the whole matrix):
// the same eigenvalues, and each returned pair satisfies A v = lambda v with |v| = 1.
void expectEigensystemsOfA(const SweepResult& s) {
  double worstValue = 0, worstResidual = 0;
  for (const LinearModel& m : s.models) {
    Eigen::EigenSolver<Eigen::MatrixXd> dense(m.A);
    LinearModel reference = m;
    reference.eigenvalues = dense.eigenvalues();
    SweepResult a, b;
    a.models = {m}, b.models = {reference};
    worstValue = std::max(worstValue, compareEigenvalues(a, b));
    const double scale = std::max(1.0, m.A.lpNorm<Eigen::Infinity>());
    for (int k = 0; k < m.eigenvalues.size(); ++k) {
      EXPECT_NEAR(m.eigenvectors.col(k).norm(), 1.0, 1e-12);
      worstResidual = std::max(worstResidual, (m.A * m.eigenvectors.col(k) - m.eigenvalues[k] * m.eigenvectors.col(k)).norm() / scale);
    }
  }
  // Both solves are backward stable: eigenvalues agree to about eps |A| (|A| up to 1e6 1/s^2 with
  // the stiff fork), i.e. 1e-10 absolute.
  EXPECT_LT(worstValue, 1e-9);
  EXPECT_LT(worstResidual, 1e-12);
  std::cout << "eigenvalues against a dense solve " << worstValue << ", worst |A v - lambda v| / |A| " << worstResidual << "\n";
}

TEST(MirrorSymmetry, SymmetricVehicleWithExtensionsMatchesCentralDifferences) {
  PortableRandom g(20261124);
  const VehicleModel model(loadScenario(kEnduro, drawExtensions(g)));
  const SweepResult mirrored = sweep(model, true), central = sweep(model, false);
  // Mirrored sweeps have exact zeros between the lateral and in-plane blocks of A, which are then
  // eigen-solved apart.
  int decoupled = 0;
  for (int i = 0; i < mirrored.models[20].A.rows(); ++i)
    for (int j = 0; j < mirrored.models[20].A.cols(); ++j) decoupled += mirrored.models[20].A(i, j) == 0;
  EXPECT_GE(decoupled, 2 * 15 * 7);
  expectEigensystemsOfA(mirrored);
  expectEigensystemsOfA(central);
  TrimResult trim;
  ColumnGrouping grouping = groupAt(model, central, 10, 11, trim);
  // The lateral block: every state the roll row or column reaches (22 states, 15 lateral).
  ASSERT_EQ(grouping.mirror.size(), 22u);
  EXPECT_EQ(std::count(grouping.mirror.begin(), grouping.mirror.end(), -1), 15);
  for (const char* lateral : {"roll", "steer", "rider_lean", "fork_bending", "fork_torsion", "vy", "rear_tyre_lagged_slip"})
    EXPECT_EQ(grouping.mirror[std::find(grouping.states.begin(), grouping.states.end(), lateral) - grouping.states.begin()], -1) << lateral;
  for (const char* inPlane : {"pitch", "height", "vx", "vz"})
    EXPECT_EQ(grouping.mirror[std::find(grouping.states.begin(), grouping.states.end(), inPlane) - grouping.states.begin()], 1) << inPlane;
  double defect = 0;
  SweepOptions opt;
  EXPECT_TRUE(checkMirrorSymmetry(model, trim, opt.linearize, grouping, 1e-8, &defect));
  EXPECT_LT(defect, 1e-12);
  EXPECT_TRUE(grouping.useMirror);
  // Both sweeps are second-order central differences: they agree to the difference noise.
  const double worst = compareEigenvalues(mirrored, central);
  std::cout << "worst relative eigenvalue difference, mirrored against central: " << worst << "\n";
  EXPECT_LT(worst, 1e-9);
  ASSERT_EQ(mirrored.criticalSpeeds.size(), central.criticalSpeeds.size());
  for (size_t c = 0; c < central.criticalSpeeds.size(); ++c)
    EXPECT_NEAR(mirrored.criticalSpeeds[c].speed, central.criticalSpeeds[c].speed, 1e-8);
}

// A steer torque c x^2, x a rate or auxiliary state in a lateral group of its own, is even in x, so
// not mirror-symmetric. It vanishes with its slope at the upright trim: trim, A and the pattern are
// unchanged, but f(y0 - h e_x) differs from S f(y0 + h e_x) by 2 c h^2 (M^-1)_ss in the steer-rate
// row: a defect of c h (M^-1)_ss in A's units, above the tolerance for the c drawn.
class EvenSteerTorque : public SimTK::Force::Custom::Implementation {
 public:
  EvenSteerTorque(const SimTK::MobilizedBody& front, StateEntry x, double c) : front_(front), x_(x), c_(c) {}
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector& mobilityForces) const override {
    const double x = x_.slot == Slot::U ? s.getU()[x_.index] : s.getZ()[x_.index];
    front_.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), c_ * x * x, mobilityForces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
  bool dependsOnlyOnPositions() const override { return false; }

 private:
  SimTK::MobilizedBody front_;
  StateEntry x_;
  double c_;
};

// The first rate or auxiliary state in a one-evaluation (lateral) group of the symmetric sweep `s`.
LinearState findMirroredState(const VehicleModel& model, const SweepResult& s) {
  TrimResult trim;
  ColumnGrouping grouping = groupAt(model, s, 20, 21, trim);
  SweepOptions opt;
  EXPECT_TRUE(checkMirrorSymmetry(model, trim, opt.linearize, grouping));
  for (const auto& group : grouping.groups) {
    bool lateral = true;
    for (int j : group) lateral = lateral && grouping.mirror[j] == -1;
    for (int j : group)
      if (lateral && grouping.slots[j] != Slot::Q) return s.models[21].states[s.models[21].findState(grouping.states[j])];
  }
  ADD_FAILURE() << "no lateral rate or auxiliary state evaluated once";
  return {};
}

TEST(MirrorSymmetry, SecondOrderAsymmetryFailsTheCheck) {
  PortableRandom g(7);
  const double c = g.drawUniform(2e3, 1e4);  // N m per (unit of x)^2
  const Scenario scenario = loadScenario(kEnduro);
  const VehicleModel symmetric(scenario);
  const SweepResult plain = sweep(symmetric, false);
  const LinearState x = findMirroredState(symmetric, plain);
  std::cout << "even steer torque in " << x.name << "\n";
  PluginRegistry registry = makeBuiltinRegistry();
  ModelExtension even = [c, x](BuildContext& ctx, const VehicleModel& m) {
    SimTK::Force::Custom(ctx.forces, new EvenSteerTorque(m.getFrontFrame(), x.entry, c));
    return std::vector<vehicle::AuxiliaryState>{};
  };
  const VehicleModel asymmetric(scenario, registry, {even});
  const SweepResult central = sweep(asymmetric, false);
  TrimResult trim;
  ColumnGrouping grouping = groupAt(asymmetric, central, 20, 21, trim);
  ASSERT_FALSE(grouping.mirror.empty()) << "the linearisation is as symmetric as the plain vehicle's";
  SweepOptions opt;
  double defect = 0;
  EXPECT_FALSE(checkMirrorSymmetry(asymmetric, trim, opt.linearize, grouping, 1e-8, &defect));
  // The steer-rate row's defect from the mass matrix at the trim (Simbody's M, inverted here).
  SimTK::Matrix M;
  asymmetric.getSystem().realize(trim.state, SimTK::Stage::Position);
  asymmetric.getMatter().calcM(trim.state, M);
  Eigen::MatrixXd Me(M.nrow(), M.ncol());
  for (int i = 0; i < M.nrow(); ++i)
    for (int j = 0; j < M.ncol(); ++j) Me(i, j) = M(i, j);
  const int steer = asymmetric.getIndices().steer;
  const double h = opt.linearize.step, minvSS = Me.inverse()(steer, steer);
  const int row = static_cast<int>(std::find(grouping.states.begin(), grouping.states.end(), "steer_rate") - grouping.states.begin());
  const double expected = c * h * minvSS / grouping.rowScale[row];
  EXPECT_GT(expected, 1e-8);
  EXPECT_GE(defect, expected * (1 - 1e-3)) << "expected at least the steer-rate row's " << expected;
  EXPECT_FALSE(grouping.useMirror);
  // The sweep refuses the mirror too: it equals the central one to the bit.
  EXPECT_EQ(compareEigenvalues(sweep(asymmetric, true), central), 0.0);
}

TEST(MirrorSymmetry, NotProposedForATiltedAxisNorUsedWithConstraints) {
  const VehicleModel tilted(loadScenario(kEnduro, {"swingarm.compliance=torsion",
                                                   "swingarm.torsion={point_m: [0.56, 0, 0.014], direction: [1, 0.2, 0], "
                                                   "stiffness_Nm_per_rad: 55200, damping_Nms_per_rad: 0.49}"}));
  SweepOptions opt;
  opt.start = 5, opt.stop = 7, opt.step = 1;
  const SweepResult s = runSweep(tilted, opt);
  TrimResult trim;
  EXPECT_TRUE(groupAt(tilted, s, 1, 2, trim).mirror.empty()) << "lateral and in-plane states are coupled";
  // The Whipple bicycle (rolling without slip): its pattern splits, but its tangent space mixes the
  // dependent rates, so the check does not apply.
  const VehicleModel whipple(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml"));
  const SweepResult w = runSweep(whipple, opt);
  ColumnGrouping grouping = groupAt(whipple, w, 1, 2, trim);
  double defect = 0;
  EXPECT_FALSE(checkMirrorSymmetry(whipple, trim, opt.linearize, grouping, 1e-8, &defect));
  EXPECT_TRUE(std::isinf(defect));
}

}  // namespace
}  // namespace motostab::analysis

namespace motostab::analysis {
namespace {

// Every bundled vehicle without constraints, mirrored or not: the same eigenvalues to the difference
// noise and the same critical speeds (the asymmetric ones keep central differences).
TEST(MirrorSymmetry, BundledScenariosMatchCentralDifferences) {
  const std::string dir = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/";
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"supersport.yaml", {"swingarm.compliance=rigid"}},   {"supersport.yaml", {"swingarm.compliance=bending"}},
      {"supersport.yaml", {"swingarm.compliance=torsion"}}, {"supersport.yaml", {"swingarm.compliance=bending+torsion"}},
      {"enduro.yaml", {"swingarm.compliance=twist"}},       {"whipple-benchmark-tyres.yaml", {}},
      {"browser-jason-rider.yaml", {"contact={model: relaxation_linear, preset: bicycle}"}}};
  for (const auto& [file, sets] : cases) {
    const VehicleModel model(loadScenario(dir + file, sets));
    SweepOptions opt;
    opt.start = 0, opt.stop = file == "supersport.yaml" ? 50 : file == "enduro.yaml" ? 40 : 10;
    opt.step = opt.stop / 40;
    const SweepResult mirrored = runSweep(model, opt);
    opt.mirrorLateralColumns = false;
    const SweepResult central = runSweep(model, opt);
    const double worst = compareEigenvalues(mirrored, central);
    std::cout << file << (sets.empty() ? "" : " " + sets.front()) << ": " << worst << "\n";
    EXPECT_LT(worst, 1e-9) << file;
    ASSERT_EQ(mirrored.criticalSpeeds.size(), central.criticalSpeeds.size()) << file;
    for (size_t c = 0; c < central.criticalSpeeds.size(); ++c)
      EXPECT_NEAR(mirrored.criticalSpeeds[c].speed, central.criticalSpeeds[c].speed, 1e-8) << file;
  }
}

}  // namespace
}  // namespace motostab::analysis
