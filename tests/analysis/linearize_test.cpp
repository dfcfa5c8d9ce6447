#include <gtest/gtest.h>

#include "analysis/linearize.h"
#include "scenario/scenario.h"

namespace motostab::analysis {

using scenario::loadScenario;
using vehicle::Input;
using vehicle::VehicleModel;

namespace {

// Linearising in place perturbs the trim's own State and puts every value back: the same A as the
// copying linearisation, to the last bit, and the same state values afterwards.
TEST(Linearize, InPlaceEqualsCopyAndRestoresTheState) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml", {"swingarm.compliance=twist"}));
  TrimResult t = calcTrim(model, 20.0);
  const SimTK::Vector y0 = t.state.getY();
  const double steer0 = model.getInput(t.state, Input::SteerTorque);
  const LinearModel a = linearize(model, t);
  const LinearModel b = linearizeInPlace(model, t);
  ASSERT_EQ(a.A.rows(), b.A.rows());
  EXPECT_EQ((a.A - b.A).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((a.B - b.B).cwiseAbs().maxCoeff(), 0.0);
  for (int i = 0; i < y0.size(); ++i) EXPECT_EQ(t.state.getY()[i], y0[i]) << i;
  EXPECT_EQ(model.getInput(t.state, Input::SteerTorque), steer0);
  EXPECT_GT(b.A.cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace motostab::analysis
