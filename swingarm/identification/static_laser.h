#pragma once
// Static test: lateral load at the hub, laser readings on the reference plate -> static twist axis,
// k_lat, a_tw, k_tw (seed eq. 1-4) with standard errors.
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "swingarm/identification/plate_motion.h"

namespace motostab::swingarm::identification {

/// A laser sensor on the plate, measuring y displacement (CSV column "<name>_m").
struct PlateSensor {
  std::string name;
  PlatePoint position;
};

/// The static test description (docs/swingarm-identification.md, "Static test").
struct StaticTest {
  std::filesystem::path file;         ///< the YAML file
  std::string frame;                  ///< free text
  PlatePoint forcePoint;              ///< m
  std::vector<PlateSensor> sensors;   ///< >= 3, not collinear
  std::filesystem::path readings;     ///< CSV: force_N,<name>_m,...
  double sensorResolution = 4e-6;     ///< m (optional key sensor_resolution_m)
};

/// Reads and checks a static test YAML (strict keys; InputError on any problem).
StaticTest readStaticTest(const std::filesystem::path& file);

/// Readings: one row per load level (repeated levels allowed).
struct StaticReadings {
  std::vector<double> force;  ///< N
  Eigen::MatrixXd dy;         ///< m, rows = load levels, columns = sensors
};

/// Reads the CSV named by the test: needs force_N and every sensor column, a 0 N (unloaded) row and at
/// least two other load levels. InputError naming file, line and column otherwise.
StaticReadings readStaticReadings(const StaticTest& test);

/// Plane fit of one load level: dy = d0 + dx x + dz z.
struct LoadLevelFit {
  double force = 0;            ///< N
  Eigen::Vector3d plane;       ///< [d0 (m), dx, dz (rad)]
  double residualRms = 0;      ///< m
};

/// Static identification result (value and standard error of each quantity).
struct StaticResult {
  std::vector<LoadLevelFit> levels;
  Eigen::Vector3d compliancePlane;   ///< d[d0, dx, dz]/dF per N (slope of the per-level planes)
  Eigen::Matrix3d complianceCovariance;
  double sigma = 0;                  ///< m, reading noise used: max(residual estimate, resolution/sqrt(12))
  double sigmaResidual = 0;          ///< m, from regression residuals (0 if no residual dof)
  int residualDof = 0;
  TwistAxis axis;                    ///< per N: rotation rad/N, forcePointMotion m/N
  double kLat = 0, kLatStderr = 0;         ///< N/m (seed eq. 1)
  double aTw = 0, aTwStderr = 0;           ///< m (seed eq. 2)
  double kTw = 0, kTwStderr = 0;           ///< Nm/rad (seed eq. 3-4)
  double betaDeg = 0, betaStderrDeg = 0;   ///< deg
  double rotationPerN = 0, rotationPerNStderr = 0;  ///< rad/N
  double yLatPerN = 0, yLatPerNStderr = 0;          ///< m/N
  Eigen::Vector2d axisPointStderr = Eigen::Vector2d::Zero();  ///< m
  double maxForce = 0;                     ///< N, largest |load|
};

/// Per-level plane fits, slope of the plane coefficients versus force (least squares over all levels),
/// twist axis of the slope plane and seed eq. 1-4:
///   k_lat = F / y_lat,  a_tw = y_lat / theta_tw,  k_tw = F a_tw / theta_tw = k_lat a_tw^2.
/// Standard errors: Cov(slope) = sigma^2 (A^T A)^-1 / sum (F - mean F)^2, propagated to first order.
StaticResult identifyStatic(const StaticTest& test, const StaticReadings& readings);

}  // namespace motostab::swingarm::identification
