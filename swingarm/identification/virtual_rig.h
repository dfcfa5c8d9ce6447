#pragma once
// Virtual test rig with known truth, for tests and examples: a swingarm whose reference plate moves as a
// 2-DOF lumped system (rotation theta_b about a bending axis, theta_t about a torsion axis, seed Fig. 8),
// uncoupled in mass and stiffness, so the modes are exactly the bending and torsion rotations. Generates
// laser readings (quantised to the laser resolution), hammer time histories (half-sine pulse, exact
// first-order-hold integration, sensor noise) and mass-property rig readings. Their files, in the formats
// of docs/swingarm-identification.md, are written by output/virtual_rig_output.h.
#include <cstdint>
#include <vector>

#include "modal/spectra.h"
#include "swingarm/identification/hammer_frf.h"
#include "swingarm/identification/mass_properties.h"
#include "swingarm/identification/static_laser.h"

namespace motostab::swingarm::identification {

/// Truth of the virtual swingarm (defaults resemble seed Table 2, swingarm 1).
struct VirtualSwingarm {
  PlatePoint forcePoint{0.55, 0.0};
  std::vector<PlatePoint> sensorPoints{{0.50, 0.04}, {0.60, 0.04}, {0.55, -0.05}};  ///< lasers = accelerometers
  double armB = 0.451, betaBDeg = 95.0, kB = 222.4e3, fB = 134.0, zetaB = 0.0037;  ///< m, deg, Nm/rad, Hz, -
  double armT = 0.026, betaTDeg = 3.0, kT = 77.4e3, fT = 208.0, zetaT = 0.00485;

  /// Point of the bending (mode 0) or torsion (mode 1) axis nearest the force point, (x, z) m.
  Eigen::Vector2d getAxisPoint(int mode) const;
  /// y displacement at r per unit rotation about the axis of `mode`, m/rad.
  double getArmAt(int mode, const PlatePoint& r) const;
};

/// Sensor imperfections.
struct RigNoise {
  double laserResolution = 4e-6;  ///< m, readings are rounded to this
  double laserNoise = 1e-6;       ///< m, Gaussian, before rounding
  double accelNoise = 0.05;       ///< m/s^2 Gaussian
  double forceNoise = 0.05;       ///< N Gaussian
  /// Every figure scaled by `factor` (a quieter rig for factor < 1).
  RigNoise scaled(double factor) const;
};

/// Hammer test settings.
struct HammerOptions {
  int hits = 3;
  double sampleRate = 1024, duration = 1.0;   ///< Hz, s
  double pulseWidth = 0.003, peakForce = 200;  ///< s, N (half-sine; +/-10 % amplitude spread between hits)
  double preTrigger = 0.02;                    ///< s before the pulse
  double doubleHitDelay = 0, doubleHitFraction = 0.3;  ///< s after the first pulse (0: none), relative size
  double accelClip = 0;                        ///< m/s^2, readings clipped here (0: none)
};

/// Static readings at `loads` (N; include 0 for the unloaded plate): offsets + compliance + noise,
/// rounded to the laser resolution.
StaticReadings simulateStaticReadings(const VirtualSwingarm& rig, const std::vector<double>& loads,
                                      const RigNoise& noise, std::uint64_t seed);

/// Hammer hits at the force point, accelerations at the sensor points.
std::vector<modal::ImpactRecord> simulateHammerHits(const VirtualSwingarm& rig, const HammerOptions& options,
                                                    const RigNoise& noise, std::uint64_t seed);

/// Truth of the mass-property rig.
struct VirtualPart {
  double mass = 6.96;                                     ///< kg (seed Table 1, swingarm 1)
  Eigen::Vector3d cog{0.299, 0.0, 0.027};                 ///< m, part frame
  Eigen::Matrix3d inertia = Eigen::Vector3d(0.11, 0.27, 0.34).asDiagonal();  ///< kg m^2 about CoG
};

/// Readings of the tilting rig (before the tare is subtracted).
struct CogRigReadings {
  std::vector<LoadCell> cells;                        ///< N1..N4 on the platform, m
  Eigen::Vector3d partOrigin = Eigen::Vector3d::Zero();  ///< part-frame origin on the platform, m
  std::vector<int> tiltDeg;                           ///< deg, one per row
  std::vector<Eigen::Vector4d> loads, tareLoads;      ///< N per cell: platform with the part, platform alone
};

/// Tilting rig with four cells, tilts 0..30 deg in 3 deg steps, part frame origin at `origin` on the
/// platform, Gaussian cell noise (N); the cell loads from the moment balance of part and platform.
CogRigReadings simulateCogReadings(const VirtualPart& part, const Eigen::Vector3d& origin, double cellNoise,
                                   std::uint64_t seed);
/// Trifilar pendulum (wire 2 m, radius 0.3 m, plate 4 kg, 0.25 kg m^2): plate alone and six set-ups (x, y, z
/// and three oblique axes, CoG 0..25 mm off the pendulum axis), five periods each with Gaussian timing
/// noise (s), from I = m g R^2 T^2 / (4 pi^2 L).
InertiaTest simulateTrifilarTest(const VirtualPart& part, double periodNoise, std::uint64_t seed);

}  // namespace motostab::swingarm::identification
