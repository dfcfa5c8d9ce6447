// Nonlinear check of the assembled Whipple bicycle: Basu-Mandal, Chatterjee, Papadopoulos (2007),
// "Hands-free circular motions of a benchmark bicycle", Proc. R. Soc. A 463:1983-2003, Table 1:
// a general leaned, steered, pitched state of the benchmark bicycle and its accelerations.
#include <gtest/gtest.h>

#include "analysis/state_function.h"

namespace motostab::vehicle {

using analysis::StateFunction;
using scenario::loadScenario;

namespace {

// Their coordinates: rear-wheel centre (x, y, z) with z up; heading theta; lean psi from the
// horizontal (pi/2 upright); pitch phi (pi at the design pose); steer psi_f; wheel angles beta.
// Ours (vehicle/vehicle_model.h) relate by a half turn of the ground frame about z (their bicycle
// heads along -x): x = -x_BM, y = -y_BM, height = z, yaw = theta, roll = pi/2 - psi,
// pitch = phi - pi, steer = psi_f, wheel angles equal. The test first checks that this mapping
// puts their state on our constraint manifold, then compares accelerations.
TEST(WhippleNonlinear, AccelerationsMatchBasuMandalTable1) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml"));
  const StateFunction fn(model);
  const CoordinateIndices& ix = model.getIndices();
  SimTK::State s = model.getDefaultState();
  s.updQ()[ix.height] = 0.2440472102925;
  s.updQ()[ix.roll] = M_PI / 2 - 0.9501292851472;
  s.updQ()[ix.pitch] = 3.1257073014894 - M_PI;
  s.updQ()[ix.steer] = 0.2311385135743;
  s.updU()[ix.x] = 2.8069345714545;
  s.updU()[ix.y] = 0.1480982396001;
  s.updU()[ix.height] = 0.1058778746261;
  s.updU()[ix.yaw] = 0.7830033527065;
  s.updU()[ix.roll] = -0.6068425835418;
  s.updU()[ix.pitch] = -0.0119185528069;
  s.updU()[ix.steer] = 0.4859824687093;
  s.updU()[ix.rearSpin] = 8.9129896614890;
  s.updU()[ix.frontSpin] = 8.0133620584155;

  Eigen::VectorXd err;
  fn.calcConstraintErrors(s, err);
  ASSERT_LT(err.lpNorm<Eigen::Infinity>(), 1e-11) << "mapping does not satisfy the constraints: " << err.transpose();

  model.getSystem().realize(s, SimTK::Stage::Acceleration);
  const SimTK::Vector& ud = s.getUDot();
  const double tol = 1e-10;
  EXPECT_NEAR(-ud[ix.x], -0.5041626315047, tol);
  EXPECT_NEAR(-ud[ix.y], -0.3449706619454, tol);
  EXPECT_NEAR(ud[ix.height], -1.4604528332980, tol);
  EXPECT_NEAR(ud[ix.yaw], 0.8353281706379, tol);
  EXPECT_NEAR(-ud[ix.roll], -7.8555281128244, tol);
  EXPECT_NEAR(ud[ix.pitch], 0.1205543897884, tol);
  EXPECT_NEAR(ud[ix.steer], -4.6198904039403, tol);
  EXPECT_NEAR(ud[ix.rearSpin], 1.8472554144217, tol);
  EXPECT_NEAR(ud[ix.frontSpin], 2.4548072904550, tol);
}

}  // namespace
}  // namespace motostab::vehicle
