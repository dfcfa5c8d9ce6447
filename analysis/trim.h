#pragma once
// Steady straight running at a forward speed, and steady turns at a roll angle: Newton's method
// (Gauss-Newton for the over-determined constrained case) with a backtracking line search.
//
// Steady turn (docs/cornering.md): the heading is yaw psi = 0 at the instant; every body-fixed rate
// is constant, so the roll, pitch, height, steer and compliance rates are zero, the yaw rate r is
// constant and the ground-frame velocity (xdot, ydot) of the rear wheel centre turns at r:
//   residual = [udot - (0, ..., xddot = -r ydot, yddot = r xdot, ...); zdot; qerr; uerr; V_P - V]
// over the unknowns: the non-cyclic q but yaw and roll (fixed), the yaw rate, xdot, ydot, the wheel
// spins, every z, and the steer and drive torques. V_P is the speed of the rear contact point
// (calcTurnFigures) and V the requested speed; TurnCondition::Steer and ::SteerTorque replace the
// speed equation by a fixed steer angle or steer torque, and the speed becomes an unknown.
#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>
#include <string>

#include "analysis/state_function.h"
#include "io/result_error.h"

namespace motostab::analysis {

/// What fixes a steady turn besides its roll angle.
enum class TurnCondition {
  Speed,        ///< the rear contact point's speed (the `speed` argument)
  Steer,        ///< the steer angle TrimOptions::steer; speed and steer torque are solved
  SteerTorque,  ///< the steer torque TrimOptions::steerTorque (0: hands-free); speed and steer solved
};

struct TrimOptions {
  /// On the residual's infinity norm (rad/s^2, m/s^2, m, m/s); where Newton stops descending with a fresh
  /// Jacobian, the residual's round-off floor (1000 eps max_i sum_j |J_ij| max(1, |x_j|)) also passes.
  double tolerance = 1e-11;
  int maxIterations = 40;
  double jacobianStep = 1e-6;
  /// Steady turn at this roll angle (rad, > 0 leans right, |roll| < 89 deg); NaN: straight running.
  double roll = NAN;
  TurnCondition condition = TurnCondition::Speed;  ///< of a turn
  double steer = 0;        ///< rad (> 0 left), fixed by TurnCondition::Steer
  double steerTorque = 0;  ///< N m (> 0 turns the front frame left), fixed by TurnCondition::SteerTorque
  /// Largest roll step (rad) of the continuation from upright that starts a turn trim without a warm
  /// start at the same roll.
  double rollStep = 0.0873;
  bool isTurn() const { return std::isfinite(roll); }
};

/// A trim's figures and its warm-start data for the next speed, without the Simbody State.
struct TrimSummary {
  /// m/s: straight running, the rear wheel centre's forward speed; a turn, the rear contact
  /// point's speed along its path (calcTurnFigures).
  double speed = 0;
  double roll = NAN;          ///< rad, the roll of a turn; NaN for straight running
  bool turn = false;          ///< a steady turn: linearize() works in the heading frame
  double residualNorm = 0;    ///< infinity norm of [udot; zdot; qerr; uerr]
  int iterations = 0;
  int jacobianEvaluations = 0;  ///< finite-difference Jacobians computed (2 realizations per unknown each)
  /// d residual / d unknowns near the solution, for the next warm start: the last one the Newton
  /// iteration used (differentiated at some iterate of this or an earlier speed), or in sweeps of
  /// constraint-free models the block of this speed's A (calcTrimJacobian).
  Eigen::MatrixXd jacobian;
  /// d jacobian / d speed (per m/s) when known (sweeps: from the last two speeds' A): the next warm
  /// start extrapolates the Jacobian with it, and Newton then converges at rate O(dv^2), not O(dv).
  Eigen::MatrixXd jacobianPerSpeed;
  /// Secant slope d(unknowns)/d(speed) from the warm start to this trim (getTrimUnknowns order,
  /// their units per m/s); empty without a warm start. The next warm start extrapolates with it.
  Eigen::VectorXd unknownsPerSpeed;
  /// Second divided difference of the unknowns over this, the warm start's and its warm start's
  /// speeds (units per (m/s)^2), and the earlier of those speeds: the predictor is then quadratic.
  Eigen::VectorXd unknownsCurvature;
  double secantStartSpeed = 0;  ///< m/s, the warm start's speed
};

/// A trimmed state: every udot and zdot zero, constraints satisfied, forward speed fixed.
struct TrimResult : TrimSummary {
  SimTK::State state;
};

/// A trim without its State, as sweeps keep one per speed (copying a realized State costs two to
/// four realizations): y = [q; u; z] and the inputs (N m, VehicleModel::getInputNames order).
struct TrimPoint : TrimSummary {
  Eigen::VectorXd y;
  Eigen::VectorXd inputs;
};

/// A trim that did not converge: names the speed, the roll (turns) and the residual. Valid input
/// without a result: exit code 3 (io/result_error.h).
class TrimError : public io::ResultError {
 public:
  /// `detail`, if any, is appended in parentheses (e.g. the continuation step that failed).
  TrimError(double speed, double residual, int iterations, double roll = NAN, const std::string& detail = "");
  /// None of a set of trims (a sweep's speeds, a map's roll angles) converged: `what` says which set, and
  /// `first` is the first failure, whose speed, residual and roll this error carries.
  TrimError(const std::string& what, const TrimError& first);
  /// No trim was tried (another worker failed first): `what` at `speed` (m/s) and roll; residual NaN.
  TrimError(const std::string& what, double speed, double roll);
  double speed, residual, roll;
};

/// The trim unknowns of straight running: the non-cyclic q (yaw, roll, pitch, height, steer,
/// compliance...), the wheel spin rates, every z, and the steer and drive torques.
std::vector<StateEntry> getTrimUnknowns(const vehicle::VehicleModel& model);
/// The unknowns of the trim `options` ask for (straight running, or a turn: see the header comment).
std::vector<StateEntry> getTrimUnknowns(const vehicle::VehicleModel& model, const TrimOptions& options);

/// Steady-turn figures of a state (realizes to Velocity). The rear contact point P is the contact
/// model's (ContactModel::calcContactPoint; a torus by default); its velocity is that of the rear-frame point
/// at P, v_P = v_O + w x (P - O), so in a steady turn (w = r z) |v_P| = R r with R its path radius.
struct TurnFigures {
  double speed = 0;                  ///< |v_P| horizontal, m/s
  double yawRate = 0;                ///< r, rad/s (> 0 turns left)
  double pathRadius = INFINITY;      ///< |v_P| / |r|, m (infinite when r = 0)
  double lateralAcceleration = 0;    ///< |v_P| r, m/s^2 (> 0 towards the left)
};
TurnFigures calcTurnFigures(const vehicle::VehicleModel& model, const SimTK::State& state);

/// Trims `model` at `speed` (m/s; with TurnCondition::Steer or ::SteerTorque the starting guess of
/// the speed). A turn without a warm start at the same roll starts from straight running at `speed`
/// and steps the roll up (options.rollStep) at that speed. `warmStart` (a trim at a nearby speed) speeds it up: its unknowns,
/// extrapolated along its secant slope (and curvature), start the iteration, and its Jacobian is
/// reused, extrapolated with jacobianPerSpeed when that is set. Throws TrimError on failure.
TrimResult calcTrim(const vehicle::VehicleModel& model, double speed, const TrimOptions& options = {},
                    const TrimResult* warmStart = nullptr);

/// calcTrim in place, without copying a State: `trim` (a trim at a nearby speed) is the warm start
/// and becomes the trim at `speed` (m/s). Throws TrimError on failure; `trim` then holds the last
/// iterate and the Jacobian it used, without the predictor data (slopes, curvature).
void updTrim(const vehicle::VehicleModel& model, double speed, const TrimOptions& options, TrimResult& trim);

/// No hands-free turn was found: the steer torque of the fixed-speed turns kept its sign over the speeds
/// (a result error, exit code 3).
class NoTurnError : public io::ResultError {
 public:
  NoTurnError(double roll, double low, double high, double torqueLow, double torqueHigh);
  double roll, low, high;  ///< rad; m/s, the speeds where turns were trimmed
};

/// A hands-free steady turn (calcHandsFreeTurns).
struct HandsFreeTurn {
  TrimPoint trim;  ///< the turn (trim.speed: the rear contact point's speed, m/s)
  /// On the branch of hands-free turns that leaves straight running where a real root of straight
  /// running crosses zero (the capsize speed): reached by following that branch in roll.
  bool continuesFromStraight = false;
};

/// Every hands-free steady turn (steer torque options.steerTorque, normally 0) at roll options.roll that
/// the speed grid shows, sorted by speed (docs/cornering.md): fixed-speed turns on `speeds` (m/s,
/// ascending; trimmed from the top down, stopping below the first that fails) bracket each sign change
/// of the steer torque, and TurnCondition::SteerTorque solves the turn from the bracket's linear
/// interpolation. The branch from straight running (a sweep of straight running on `speeds` finds where
/// a real root crosses zero; the hands-free turn 0.5 deg from upright there is followed in roll) is
/// marked, and added if the grid missed it. Throws NoTurnError when there is none, TrimError when none
/// of the brackets could be solved.
std::vector<HandsFreeTurn> calcHandsFreeTurns(const vehicle::VehicleModel& model, const std::vector<double>& speeds,
                                              const TrimOptions& options);

/// The index of the default turn of `turns` (not empty): the one nearest `preferredSpeed` (m/s); without
/// one (NaN), the first that continues from straight running, else the first (the slowest).
size_t chooseHandsFreeTurn(const std::vector<HandsFreeTurn>& turns, double preferredSpeed = NAN);

/// The default hands-free turn (chooseHandsFreeTurn of calcHandsFreeTurns).
TrimResult calcHandsFreeTrim(const vehicle::VehicleModel& model, const std::vector<double>& speeds, const TrimOptions& options,
                             double preferredSpeed = NAN);

/// The trim's summary, y and inputs.
TrimPoint makeTrimPoint(const vehicle::VehicleModel& model, const TrimResult& trim);
/// A TrimResult with `point`'s values in a copy of the model's default state.
TrimResult restoreTrim(const vehicle::VehicleModel& model, const TrimPoint& point);

}  // namespace motostab::analysis
