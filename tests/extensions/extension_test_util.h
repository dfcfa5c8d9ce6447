#pragma once
// Shared by the model-extension tests (extensions/): eigenvalues at one speed, matching of spectra,
// labelled modes of a sweep, scenario files with an extra section, and a portable random draw.
#include <gtest/gtest.h>

#include <algorithm>
#include <complex>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "core/portable_random.h"
#include "io/number.h"
#include "tests/support/analysis_chain.h"
#include "tests/support/extension_sections.h"
#include "analysis/linearize.h"
#include "analysis/sweep.h"
#include "analysis/trim.h"
#include "scenario/scenario.h"
#include "vehicle/vehicle_model.h"

namespace motostab::testing {

using cd = std::complex<double>;

inline const std::string kWhipple = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";
inline const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

/// Eigenvalues of the fourth-order linearisation at `speed` (m/s).
inline Eigen::VectorXcd calcEigenvaluesAt(const Scenario& s, double speed) {
  const VehicleModel model(s);
  return linearize(model, calcTrim(model, speed)).eigenvalues;
}

/// Largest distance from each eigenvalue of `ref` to the nearest one of `test`, relative to
/// max(1, |lambda_ref|) (test may have more eigenvalues: the extension's own modes).
inline double calcSpectrumDistance(const Eigen::VectorXcd& ref, const Eigen::VectorXcd& test) {
  double worst = 0;
  for (int i = 0; i < ref.size(); ++i) {
    double best = 1e300;
    for (int j = 0; j < test.size(); ++j) best = std::min(best, std::abs(ref[i] - test[j]));
    worst = std::max(worst, best / std::max(1.0, std::abs(ref[i])));
  }
  return worst;
}

/// The eigenvalue with positive imaginary part labelled `label` at sweep speed index k, or NaN if there
/// is none.
inline cd findLabelled(const SweepResult& sweep, const std::string& label, size_t k) {
  for (const auto& b : sweep.branches)
    if (analysis::toString(b.labels[k]) == label && b.eigenvalue[k].imag() >= 0) return b.eigenvalue[k];
  return {std::nan(""), std::nan("")};
}

/// Sweep of a scenario over start..stop at `step` (m/s).
inline SweepResult runScenarioSweep(const Scenario& s, double start, double stop, double step) {
  const VehicleModel model(s);
  SweepOptions o;
  o.start = start, o.stop = stop, o.step = step;
  return runSweep(model, o);
}

/// The limit test on the enduro: weave and wobble at 10, 20 and 30 m/s with `overrides`
/// within `tolerance` (relative) of the plain enduro's.
inline void expectEnduroWeaveAndWobbleKept(const std::vector<std::string>& overrides, double tolerance = 1e-3) {
  const SweepResult a = runScenarioSweep(loadScenario(kEnduro), 10, 30, 1);
  const SweepResult b = runScenarioSweep(loadScenario(kEnduro, overrides), 10, 30, 1);
  for (size_t k : {0, 10, 20})
    for (const char* mode : {"weave", "wobble"}) {
      const cd la = findLabelled(a, mode, k), lb = findLabelled(b, mode, k);
      ASSERT_TRUE(std::isfinite(la.real()) && std::isfinite(lb.real())) << mode << " at " << a.speeds[k];
      std::cout << "enduro " << mode << " at " << a.speeds[k] << " m/s: relative change " << std::abs(la - lb) / std::abs(la) << "\n";
      EXPECT_LT(std::abs(la - lb) / std::abs(la), tolerance) << mode << " at " << a.speeds[k];
    }
}

/// The limit test on the Whipple bicycle: every eigenvalue at 2, 5 and 8 m/s of
/// `extended` within `tolerance` (relative to max(1, |lambda|)) of one of the plain benchmark's.
inline void expectWhippleSpectrumKept(const Scenario& extended, double tolerance = 1e-4) {
  const Scenario plain = loadScenario(kWhipple);
  for (double v : {2.0, 5.0, 8.0}) {
    const double d = calcSpectrumDistance(calcEigenvaluesAt(plain, v), calcEigenvaluesAt(extended, v));
    std::cout << "Whipple at " << v << " m/s: largest relative eigenvalue change " << d << "\n";
    EXPECT_LT(d, tolerance) << v;
  }
}

/// Writes `base` with `extra` appended to a fresh file; returns its path. `lineOfExtra` gets the
/// 1-based line number of the first appended line.
inline std::string writeScenarioWith(const std::string& base, const std::string& extra, const std::string& name,
                                     int& lineOfExtra) {
  std::ifstream in(base);
  std::stringstream text;
  text << in.rdbuf();
  std::string body = text.str();
  if (!body.empty() && body.back() != '\n') body += '\n';
  lineOfExtra = 1;
  for (char c : body) lineOfExtra += c == '\n';
  // One folder per process: parallel test runs (other checkouts too) never share a file.
  const auto dir = std::filesystem::temp_directory_path() / ("motostab_extension_tests_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / (name + ".yaml")).string();
  std::ofstream(path) << body << extra;
  return path;
}

/// The body `name` of the model of `s` as it is built (vehicle::listModelBodies).
inline scenario::BodySpec getModelBody(const Scenario& s, const std::string& name) {
  for (const scenario::NamedBody& b : vehicle::listModelBodies(s))
    if (b.name == name) return b.body;
  ADD_FAILURE() << "no body " << name;
  return {};
}

/// The whole vehicle composed from the model's bodies as built.
inline scenario::BodySpec calcModelTotal(const Scenario& s) {
  std::vector<scenario::BodySpec> parts;
  for (const scenario::NamedBody& b : vehicle::listModelBodies(s)) parts.push_back(b.body);
  return scenario::composeBodies(parts);
}

/// Loads `file` with `overrides` and builds its model: the InputError of either propagates.
inline void loadAndBuild(const std::string& file, const std::vector<std::string>& overrides) {
  const VehicleModel model(loadScenario(file, overrides));
}

/// Loads `file` and builds its model (which reads the extension sections) expecting an InputError at
/// (line, column) naming `key`; returns the message.
inline std::string expectInputError(const std::string& file, int line, int column, const std::string& key) {
  try {
    const VehicleModel model(loadScenario(file));
  } catch (const InputError& e) {
    EXPECT_EQ(e.getLocation().file, file);
    EXPECT_EQ(e.getLocation().line, line) << e.what();
    EXPECT_EQ(e.getLocation().column, column) << e.what();
    EXPECT_EQ(e.getLocation().key, key) << e.what();
    return e.what();
  }
  ADD_FAILURE() << file << ": no InputError for " << key;
  return "";
}

/// Index of the coordinate `name` in the model's q, or -1.
inline int findCoordinate(const VehicleModel& model, const std::string& name) {
  const auto& n = model.getQNames();
  const auto it = std::find(n.begin(), n.end(), name);
  return it == n.end() ? -1 : static_cast<int>(it - n.begin());
}

/// omega^2 (rad^2/s^2) of coordinate `name` with every other mobilizer locked at the design pose,
/// at rest: -d(qddot)/dq by a central difference (exact for linear springs up to round-off).
inline double calcLockedOmegaSquared(const Scenario& s, const std::string& name) {
  const VehicleModel model(s);
  SimTK::State st = model.getDefaultState();
  const int q = findCoordinate(model, name);
  EXPECT_GE(q, 0) << name;
  const auto& matter = model.getMatter();
  for (SimTK::MobilizedBodyIndex i(1); i < matter.getNumBodies(); ++i) {
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(i);
    const int q0 = mb.getFirstQIndex(st);
    if (!(q0 <= q && q < q0 + mb.getNumQ(st))) mb.lock(st);
  }
  const double eps = 1e-6;
  double udot[2];
  for (int k = 0; k < 2; ++k) {
    st.updQ()[q] = k == 0 ? eps : -eps;
    model.getSystem().realize(st, SimTK::Stage::Acceleration);
    udot[k] = st.getUDot()[q];
  }
  return -(udot[0] - udot[1]) / (2 * eps);
}

/// Whole-vehicle mass (kg), CoM (m) and central inertia (kg m^2) in ground at the design pose.
struct VehicleTotals {
  double mass = 0;
  SimTK::Vec3 com;
  SimTK::Mat33 inertia;
};
inline VehicleTotals calcVehicleTotals(const Scenario& s) {
  const VehicleModel model(s);
  SimTK::State st = model.getDefaultState();
  model.getSystem().realize(st, SimTK::Stage::Position);
  const auto& m = model.getMatter();
  return {m.calcSystemMass(st), m.calcSystemMassCenterLocationInGround(st),
          m.calcSystemCentralInertiaInGround(st).toMat33()};
}

/// Largest relative difference of two VehicleTotals (mass, CoM per wheelbase, inertia per its norm).
inline double calcTotalsDifference(const VehicleTotals& a, const VehicleTotals& b, double wheelbase) {
  const double dm = std::abs(a.mass - b.mass) / a.mass;
  const double dc = (a.com - b.com).norm() / wheelbase;
  const double di = (a.inertia - b.inertia).norm() / a.inertia.norm();
  return std::max(dm, std::max(dc, di));
}

/// Malformed-input cases: the text appended to a scenario, the column of the offending key on the
/// last appended line, and its key path; each must fail at that line and column.
struct BadInputCase {
  std::string text;
  int column;
  std::string key;
};
inline void expectBadInputs(const std::string& base, const std::string& prefix, const std::vector<BadInputCase>& cases) {
  int i = 0;
  for (const BadInputCase& c : cases) {
    int line = 0;
    const std::string file = writeScenarioWith(base, c.text, prefix + std::to_string(i++), line);
    const int badLine = line + static_cast<int>(std::count(c.text.begin(), c.text.end(), '\n')) - 1;
    SCOPED_TRACE(c.text);
    expectInputError(file, badLine, c.column, c.key);
  }
}

}  // namespace motostab::testing
