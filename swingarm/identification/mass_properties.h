#pragma once
// Mass properties (seed section 2.4): centre of gravity from a tilting load-cell rig, moments of inertia
// from a trifilar pendulum, with standard errors.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace motostab::swingarm::identification {

/// A load cell under the tilting platform at (x, y) on the platform surface (z = 0), m.
struct LoadCell {
  std::string name;
  double x = 0, y = 0;
};

/// Tilting-rig test (docs/swingarm-identification.md, "Centre of gravity").
struct CogTest {
  std::filesystem::path file;
  std::string frame;
  std::vector<LoadCell> cells;             ///< >= 3, not collinear
  std::vector<double> tiltDeg;             ///< one per reading row
  Eigen::MatrixXd loads;                   ///< N, rows = tilt angles, columns = cells (tare subtracted)
  double g = 9.80665;                      ///< m/s^2
  double cellResolution = 0.05;            ///< N
  Eigen::Vector3d partOrigin = Eigen::Vector3d::Zero();  ///< part-frame origin in the platform frame, m
};

/// Reads the YAML and its CSV(s) (readings, optional tare at the same angles). InputError on any problem:
/// unknown keys, < 3 or collinear cells, missing columns, fewer than two distinct angles, no non-zero
/// angle, angles outside 0..60 deg, tare rows not matching.
CogTest readCogTest(const std::filesystem::path& file);

/// CoG result, part frame (platform axes), m and kg.
struct CogResult {
  double mass = 0, massStderr = 0;
  Eigen::Vector3d cog = Eigen::Vector3d::Zero(), cogStderr = Eigen::Vector3d::Zero();
  double residualRms = 0;                  ///< m, of the centre-of-pressure fit
  std::vector<double> centreOfPressureX;   ///< m, per row (platform frame)
};

/// Least squares over all angles: with the +x side raised by alpha, moment balance gives the centre of
/// pressure x_p = sum(x_i N_i)/sum(N_i) = x_G - z_G tan(alpha); y_G = sum(y_i N_i)/sum(N_i);
/// m = sum(N_i)/(g cos alpha). Standard errors from the residuals, floored by the cell resolution.
CogResult identifyCog(const CogTest& test);

/// One trifilar set-up: the part on the plate with `axis` (unit vector in the part frame) vertical and
/// its CoG `cogOffset` m from the pendulum axis.
struct PendulumSetup {
  std::string name;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double cogOffset = 0;
  std::vector<double> periods;  ///< s, repeated measurements
};

/// Trifilar-pendulum test (docs/swingarm-identification.md, "Moments of inertia").
struct InertiaTest {
  std::filesystem::path file;
  double wireLength = 0, radius = 0, plateMass = 0, partMass = 0;  ///< m, m, kg, kg
  double g = 9.80665, periodResolution = 1e-3;
  std::vector<double> platePeriods;  ///< s, plate alone
  std::vector<PendulumSetup> setups;
};

/// Reads and checks the YAML (strict keys, positive values, >= 3 set-ups, unit-normalised axes).
InertiaTest readInertiaTest(const std::filesystem::path& file);

/// Moment of inertia about the vertical axis of a trifilar pendulum with equal top and bottom radius R:
/// I = m g R^2 T^2 / (4 pi^2 L), kg m^2.
double calcTrifilarInertia(double mass, double g, double radius, double wireLength, double period);

/// Inertia result: per set-up moment about the axis through the CoG, and the tensor about the CoG.
struct InertiaResult {
  double plateInertia = 0, plateInertiaStderr = 0;   ///< kg m^2
  std::vector<double> setupInertia, setupInertiaStderr;  ///< kg m^2, about the set-up axis through the CoG
  bool fullTensor = false;                           ///< products fitted (>= 6 independent set-ups)
  Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero(), tensorStderr = Eigen::Matrix3d::Zero();
};

/// I_part(axis through CoG) = I(plate + part) - I(plate) - m_part d^2 for each set-up, then weighted least
/// squares of n^T I n over set-ups for the 6 tensor components (or the 3 diagonal ones if the set-ups do
/// not determine the products). Period stderr = max(scatter/sqrt(n), resolution/sqrt(12)).
InertiaResult identifyInertia(const InertiaTest& test);

}  // namespace motostab::swingarm::identification
