// Mode label rules on small linear models built here, whose motion is known by construction
// (docs/methods.md, "Mode labels"): a roll divergence beside a stiff tyre that the roll does not
// deflect, and a tight turn's pair of real roll roots. Parameters are drawn at random (seeded).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>

#include "analysis/modes.h"
#include "core/portable_random.h"

namespace motostab::analysis {

using core::PortableRandom;
using vehicle::StateRole;

namespace {

// x = [q; u] for mechanical degrees of freedom with the given roles, M q'' + C q' + K q = 0.
LinearModel makeMechanicalModel(const std::vector<StateRole>& roles, const Eigen::MatrixXd& M, const Eigen::MatrixXd& C,
                                const Eigen::MatrixXd& K) {
  const int n = static_cast<int>(roles.size());
  LinearModel lin;
  lin.speed = 5;
  lin.headingFrame = true;
  for (int i = 0; i < n; ++i) lin.states.push_back({"q" + std::to_string(i), {Slot::Q, i}, roles[i]});
  for (int i = 0; i < n; ++i) lin.states.push_back({"u" + std::to_string(i), {Slot::U, i}, roles[i]});
  lin.A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  lin.A.topRightCorner(n, n).setIdentity();
  lin.A.bottomLeftCorner(n, n) = -M.inverse() * K;
  lin.A.bottomRightCorner(n, n) = -M.inverse() * C;
  lin.massMatrix = M;
  Eigen::EigenSolver<Eigen::MatrixXd> es(lin.A);
  lin.eigenvalues = es.eigenvalues();
  lin.eigenvectors = es.eigenvectors();
  lin.eigenvectors.colwise().normalize();
  return lin;
}

int findRealRoot(const LinearModel& lin, bool positive) {
  for (int k = 0; k < lin.eigenvalues.size(); ++k)
    if (std::abs(lin.eigenvalues[k].imag()) < 1e-9 && (lin.eigenvalues[k].real() > 0) == positive) return k;
  return -1;
}

}  // namespace

// A rider-and-frame roll inertia I on a tyre of radial stiffness k whose deflection is h + a phi (the
// contact point of a leaning wheel rises as it rolls: a, m), with gravity's negative roll stiffness
// m g l. Potential energy V = k (h + a phi)^2 / 2 - m g l phi^2 / 2. The slow roots +-sqrt(...) move
// height and roll together with the tyre hardly deflected (checked on the eigenvector): the vehicle
// falling over, or recovering, in roll. The tyre holds almost none of their energy, so they are lateral
// roots, not bounce, and the diverging one is a capsize; the stiff root (the tyre deflecting) is the bounce.
TEST(ModeLabelRules, RollDivergenceThatLeavesAStiffTyreUndeflectedIsCapsize) {
  PortableRandom g(28071);
  for (int draw = 0; draw < 20; ++draw) {
    const double I = g.drawUniform(20, 60), m = g.drawUniform(150, 300), l = g.drawUniform(0.4, 0.7);
    const double a = g.drawUniform(0.1, 0.35), k = g.drawUniform(1e5, 1e7), c = g.drawUniform(200, 2000);
    const double gl = 9.81 * l;
    Eigen::Matrix2d M, C, K;
    M << I, 0, 0, m;
    C << 0, 0, 0, c;  // the tyre's damping acts on the height alone
    K << k * a * a - m * gl, k * a, k * a, k;
    const LinearModel lin = makeMechanicalModel({StateRole::Roll, StateRole::Height}, M, C, K);
    const std::vector<ModeLabel> labels = labelModes(lin);
    for (bool positive : {true, false}) {
      const int r = findRealRoot(lin, positive);
      ASSERT_GE(r, 0) << "draw " << draw;
      const std::complex<double> phi = lin.eigenvectors(0, r), h = lin.eigenvectors(1, r);
      // Independent of the labelling: the tyre deflection is small against the roll's lift a phi.
      ASSERT_LT(std::abs(h + a * phi), 0.05 * a * std::abs(phi)) << "draw " << draw;
      const ModeContent content = calcModeContent(lin, r);
      EXPECT_LT(content.get(StateRole::Height), 0.5 * content.get(StateRole::Roll)) << "draw " << draw << " root " << lin.eigenvalues[r];
      // The diverging root is the capsize (the slower of the two, or the diverging second one); the
      // decaying one is lateral motion, never the tyre's bounce.
      if (positive)
        EXPECT_EQ(labels[r], ModeLabel::Capsize) << "draw " << draw << " root " << lin.eigenvalues[r] << " is " << toString(labels[r]);
      else
        EXPECT_TRUE(labels[r] == ModeLabel::Capsize || labels[r] == ModeLabel::Other)
            << "draw " << draw << " root " << lin.eigenvalues[r] << " is " << toString(labels[r]);
    }
    for (int r = 0; r < lin.eigenvalues.size(); ++r) {
      if (std::abs(lin.eigenvalues[r].imag()) > 1e-9) {
        EXPECT_EQ(labels[r], ModeLabel::Bounce) << "draw " << draw << " root " << lin.eigenvalues[r];
      }
    }
  }
}

// Roll with damping c and stiffness k drawn so that its roots are r1 > 0 and -r2, r2 < r1 (as a bicycle's
// in a tight turn at walking pace: +3.7 and -2.7 1/s), beside a steer oscillation. Both real roots are
// pure roll by construction: the faster one a divergence (falling over), the slower one decaying. The
// slower is the capsize by the slowest-root rule; the diverging one is a capsize too, never `other`.
TEST(ModeLabelRules, FasterDivergingRollRootIsCapsizeToo) {
  PortableRandom g(1971028);
  for (int draw = 0; draw < 20; ++draw) {
    const double r1 = g.drawUniform(1, 5), r2 = r1 * g.drawUniform(0.2, 0.9);
    const double I = g.drawUniform(5, 60), J = g.drawUniform(0.05, 0.5);
    const double ws = g.drawUniform(20, 60), zs = g.drawUniform(0.05, 0.5);  // steer: 1/s, damping ratio
    Eigen::Matrix2d M, C, K;
    M << I, 0, 0, J;
    C << -I * (r1 - r2), 0, 0, 2 * zs * ws * J;  // roll: (s - r1)(s + r2) = s^2 - (r1 - r2) s - r1 r2
    K << -I * r1 * r2, 0, 0, J * ws * ws;
    const LinearModel lin = makeMechanicalModel({StateRole::Roll, StateRole::Steer}, M, C, K);
    const std::vector<ModeLabel> labels = labelModes(lin);
    const int up = findRealRoot(lin, true), down = findRealRoot(lin, false);
    ASSERT_GE(up, 0);
    ASSERT_GE(down, 0);
    ASSERT_NEAR(lin.eigenvalues[up].real(), r1, 1e-9 * r1);
    EXPECT_EQ(labels[down], ModeLabel::Capsize) << "draw " << draw << ": " << lin.eigenvalues[down];
    EXPECT_EQ(labels[up], ModeLabel::Capsize) << "draw " << draw << ": " << lin.eigenvalues[up] << " is " << toString(labels[up]);
  }
}

}  // namespace motostab::analysis
