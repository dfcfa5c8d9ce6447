#pragma once
// The scenario: everything that defines one vehicle study, read strictly from YAML.
// Frame of all positions and inertias (the design frame D): origin at the rear contact point of the
// upright vehicle at rest, x forward, y left, z up (ISO 8855). SI units; angles say their unit in the key.
#include <yaml-cpp/yaml.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "io/input_store.h"

namespace motostab::scenario {

using Vec3d = std::array<double, 3>;

/// Inertia tensor components about the centre of mass, in the design frame, kg m^2.
/// Off-diagonal entries are tensor components (I_xz = -sum m x z), as in Meijaard et al. 2007.
struct InertiaSpec {
  double xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;
};

/// A rigid body: mass (kg), centre of mass in D (m), inertia about the CoM in D.
struct BodySpec {
  double mass = 0;
  Vec3d com{0, 0, 0};
  InertiaSpec inertia;
};

/// A wheel: rolling (outer) radius and crown radius (0 = knife edge), mass, and the spin (axial)
/// and diametral moments of inertia about its centre (kg m^2).
struct WheelSpec {
  double radius = 0;
  double crownRadius = 0;
  double mass = 0;
  double axialInertia = 0;
  double diametralInertia = 0;
};

/// Steer geometry: wheelbase w (m), trail c (m, front contact behind the steer-axis ground point),
/// steer axis tilt lambda from vertical (rad).
struct GeometrySpec {
  double wheelbase = 0;
  double trail = 0;
  double steerAxisTilt = 0;
};

/// An optional rear suspension: the swingarm turns about the pivot's lateral axis (design y) against
/// a rotational spring and damper. Always stored about the pivot; the scenario may give them
/// referred to the wheel (k_theta = k_wheel l^2, c_theta = c_wheel l^2, l = horizontal pivot-to-hub
/// distance, see calcSuspensionLever).
struct SuspensionSpec {
  double stiffness = 0;     ///< k_theta, N m/rad (> 0)
  double damping = 0;       ///< c_theta, N m s/rad (>= 0)
};

/// The swingarm between rear frame and rear wheel (seed sec. 2.4 and 4). Its own frame S: origin at
/// the pivot, x towards the rear hub, z up in the vehicle's plane of symmetry.
struct SwingarmSpec {
  Vec3d pivot{0, 0, 0};     ///< pivot in D, m
  BodySpec body;            ///< mass; com and inertia in S (seed Table 1)
  std::string compliance;   ///< compliance plugin name: rigid, bending, torsion, twist, bending+torsion
  bool hasSuspension = false;  ///< false: the pivot is rigid in-plane
  SuspensionSpec suspension;
  YAML::Node params;        ///< the whole swingarm mapping, for the compliance plugin
  std::string file;
};

/// Aerodynamic drag on the rear frame: F = -1/2 rho CdA |v| v at the centre of pressure.
struct AerodynamicsSpec {
  double dragArea = 0;      ///< Cd A, m^2
  double airDensity = 1.2;  ///< kg/m^3
  Vec3d centreOfPressure{0, 0, 0};  ///< in D, m
};

/// A steering damper between front and rear frames about the steer axis (vehicle/steer_damper.h):
/// T = -c delta' - f tanh(delta'/omega_s) on the front frame, its reaction on the rear frame.
struct SteerDamperSpec {
  double damping = 0;            ///< c, N m s/rad (>= 0)
  double coulomb = 0;            ///< f, N m (>= 0): smoothed Coulomb friction
  double coulombSmoothing = 0.1; ///< omega_s, rad/s (> 0): steer rate at which tanh reaches 76 % of f
};

/// Lateral bending of the front fork (vehicle/fork_compliance.h): the hub carrier (lower legs, axle,
/// brake) turns relative to the front frame about an axis perpendicular to the steer axis in the plane
/// of symmetry, through the steer-axis point `axisDistance` above the steer axis's ground point.
/// Optional torsion about the steer-axis direction in series (between carrier and wheel).
struct ForkComplianceSpec {
  double stiffness = 0;          ///< bending stiffness, N m/rad (> 0)
  double damping = 0;            ///< bending damping, N m s/rad (>= 0)
  double axisDistance = 0;       ///< m along the steer axis from its ground point (default: the crown, see reader)
  BodySpec carrier;              ///< moving part's mass properties in D (default: a fraction of the front frame)
  double carrierFraction = 0;    ///< the fraction used for the default carrier (0 when given explicitly)
  bool hasTorsion = false;
  double torsionStiffness = 0;   ///< N m/rad (> 0)
  double torsionDamping = 0;     ///< N m s/rad (>= 0)
};

/// A passive rider upper body (vehicle/rider_lean.h) hinged to the rear frame about the longitudinal
/// axis (design x) at height `hingeHeight`, against a torsional spring and damper. `body` is taken out
/// of the rear frame, whose mass properties include the whole rider: the vehicle's totals are unchanged.
struct RiderLeanSpec {
  double hingeHeight = 0;        ///< m above the ground, in the plane of symmetry
  BodySpec body;                 ///< upper body: mass (kg), CoM in D (m), inertia about its CoM in D
  double stiffness = 0;          ///< N m/rad (> 0)
  double damping = 0;            ///< N m s/rad (>= 0)
};

/// The rider's arms on the handlebar (vehicle/rider_arms.h): a steer impedance between the front
/// frame and the rear frame (the rider rigid on it), after Sharp's hands-on steer model (added steer
/// inertia, a torsional spring and a damper about the steer axis; Sharp 1994, "Vibrational modes of
/// motorcycles and their design parameter sensitivities", IMechE Vehicle NVH and Refinement) and
/// Cossalter, Doria, Lot, Massaro (2011) "The effect of rider's passive steering impedance on
/// motorcycle stability: identification and analysis", Meccanica 46:279-292. The inertia is carried
/// by two point masses at the grips, `gripHalfWidth` either side of the steer axis at the height of the
/// front frame's centre of mass, moved from the rear frame (which holds the whole rider) to the front
/// frame: the vehicle's totals are unchanged.
struct RiderArmsSpec {
  double inertia = 0;            ///< J_a, added steer inertia about the steer axis, kg m^2 (> 0)
  double stiffness = 0;          ///< k_a, N m/rad (>= 0)
  double damping = 0;            ///< c_a, N m s/rad (>= 0)
  double gripHalfWidth = 0.25;   ///< d, m (> 0): grip distance from the steer axis
  BodySpec body;                 ///< the grip masses (2 x J_a / (2 d^2)) in D: what moved to the front frame
};

/// The shortest steer controller delay, s: a tenth of a millisecond, below any rider's or actuator's
/// (human reaction ~0.1-0.3 s, electric steer actuators ~1-10 ms). The Pade pole -2/tau of a shorter
/// delay swamps every other root (1e-300 s gives -2e300 1/s and loses the weave).
constexpr double kMinSteerDelay = 1e-4;

/// Linear state feedback on the steer torque (vehicle/steer_controller.h), ISO 8855 signs (roll > 0
/// leans right, steer > 0 steers left, torque > 0 steers left):
///   u = f(v) g (k_phi phi + k_phid phi' + k_delta delta + k_deltad delta')            (N m)
/// f(v) the speed schedule (1 without one), g the gain factor; then the optional delay and limit.
struct SteerControllerSpec {
  enum class Schedule { None, Below, Table };
  double rollAngleGain = 0;   ///< k_phi, N m/rad (per m/s with a `below_mps` schedule)
  double rollRateGain = 0;    ///< k_phid, N m s/rad (likewise)
  double steerAngleGain = 0;  ///< k_delta, N m/rad
  double steerRateGain = 0;   ///< k_deltad, N m s/rad
  double gainFactor = 1;      ///< g, dimensionless (> 0): scales every gain
  Schedule schedule = Schedule::None;
  double scheduleBelow = 0;   ///< v0, m/s: f = v0 - v for v < v0, else 0
  std::vector<std::array<double, 2>> scheduleTable;  ///< (v m/s, f) sorted by v: f interpolated linearly
  double delay = 0;           ///< tau, s (0: none, else >= kMinSteerDelay): first-order Pade delay
  double torqueLimit = 0;     ///< N m (> 0 when given; 0: none): |T| <= limit
};

/// A plugin selected by name with its own parameters (validated by the plugin itself).
struct PluginSpec {
  std::string model;
  YAML::Node params;    ///< the whole mapping, including `model`
  std::string file;     ///< for error messages
  std::string path;     ///< key path, e.g. "contact"
};

/// Default speed range for sweeps, m/s.
struct SpeedRange {
  double start = 0, stop = 10, step = 0.1;
  /// The most speeds a range may hold, wherever it is given: a sweep keeps a trim and a linear model per
  /// speed (about 27 kB for a 20-state motorcycle, measured: 10000 speeds take about 0.3 GB).
  static constexpr long kMaxSpeeds = 10000;
  /// The highest speed, m/s (540 km/h, above any motorcycle's), as for measured speeds.
  static constexpr double kMaxSpeed = 150;
};

/// The number of speeds start, start + step, ... up to stop (within 1e-9 steps) of a range; 0 with `why`
/// set when it is not one (else `why` is empty): every value finite, 0 <= start <= stop <= SpeedRange::kMaxSpeed, step > 0, at
/// most SpeedRange::kMaxSpeeds speeds.
long countSpeeds(double start, double stop, double step, std::string& why);

/// A stated uncertainty of one scenario parameter (the `uncertainty:` section): the key path as
/// --set takes it, and the standard deviation in the key's own unit.
struct ParameterUncertainty {
  enum class Distribution { Normal, Uniform, Lognormal };
  std::string path;
  double sigma = 0;
  Distribution distribution = Distribution::Normal;
  io::InputLocation where;  ///< where the scenario states it
};

/// A value a scenario with `total:` left out and the loader assumed (scenario/whole_vehicle.h): the
/// key path, the value as text with its unit, and its source.
struct AssumedValue {
  std::string key;
  std::string value;
  std::string source;
};

/// A warning found at load: a likely unit slip or swapped quantity (scenario/plausibility.h), or what
/// a plugin found reading its section (PluginInput, e.g. .tir coefficients its equations do not use);
/// the check that found it, where the value is given, and what it means.
struct ScenarioWarning {
  enum class Check {
    SteerAxisTilt, Wheelbase, Trail, ForkOffset, CentreOfMass, TotalMass, InertiaOrder, RadiusOfGyration,
    WheelRadius, WheelInertia, DefaultWheel, Gravity, TyreSign, CorneringStiffness, RelaxationLength, PluginInput
  };
  Check check = Check::SteerAxisTilt;
  io::InputLocation where;
  std::string message;
};

struct Scenario {
  std::string name;
  std::string description;
  std::string sourceFile;
  double gravity = 9.81;                ///< m/s^2, acting along -z
  SpeedRange speeds;
  GeometrySpec geometry;
  BodySpec rearFrame;                   ///< rear frame with rigid rider (derived from `total` when given)
  bool hasTotal = false;                ///< the whole vehicle was given (`total:`), the rear frame derived
  BodySpec total;                       ///< whole vehicle with rider about its own CoM, in D (hasTotal)
  BodySpec frontFrame;                  ///< fork and handlebar
  WheelSpec rearWheel, frontWheel;
  PluginSpec contact;                   ///< contact/tyre model for both wheels
  bool hasSwingarm = false;
  SwingarmSpec swingarm;
  bool hasAerodynamics = false;
  AerodynamicsSpec aerodynamics;
  bool hasSteerDamper = false;
  SteerDamperSpec steerDamper;
  bool hasForkCompliance = false;
  ForkComplianceSpec forkCompliance;
  bool hasRiderLean = false;
  RiderLeanSpec riderLean;
  bool hasSteerController = false;
  SteerControllerSpec steerController;
  bool hasRiderArms = false;
  RiderArmsSpec riderArms;                ///< its grip masses are already in frontFrame, out of rearFrame
  std::vector<std::string> plugins;     ///< shared libraries to load before building
  std::vector<std::string> overrides;   ///< the --set assignments applied, for messages
  std::vector<ParameterUncertainty> uncertainty;  ///< stated parameter uncertainties (may be empty)
  std::vector<AssumedValue> assumed;    ///< values left out beside `total:` and taken from defaults
  std::vector<ScenarioWarning> warnings;  ///< warnings found at load (never printed by a library)
  /// The files the plugin sections name, read once and shared by every copy and by every scenario
  /// loaded from the same ScenarioSource, and the warnings the plugins found (io/input_store.h).
  std::shared_ptr<io::InputStore> inputs = std::make_shared<io::InputStore>();
};

/// Loads and validates a scenario file. `overrides` are "a.b=value" assignments applied first.
/// Every problem is an InputError naming file, line, column and key. A convenience for one load:
/// whoever loads variants of one scenario reads it once with ScenarioSource (scenario_source.h).
Scenario loadScenario(const std::string& file, const std::vector<std::string>& overrides = {});

/// Validates a scenario from its YAML tree (as read from `file`, with the changes `overrides` name
/// already applied; they are kept in Scenario::overrides for messages). InputError as loadScenario.
/// `inputs` is the store the scenario's plugins read their files through (a new one when null).
Scenario readScenarioTree(const YAML::Node& tree, const std::string& file, const std::vector<std::string>& overrides,
                          std::shared_ptr<io::InputStore> inputs = nullptr);

/// Rethrows `error`, naming the override that set the value it is about ("(value from --set
/// a.b=...)") when one did: for errors found after loading, e.g. by a plugin reading its section.
[[noreturn]] void rethrowNamingOverride(const io::InputError& error, const std::vector<std::string>& overrides);

/// Checks an inertia tensor: symmetric positive definite and principal moments satisfying the
/// triangle inequality. Returns an empty string if valid, else the reason.
std::string checkInertia(const InertiaSpec& inertia);

/// The mass properties of `whole` without `part` (all in D): mass, CoM and inertia about the new CoM.
/// Parallel-axis theorem about the design origin; the caller checks the result (mass > 0, checkInertia).
BodySpec calcBodyRemainder(const BodySpec& whole, const BodySpec& part);

/// The default hub carrier of a fork_compliance section: the front frame scaled by `fraction` (that
/// fraction of its mass at its CoM, that fraction of its inertia), so that the rest, the front frame
/// scaled by 1 - fraction, is a valid body for every valid front frame.
BodySpec calcDefaultForkCarrier(const Scenario& scenario, double fraction);

/// Total mass (kg) and centre of mass in D (m) of frames and wheels.
struct MassSummary {
  double mass = 0;
  Vec3d com{0, 0, 0};
};
MassSummary calcMassSummary(const Scenario& scenario);

/// Normal trail c cos(lambda), m.
double calcNormalTrail(const GeometrySpec& geometry);
/// Fork offset: distance from the front wheel centre to the steer axis, r_F sin(lambda) - c cos(lambda), m.
double calcForkOffset(const Scenario& scenario);
/// Transform from the swingarm frame S to the design frame D (needs hasSwingarm).
struct SwingarmFrame {
  Vec3d origin;        ///< pivot in D
  Vec3d x, y, z;       ///< axes of S in D
  double length = 0;   ///< pivot to rear hub, m
};
SwingarmFrame calcSwingarmFrame(const Scenario& scenario);

/// Static vertical wheel loads (N) of the upright vehicle at rest: {rear, front}.
std::array<double, 2> calcStaticWheelLoads(const Scenario& scenario);

/// Keys of the `swingarm` mapping read by loadScenario itself; the compliance plugin reads the rest.
const std::vector<std::string>& getSwingarmLoaderKeys();

/// Suspension lever l: horizontal distance from the pivot to the rear hub at the design pose, m
/// (vertical hub travel per radian of swingarm rotation; needs hasSwingarm).
double calcSuspensionLever(const Scenario& scenario);

/// Moment (N m) about the pivot's +y axis (positive lifts the hub) that the rear tyre's static load
/// and the weights of swingarm and rear wheel exert on the swingarm at the design pose; the
/// suspension spring carries its negative (needs hasSwingarm).
double calcStaticPivotMoment(const Scenario& scenario);

}  // namespace motostab::scenario
