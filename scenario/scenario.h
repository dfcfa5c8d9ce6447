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
#include "scenario/body_spec.h"
#include "io/input_store.h"
#include "io/yaml_map.h"

namespace motostab::scenario {

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

/// The swingarm between rear frame and rear wheel (seed sec. 2.4 and 4). Its own frame S: origin at
/// the pivot, x towards the rear hub, z up in the vehicle's plane of symmetry.
struct SwingarmSpec {
  Vec3d pivot{0, 0, 0};     ///< pivot in D, m
  BodySpec body;            ///< mass; com and inertia in S (seed Table 1)
  std::string compliance;   ///< compliance plugin name: rigid, bending, torsion, twist, bending+torsion
  YAML::Node params;        ///< the whole swingarm mapping, for the compliance plugin
  std::string file;
};

/// A plugin selected by name with its own parameters (validated by the plugin itself).
struct PluginSpec {
  std::string model;
  YAML::Node params;    ///< the whole mapping, including `model`
  std::string file;     ///< for error messages
  std::string path;     ///< key path, e.g. "contact"
  io::InputLocation where;  ///< where its key is given (an extension section: its name), for messages
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
  /// The model-extension sections (steer_damper, rider_lean, ... and those a plugin library registers),
  /// in file order: every top-level mapping that is not one of the sections above. Each is read and
  /// checked by the extension plugin of its name (plugins/plugin_api.h ExtensionModel) when the model is
  /// built, or at once by PluginRegistry::readScenarioSections; an unknown name is an InputError then.
  std::vector<PluginSpec> extensions;
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

/// The extension section named `name` of `scenario`, or null when it has none.
const PluginSpec* findExtension(const Scenario& scenario, const std::string& name);

/// Reads `mass_kg`, `com_m` and `inertia_kgm2` (checked) from `m`; the caller finishes the map.
BodySpec readBodyKeys(io::YamlMap& m);

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

/// The key of the swingarm's own model-extension section: the loader passes `swingarm.suspension`
/// (the rear suspension, extensions/rear_suspension.h) on as the extension section of that path.
inline constexpr const char* kSwingarmSuspension = "suspension";

/// Moment (N m) about the pivot's +y axis (positive lifts the hub) that the rear tyre's static load
/// and the weights of swingarm and rear wheel exert on the swingarm at the design pose; the
/// suspension spring carries its negative (needs hasSwingarm).
double calcStaticPivotMoment(const Scenario& scenario);

}  // namespace motostab::scenario
