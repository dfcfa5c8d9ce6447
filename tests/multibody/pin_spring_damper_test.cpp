// multibody/pin_spring_damper.h: the generalized force and potential energy of the one-element pin
// spring-damper, against tau = -k (q - q0) - c u and V = k (q - q0)^2 / 2 written here, at random
// (seeded) values; and its free oscillation against the damped-oscillator solution.
#include <gtest/gtest.h>

#include <cmath>

#include "core/portable_random.h"
#include "multibody/pin_spring_damper.h"

namespace motostab::multibody {

using core::PortableRandom;

namespace {

struct OnePin {
  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter{system};
  SimTK::GeneralForceSubsystem forces{system};
  SimTK::MobilizedBody::Pin pin;
  OnePin(double k, double c, double q0, double inertia)
      : pin(matter.Ground(), SimTK::Transform(),
            SimTK::Body::Rigid(SimTK::MassProperties(1.0, SimTK::Vec3(0), SimTK::Inertia(1.0, 1.0, inertia))),
            SimTK::Transform()) {
    addPinSpringDamper(forces, pin, k, c, q0);
    system.realizeTopology();
  }
};

TEST(PinSpringDamper, GeneralizedForceAndEnergyMatchTheLinearLaw) {
  PortableRandom rng(20261124);
  for (int trial = 0; trial < 20; ++trial) {
    const double k = 10 + 1e5 * rng.drawUniform(), c = 100 * rng.drawUniform(), q0 = rng.drawUniform() - 0.5;
    OnePin m(k, c, q0, 0.5 + rng.drawUniform());
    SimTK::State s = m.system.getDefaultState();
    const double q = 2 * rng.drawUniform() - 1, u = 20 * rng.drawUniform() - 10;
    m.pin.setOneQ(s, 0, q);
    m.pin.setOneU(s, 0, u);
    m.system.realize(s, SimTK::Stage::Dynamics);
    const double tau = m.system.getMobilityForces(s, SimTK::Stage::Dynamics)[0];
    EXPECT_NEAR(tau, -k * (q - q0) - c * u, 1e-12 * (k + c * 10));
    EXPECT_NEAR(m.system.calcPotentialEnergy(s), 0.5 * k * (q - q0) * (q - q0), 1e-12 * k);
  }
}

// J theta'' + c theta' + k theta = 0 from theta(0) = a, theta'(0) = 0 (underdamped): the integrated
// angle at t = 1 s against the closed form.
TEST(PinSpringDamper, FreeOscillationFollowsTheDampedOscillator) {
  const double k = 400, c = 2, J = 0.8, q0 = 0.1, a = 0.05;
  OnePin m(k, c, q0, J);
  SimTK::State s = m.system.getDefaultState();
  m.pin.setOneQ(s, 0, q0 + a);
  SimTK::RungeKuttaMersonIntegrator integ(m.system);
  integ.setAccuracy(1e-10);
  SimTK::TimeStepper ts(m.system, integ);
  ts.initialize(s);
  ts.stepTo(1.0);
  const double zeta = c / (2 * std::sqrt(k * J)), wn = std::sqrt(k / J), wd = wn * std::sqrt(1 - zeta * zeta);
  const double expected = a * std::exp(-zeta * wn) * (std::cos(wd) + zeta * wn / wd * std::sin(wd));
  EXPECT_NEAR(m.pin.getOneQ(integ.getState(), 0) - q0, expected, 1e-7);
}

}  // namespace
}  // namespace motostab::multibody
