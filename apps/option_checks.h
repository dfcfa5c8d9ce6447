#pragma once
// The checks of a run's user-given values and the option structs assembled from them, shared by the
// command line (apps/cmd_*.cpp, which parse text into these values) and the Python module (python/,
// which takes them as numbers). Each check throws io::InputError at `where`: the command line passes
// its option ("--speeds" and the text), the Python module its keyword argument.
#include <memory>
#include <string>
#include <vector>

#include "analysis/sweep.h"
#include "io/input_error.h"
#include "output/tyre_curve_output.h"
#include "simulation/simulation.h"
#include "studies/study.h"
#include "tyres/magic_formula.h"
#include "uncertainty/uncertainty_study.h"

namespace motostab::cli {

/// The range of a numeric option: finite, in [low, high] (low itself excluded when `excludeLow`).
struct NumberRange {
  double low = 0, high = 0;
  bool excludeLow = false;
  bool contains(double v) const { return v >= low && v <= high && !(excludeLow && v == low); }
  /// "[low, high]" or "(low, high]".
  std::string describe() const;
};
/// InputError at `where` unless `range` contains `value`.
void checkNumber(double value, const NumberRange& range, const io::InputLocation& where);

/// The ranges of the options both the command line and the Python module take.
inline const NumberRange kSpeedMps{0, scenario::SpeedRange::kMaxSpeed};  ///< a trim or linearisation speed, m/s
inline const NumberRange kTurnSpeedMps{0, 1e3, true};   ///< the speed of `trim`, m/s
inline const NumberRange kTyreLoadN{0, 1e7, true};      ///< a tyre's normal load, N
inline const NumberRange kCamberDeg{-89, 89};           ///< a tyre's camber, deg
inline const NumberRange kSlipRatio{-1, 1};             ///< a tyre's longitudinal slip ratio
inline const NumberRange kScaleFactor{0, 1e6, true};    ///< the study's stiffness factor
inline const NumberRange kDampingFactor{0, 1e6};        ///< the study's damping factor
inline const NumberRange kMaxCauses{0, 20};             ///< causes a diagnosis names at most
inline const NumberRange kFolds{2, 1000};               ///< a diagnosis's cross-validation folds

/// A speed grid START:STOP:STEP (m/s): finite, 0 <= START <= STOP <= 150, STEP > 0, at most 10000
/// speeds (scenario::countSpeeds).
void checkSpeedRange(double start, double stop, double step, const io::InputLocation& where);

/// The most points (speeds x roll angles) of a speed x roll map: each keeps a trim and a linear model
/// (about 30 kB for a 20-state motorcycle, measured: 10000 points take about 0.3 GB, as 10000 speeds).
constexpr long kMaxMapPoints = 10000;
/// InputError at `speedsWhere` (naming --roll-deg too) when the speeds of START:STOP:STEP times `rolls`
/// roll angles exceed kMaxMapPoints.
void checkMapPoints(double start, double stop, double step, size_t rolls, const io::InputLocation& speedsWhere);

/// A roll angle (deg) strictly between -89 and 89.
bool isRollInRange(double deg);
/// checkRoll: InputError at `where` unless isRollInRange (NaN fails).
void checkRoll(double deg, const io::InputLocation& where);
/// The roll angles A, A + STEP, ..., B (deg; each strictly between -89 and 89, B >= A, STEP > 0, at
/// most 1000 angles) in radians; InputError at `where` otherwise.
std::vector<double> makeRollAngles(double first, double last, double step, const io::InputLocation& where);

/// Steady turns need a positive speed: `slowest` (m/s) is the slowest speed asked for.
void checkTurnSpeeds(double slowest, const io::InputLocation& where);

/// Worker threads, 1..256.
void checkThreads(int threads, const io::InputLocation& where);

/// The mode label's name (analysis/mode_label.h) of each eigenvalue of one linear model, from its
/// content at that operating point (lin.labels, else labelModes: the labels `motostab linearize` writes).
std::vector<std::string> labelModesOfModel(const analysis::LinearModel& lin);

/// Every hands-free steady turn at `options.roll` on the positive speeds of the grid START:STOP:STEP
/// (analysis::calcHandsFreeTurns; `motostab trim --hands-free`), sorted by speed. InputError at
/// `rollWhere` for a zero roll, at `speedsWhere` for fewer than two positive speeds; ResultError when
/// no turn is bracketed.
std::vector<analysis::HandsFreeTurn> calcHandsFreeTurns(const vehicle::VehicleModel& model, double start, double stop,
                                                       double step, const analysis::TrimOptions& options,
                                                       const io::InputLocation& rollWhere, const io::InputLocation& speedsWhere);

/// Checks a study's options (`motostab study`): each mode-shape speed inside the swept speeds, and a
/// turn's speeds above 0 (`speedsWhere`).
void checkStudyOptions(const studies::StudyOptions& options, const io::InputLocation& shapeWhere,
                       const io::InputLocation& speedsWhere);

/// The options of `motostab simulate`: `options` (speed, duration, accuracy, output step as given) with
/// the perturbations parsed from their specs (simulation/perturbation.h), the speed control ("none",
/// "pi") and integrator by name, the fall limit (deg) and the roll of a steady-turn start (deg; 0:
/// straight running, which needs no speed above 0).
simulation::SimulationOptions makeSimulationOptions(simulation::SimulationOptions options,
                                                    const std::vector<std::string>& perturbations,
                                                    const std::string& speedControl, const std::string& integrator,
                                                    double fallLimitDeg, double rollDeg);

/// "mc" or "sobol".
uncertainty::SamplingMethod parseSamplingMethod(const std::string& name, const io::InputLocation& where);

/// Slip angles A, A + STEP, ..., B (deg): finite, A <= B, STEP > 0, at most 1e5 points.
std::vector<double> makeSlipAngles(double first, double last, double step, const io::InputLocation& where);

/// A .tir file's force law (MF 6.2 for FITTYP 62, else MF 6.1), with its unused nonzero coefficients
/// reported on `warnings`.
struct TirForceLaw {
  tyres::TirFile file;
  std::unique_ptr<tyres::TyreForceLaw> law;
};
TirForceLaw loadTirForCurve(const std::string& path, std::ostream& warnings);

/// The steady-state forces at load `fz` (N), each slip angle (deg), camber (rad), slip ratio and speed
/// (m/s): the points of `motostab tyre`; ResultError where the law gives a non-finite force.
std::vector<output::TyreCurvePoint> calcTyreCurve(const tyres::TyreForceLaw& law, double fz,
                                                  const std::vector<double>& slipDeg, double camber, double slipRatio,
                                                  double speed);

}  // namespace motostab::cli
