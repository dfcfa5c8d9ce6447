#pragma once
// Candidate causes of a model's misfit. A candidate is data: `--set` overrides that
// switch an effect on, and free parameters (each an override key path with bounds and, for a measured
// scenario parameter, a Student-t prior: diagnosis/priors.h). Nothing here touches the model: the diagnosis applies the
// overrides to the scenario's YAML tree through loadScenario(file, overrides).
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "io/field.h"
#include "scenario/parameter_overrides.h"

namespace motostab::diagnosis {

/// The steer-rate amplitude of the measured oscillations that steer_friction's equivalent damping is
/// taken at (diagnosis/steer_rate_amplitude.h finds it in the data).
struct SteerRateAmplitude {
  double value_rad_s = 0;  ///< 0: none in the data
  std::string source;      ///< where it comes from, or why there is none
};

struct CandidateParameter {
  std::string name;         ///< JSON key: the scenario key (damping_Nms_per_rad) or "value" for parameter:*
  std::string path;         ///< override key path, e.g. steer_damper.damping_Nms_per_rad
  double lower = 0, upper = 0;  ///< bounds, in the key's unit
  double start = 0;         ///< first guess
  double step = 0;          ///< forward-difference step (key unit; relative when logScale)
  bool logScale = false;    ///< fitted as ln(value) (stiffnesses and scales)
  double off = 0;           ///< value at which the effect vanishes (when !offAtInfinity)
  bool offAtInfinity = false;  ///< the effect vanishes as value -> infinity (a stiffness)
  bool offAtBound = false;  ///< "off" is a bound (damping 0): the likelihood ratio uses the 50:50 mixture
  double priorMean = 0, priorSigma = 0;  ///< Student-t prior (diagnosis/priors.h); sigma 0: none
  bool priorMeasured = false;  ///< the sigma is the scenario's `uncertainty:` one, not motostab's default
  std::vector<std::string> alsoPaths;  ///< further keys set to the same value (both tyres)
  /// keyScale of each of alsoPaths (empty: keyScale for all): one scale factor applied to several
  /// keys of different values (tyre_relaxation: both tyres' relaxation lengths).
  std::vector<double> alsoScales;
  /// The override keys get keyOffset + keyScale * value (key unit): a parameter in its own unit
  /// applied through another key (steer_friction: the friction torque in N m as the equivalent
  /// viscous damping added to the damper's coefficient, physical_candidates.h).
  double keyScale = 1, keyOffset = 0;
  std::string note;         ///< reported with the value (steer_friction: the steer-rate amplitude it is read at)
};

struct Candidate {
  std::string name;                         ///< steer_damper, parameter:geometry.trail_m, ...
  scenario::ParameterOverrides fixedOverrides;  ///< applied before the parameters' (switch the effect on)
  std::vector<CandidateParameter> parameters;
  /// A candidate that predicts exactly as this one in a linear model (steer_friction and
  /// steer_damper): the pair search pools only the better of the two.
  std::string sameModelAs = {};
};

/// The declared sections of the built-in plugins (plugins::listSectionFields of the built-in registry).
const std::vector<io::SectionFields>& getBuiltinSectionFields();

/// Every candidate the scenario (its YAML tree after base overrides, and the measured parameters'
/// uncertainties given as path -> sigma) admits: model extensions this build knows, swingarm
/// compliance variants for scenarios with a swingarm, the bicycle tyre preset (tyre_slip) for
/// scenarios on rolling constraints, and one `parameter:<path>` per scalar of the geometry, bodies and
/// wheels. `rider_lean` (the rider's upper body leaning passively, its stiffness free) where the rear
/// frame holds a rider: heavier than kRiderMass_kg and no `rider_lean` section yet; otherwise a line
/// in `unavailable` says why (a riderless vehicle such as Kooijman's Silvercity has no rider to lean).
/// `rider_arms` (the rider's hands on the bars: steer stiffness and damping free, inertia
/// kRiderArmsInertia_kgm2) likewise where the rear frame holds a rider and no `rider_arms` is given.
/// With a `steer_controller`: `steer_controller_gain` (its gain_factor free) and, without a delay,
/// `steer_controller_delay` (delay_s free).
/// `steer_friction` (physical_candidates.h) where `steerRate` holds a steer-rate amplitude; else a
/// line in `unavailable` says why not. `tyre_relaxation` (both tyres' relaxation lengths scaled by one
/// factor) for scenarios with relaxation_linear tyres; `tyre_carcass` (their relaxation lengths from
/// the load and a lateral carcass stiffness whose compliance grows with speed, the published speed
/// dependence times one factor, candidates.cpp) for such tyres with constant relaxation lengths.
/// The parameter candidates are the measured fields of `sections` (the declarations of the scenario's
/// registry, plugins::makeScenarioRegistry, so that a plugin library's measured fields are varied too;
/// by default the built-in ones).
std::vector<Candidate> listCandidates(const YAML::Node& scenarioTree,
                                      const std::vector<std::pair<std::string, double>>& uncertainty,
                                      std::vector<std::string>* unavailable = nullptr,
                                      const SteerRateAmplitude& steerRate = {},
                                      const std::vector<io::SectionFields>& sections = getBuiltinSectionFields());

/// Steer inertia the `rider_arms` candidate adds with the hands on the bars: Sharp (1994), front-frame
/// steer inertia 0.71 kg m^2 hands off, 0.91 hands on.
constexpr double kRiderArmsInertia_kgm2 = 0.20;

/// Mass of the rider the `rider_lean` candidate assumes (an estimate), kg.
constexpr double kRiderMass_kg = 75;

/// Candidates whose name matches one of the comma-separated names or globs (fnmatch); all when
/// `patterns` is empty. An entry that matches nothing is an InputError (key --candidates) naming it.
std::vector<Candidate> filterCandidates(const std::vector<Candidate>& all, const std::vector<std::string>& patterns);

}  // namespace motostab::diagnosis
