// Magic Formula tyres offer their scaling factors of cornering stiffness, camber stiffness and trail
// (LKY, LKYC, LTR) as `parameter:` candidates of diagnose; changing one through its path changes the
// built model (the candidate's override reaches the tyre), and a relaxation_linear scenario has none.
#include <gtest/gtest.h>

#include "analysis/linearize.h"
#include "analysis/trim.h"
#include "diagnosis/candidates.h"
#include "diagnosis/diagnosis.h"
#include "scenario/parameter_paths.h"

namespace motostab::diagnosis {

using analysis::LinearModel;
using analysis::calcTrim;
using analysis::linearize;
using scenario::formatOverride;
using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

const std::string kDir = MOTOSTAB_SOURCE_DIR;

TEST(TyreScalingCandidates, MagicFormulaScalingFactorsAreParameters) {
  const std::string file = kDir + "/scenarios/supersport-mf.yaml";
  const auto all = listCandidates(makeScenarioTree(file, {"contact.rear.scaling={LKY: 1.2}"}), {});
  std::vector<std::string> names;
  for (const auto& c : all)
    if (c.name.find("parameter:contact.") == 0) names.push_back(c.name);
  const std::vector<std::string> expected{"parameter:contact.front.scaling.LKY", "parameter:contact.front.scaling.LKYC",
                                          "parameter:contact.front.scaling.LTR",  "parameter:contact.rear.scaling.LKY",
                                          "parameter:contact.rear.scaling.LKYC",  "parameter:contact.rear.scaling.LTR"};
  EXPECT_EQ(names, expected);
  for (const auto& c : all) {
    if (c.name != "parameter:contact.rear.scaling.LKY") continue;
    EXPECT_EQ(c.parameters[0].start, 1.2);  // the scenario's value
    EXPECT_NEAR(c.parameters[0].lower, 0.24, 1e-15);
    EXPECT_NEAR(c.parameters[0].priorSigma, 0.12, 1e-15);
  }
  // The path reaches the tyre: a stiffer rear tyre moves the weave eigenvalue at 20 m/s.
  auto weaveImag = [&](const std::vector<std::string>& ov) {
    const VehicleModel m(loadScenario(file, ov));
    const LinearModel lin = linearize(m, calcTrim(m, 20.0));
    double best = 0;  // the largest frequency below 4 Hz stands for weave
    for (int i = 0; i < lin.eigenvalues.size(); ++i)
      if (lin.eigenvalues[i].imag() > best && lin.eigenvalues[i].imag() < 2 * M_PI * 4) best = lin.eigenvalues[i].imag();
    return best;
  };
  EXPECT_GT(std::abs(weaveImag({formatOverride("contact.rear.scaling.LKY", 1.5)}) - weaveImag({})), 1e-3);
  // A linear-tyre scenario has no such candidate.
  for (const auto& c : listCandidates(makeScenarioTree(kDir + "/scenarios/supersport.yaml", {}), {}))
    EXPECT_EQ(c.name.find("scaling"), std::string::npos) << c.name;
}

}  // namespace
}  // namespace motostab::diagnosis
