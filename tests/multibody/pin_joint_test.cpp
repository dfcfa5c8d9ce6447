// addPinAtDesignPose: at q = 0 the child sits at its design pose; at any q the pin's point and axis stay
// where the design pose puts them in ground, and the child has turned by q about that axis (right hand).
// The expected poses are composed here by hand (Rodrigues' rotation formula), not by the helper.
#include <gtest/gtest.h>

#include <cmath>

#include "Simbody.h"
#include "core/portable_random.h"
#include "multibody/pin_joint.h"

namespace {

using motostab::core::PortableRandom;
using motostab::multibody::addPinAtDesignPose;

SimTK::Vec3 drawVec3(PortableRandom& rng, double a, double b) {
  return {rng.drawUniform(a, b), rng.drawUniform(a, b), rng.drawUniform(a, b)};
}

// Rotation by `angle` (rad) about the unit axis `n`: R = I + sin(angle) K + (1 - cos(angle)) K^2, K = [n]x.
SimTK::Mat33 calcRodrigues(const SimTK::Vec3& n, double angle) {
  const SimTK::Mat33 k(0, -n[2], n[1], n[2], 0, -n[0], -n[1], n[0], 0);
  const SimTK::Mat33 identity(1, 0, 0, 0, 1, 0, 0, 0, 1);
  return identity + std::sin(angle) * k + (1 - std::cos(angle)) * k * k;
}

SimTK::Mat33 toMat(const SimTK::Rotation& r) { return r.asMat33(); }

void expectNear(const SimTK::Vec3& a, const SimTK::Vec3& b, double tol, const char* what) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << what << "[" << i << "]";
}

void expectNear(const SimTK::Mat33& a, const SimTK::Mat33& b, double tol, const char* what) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(a(i, j), b(i, j), tol) << what << "(" << i << "," << j << ")";
}

TEST(PinJoint, AxisAndPointInGroundFollowTheDesignPose) {
  PortableRandom rng(20261125);
  for (int trial = 0; trial < 5; ++trial) {
    // A parent body welded to ground at X_GP, a child pinned to it at the design pose X_PC0, about the
    // axis n_C through the point p_C (both in the child frame).
    const SimTK::Rotation R_GP(rng.drawUniform(-M_PI, M_PI), SimTK::UnitVec3(drawVec3(rng, -1, 1)));
    const SimTK::Transform X_GP(R_GP, drawVec3(rng, -2, 2));
    const SimTK::Rotation R_PC0(rng.drawUniform(-M_PI, M_PI), SimTK::UnitVec3(drawVec3(rng, -1, 1)));
    const SimTK::Transform X_PC0(R_PC0, drawVec3(rng, -1, 1));
    const SimTK::Vec3 p_C = drawVec3(rng, -0.5, 0.5);
    const SimTK::Vec3 n_C = SimTK::UnitVec3(drawVec3(rng, -1, 1)).asVec3();
    const double q = rng.drawUniform(-3, 3);

    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter(system);
    const SimTK::Body::Rigid body(SimTK::MassProperties(1, SimTK::Vec3(0), SimTK::UnitInertia(1)));
    SimTK::MobilizedBody::Weld parent(matter.Ground(), X_GP, body, SimTK::Transform());
    SimTK::MobilizedBody::Pin pin = addPinAtDesignPose(parent, X_PC0, body, p_C, n_C);
    SimTK::State state = system.realizeTopology();

    // q = 0: the design pose.
    pin.setQ(state, 0);
    system.realize(state, SimTK::Stage::Position);
    const SimTK::Transform& X_GC0 = pin.getBodyTransform(state);
    const SimTK::Mat33 R_GC0 = toMat(R_GP) * toMat(R_PC0);
    const SimTK::Vec3 p_GC0 = X_GP.p() + toMat(R_GP) * X_PC0.p();
    expectNear(toMat(X_GC0.R()), R_GC0, 1e-12, "R_GC at q = 0");
    expectNear(X_GC0.p(), p_GC0, 1e-12, "p_GC at q = 0");

    // Pin location and axis in ground at the design pose.
    const SimTK::Vec3 p_GPin = p_GC0 + R_GC0 * p_C;
    const SimTK::Vec3 n_G = R_GC0 * n_C;

    // At q: the pin point and axis have not moved, and the child has turned by q about n_G.
    pin.setQ(state, q);
    system.realize(state, SimTK::Stage::Position);
    const SimTK::Transform& X_GC = pin.getBodyTransform(state);
    expectNear(X_GC.p() + toMat(X_GC.R()) * p_C, p_GPin, 1e-12, "pin point in ground");
    expectNear(toMat(X_GC.R()) * n_C, n_G, 1e-12, "pin axis in ground");
    expectNear(toMat(X_GC.R()), calcRodrigues(n_G, q) * R_GC0, 1e-12, "R_GC at q");
    // A point off the axis moves on a circle about it: its turn about n_G is q.
    const SimTK::Vec3 p_Off = p_C + drawVec3(rng, -0.3, 0.3);
    const SimTK::Vec3 r0 = p_GC0 + R_GC0 * p_Off - p_GPin, r1 = X_GC.p() + toMat(X_GC.R()) * p_Off - p_GPin;
    const SimTK::Vec3 a0 = r0 - SimTK::dot(r0, n_G) * n_G, a1 = r1 - SimTK::dot(r1, n_G) * n_G;
    EXPECT_NEAR(std::atan2(SimTK::dot(n_G, SimTK::cross(a0, a1)), SimTK::dot(a0, a1)), q, 1e-10);  // |q| < pi
  }
}

}  // namespace
