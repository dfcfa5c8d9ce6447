// The relaxation_linear tyre in the stiff limit: with cornering, longitudinal and radial stiffness
// scaled up, relaxation length to zero and no tyre moments, the benchmark bicycle on tyres must
// approach the benchmark bicycle rolling without slip, Meijaard et al. (2007) Table 2.
#include <gtest/gtest.h>

#include <complex>

#include "tests/support/extension_sections.h"
#include "../support/catch_input_error.h"
#include "analysis/linearize.h"
#include "core/portable_random.h"
#include "io/csv.h"
#include "tyres/relaxation_linear.h"

namespace motostab::tyres {

using analysis::LinearModel;
using io::InputError;
using analysis::LinearizeOptions;
using analysis::TrimOptions;
using analysis::TrimResult;
using analysis::calcTrim;
using analysis::linearize;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::CoordinateIndices;
using vehicle::Input;
using vehicle::VehicleModel;

namespace {

const std::string kWhipple = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

std::string tyres(double scale) {
  std::ostringstream t;
  t.precision(17);
  // Radial damping near critical for a quarter of the bicycle's mass keeps the bounce modes damped.
  const double kr = 1e5 * scale, cr = 2 * std::sqrt(kr * 25.0);
  t << "{cornering_stiffness_per_rad: " << 20 * scale << ", camber_stiffness_per_rad: 1.0, self_aligning_stiffness_m_per_rad: 0,"
    << " twisting_stiffness_m_per_rad: 0, relaxation_length_m: 0, radial_stiffness_N_per_m: " << kr
    << ", radial_damping_Ns_per_m: " << cr << ", longitudinal_stiffness: " << 20 * scale << "}";
  return "contact={model: relaxation_linear, front: " + t.str() + ", rear: " + t.str() + "}";
}

// Largest distance from each Table 2 eigenvalue at v to the nearest eigenvalue of `lin`.
double worstError(const LinearModel& lin, const std::vector<std::complex<double>>& reference) {
  double worst = 0;
  for (const auto& r : reference) {
    double best = INFINITY;
    for (int k = 0; k < lin.eigenvalues.size(); ++k) best = std::min(best, std::abs(lin.eigenvalues[k] - r));
    worst = std::max(worst, best);
  }
  return worst;
}

TEST(RelaxationLinear, StiffTyresConvergeToTheWhippleBenchmark) {
  // Meijaard et al. (2007) Table 2 at 5 m/s: weave pair, capsize, castor.
  const std::vector<std::complex<double>> ref5 = {{-0.77534188219585, 4.46486771378823}, {-0.77534188219585, -4.46486771378823},
                                                  {-0.32286642900409, 0}, {-14.07838969279820, 0}};
  double previous = INFINITY;
  TrimOptions opt;
  opt.tolerance = 1e-8;  // stiff springs (up to 1e9 N/m) put the round-off floor near 1e-10
  for (double scale : {1.0, 10.0, 100.0, 1000.0, 10000.0}) {
    const VehicleModel model(loadScenario(kWhipple, {tyres(scale)}));
    const TrimResult trim = calcTrim(model, 5.0, opt);
    // Perturbations must stay well inside the static tyre deflection (about 4e-3/scale m) for the
    // differences to see a smooth contact force.
    LinearizeOptions lin;
    lin.step = 1e-4 / scale;
    const double err = worstError(linearize(model, trim, lin), ref5);
    std::cout << "stiffness scale " << scale << ": worst |delta lambda| = " << err << "\n";
    EXPECT_LT(err, previous) << "error must shrink as the tyres stiffen";
    previous = err;
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(RelaxationLinear, TrimHasNoSlipOrLeanWhenSymmetric) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml"));
  const TrimResult trim = calcTrim(model, 20.0);
  EXPECT_LT(trim.residualNorm, 1e-10);
  const CoordinateIndices& ix = model.getIndices();
  for (int q : {ix.roll, ix.steer, ix.yaw}) EXPECT_NEAR(trim.state.getQ()[q], 0.0, 1e-12) << model.getQNames()[q];
  for (int z = 0; z < model.getNumZ(); ++z) EXPECT_NEAR(trim.state.getZ()[z], 0.0, 1e-12) << model.getZNames()[z];
  // Drag at 20 m/s, 1/2 rho CdA v^2, is carried by the drive torque through the rear tyre: the
  // torque equals drag times the height of the rear hub above the rear contact point, to within the
  // tyre's radial deflection and the small pitch of the trimmed vehicle.
  const Scenario& s = model.getScenario();
  const double rho = testing::getExtensionValue(s, "aerodynamics", "air_density_kgpm3").as<double>();
  const double dragArea = testing::getExtensionValue(s, "aerodynamics", "drag_area_m2").as<double>();
  const double drag = 0.5 * rho * dragArea * 400.0;
  EXPECT_NEAR(model.getInput(trim.state, Input::DriveTorque), drag * s.rearWheel.radius, 0.02 * drag * s.rearWheel.radius);
}

// The header's signs: camber thrust pushes towards the lean (k_phi >= 0) and a small slip's aligning
// moment turns the wheel towards its velocity (k_mz <= 0). A negative camber stiffness or a positive
// self-aligning stiffness is refused at its key, given directly or over a preset; the twisting
// stiffness may have either sign (measured bicycle tyres change it with load).
TEST(RelaxationLinear, UnphysicalSignsAreRefusedAtTheirKey) {
  const std::string supersport = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/supersport.yaml";
  const std::string bicycle = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark-tyres.yaml";
  struct Case {
    std::string file, set, key;
  };
  for (const auto& c : std::vector<Case>{
           {supersport, "contact.front.camber_stiffness_per_rad=-1.24", "contact.front.camber_stiffness_per_rad"},
           {supersport, "contact.rear.self_aligning_stiffness_m_per_rad=0.47", "contact.rear.self_aligning_stiffness_m_per_rad"},
           {bicycle, "contact.front={camber_stiffness_per_rad: -0.9}", "contact.front.camber_stiffness_per_rad"}}) {
    const InputError e = test::catchInputError([&] { VehicleModel(loadScenario(c.file, {c.set})); });
    EXPECT_EQ(e.getLocation().key, c.key) << e.what();
  }
  EXPECT_NO_THROW(VehicleModel(loadScenario(supersport, {"contact.front.twisting_stiffness_m_per_rad=-0.01"})));
  EXPECT_NO_THROW(VehicleModel(loadScenario(supersport, {"contact.front.camber_stiffness_per_rad=0"})));
}

// A relaxation length is 0 (no lag) or at least kMinRelaxationLength: 1e-300 m gave non-finite roots
// (a crash of the mode tracking) or a root of -1e301 1/s. Drawn (seeded) on a log scale below the floor,
// given directly, over a preset and inline; the floor itself is accepted.
TEST(RelaxationLinear, RelaxationLengthHasAPhysicalFloor) {
  const std::string bicycle = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark-tyres.yaml";
  core::PortableRandom rng(2029);
  for (int i = 0; i < 4; ++i) {
    const std::string tiny = io::formatNumber(kMinRelaxationLength * std::pow(10.0, rng.drawUniform(-300, -0.01)));
    for (const std::string& set : {"contact.front.relaxation_length_m=" + tiny, "contact.rear={relaxation_length_m: " + tiny + "}"}) {
      const InputError e = test::catchInputError([&] { VehicleModel(loadScenario(bicycle, {set})); });
      EXPECT_NE(e.getLocation().key.find("relaxation_length_m"), std::string::npos) << e.what();
      EXPECT_NE(e.getReason().find("must be 0 (off) or at least 0.0001 m"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(VehicleModel(loadScenario(bicycle, {"contact.front.relaxation_length_m=1e-4"})));
  EXPECT_NO_THROW(VehicleModel(loadScenario(bicycle, {"contact.front.relaxation_length_m=0"})));
}

// The steady-state law motostab tyre draws: the header's equations in ISO-W signs (alpha_ISO = -atan
// of the contact's slip, gamma_ISO = -phi), at drawn points and parameters.
TEST(RelaxationLinear, SteadyLawInIsoSigns) {
  core::PortableRandom rng(314);
  for (int i = 0; i < 50; ++i) {
    LinearTyreParameters p;
    p.corneringStiffness = rng.drawUniform(5, 20);
    p.camberStiffness = rng.drawUniform(0, 2);
    p.selfAligningStiffness = rng.drawUniform(-0.5, 0);
    p.twistingStiffness = rng.drawUniform(-0.05, 0.05);
    p.longitudinalStiffness = rng.drawUniform(5, 30);
    p.relaxationLength = rng.drawUniform(0, 0.3);
    const auto law = makeLinearTyreForceLaw(p);
    const double Fz = rng.drawUniform(100, 3000), alphaIso = rng.drawUniform(-0.3, 0.3), gammaIso = rng.drawUniform(-1, 1);
    const double kappa = rng.drawUniform(-0.2, 0.2);
    const TyreForces f = law->calcForces({Fz, kappa, alphaIso, gammaIso, 20});
    const double alpha = -std::tan(alphaIso), phi = -gammaIso;  // the project's signs
    EXPECT_NEAR(f.Fx, Fz * p.longitudinalStiffness * kappa, 1e-9 * Fz);
    EXPECT_NEAR(f.Fy, Fz * (p.corneringStiffness * alpha + p.camberStiffness * phi), 1e-9 * Fz);
    EXPECT_NEAR(f.Mz, Fz * (p.selfAligningStiffness * alpha + p.twistingStiffness * phi), 1e-9 * Fz);
    EXPECT_EQ(f.Mx, 0);
    EXPECT_EQ(f.My, 0);
    EXPECT_NEAR(law->calcCorneringStiffness(Fz), -Fz * p.corneringStiffness, 1e-9 * Fz);
    EXPECT_NEAR(law->calcCamberStiffness(Fz), -Fz * p.camberStiffness, 1e-9 * Fz);
    EXPECT_EQ(law->calcRelaxationLength(Fz, gammaIso, 20), p.relaxationLength);
  }
}

}  // namespace
}  // namespace motostab::tyres
