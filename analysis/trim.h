#pragma once
// Steady straight running at a forward speed: Newton's method (Gauss-Newton for the
// over-determined constrained case) with a backtracking line search.
#include <Eigen/Dense>
#include <stdexcept>

#include "analysis/state_function.h"

namespace motostab {

struct TrimOptions {
  double tolerance = 1e-11;   ///< on the residual's infinity norm (rad/s^2, m/s^2, m, m/s)
  int maxIterations = 40;
  double jacobianStep = 1e-6;
};

/// A trim's figures and its warm-start data for the next speed, without the Simbody State.
struct TrimSummary {
  double speed = 0;           ///< m/s
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

/// A trim that did not converge: names the speed and the residual.
class TrimError : public std::runtime_error {
 public:
  TrimError(double speed, double residual, int iterations);
  double speed, residual;
};

/// The trim unknowns: the non-cyclic q (yaw, roll, pitch, height, steer, compliance...), the wheel
/// spin rates, every z, and the steer and drive torques.
std::vector<StateEntry> getTrimUnknowns(const VehicleModel& model);

/// Trims `model` at `speed` (m/s). `warmStart` (a trim at a nearby speed) speeds it up: its unknowns,
/// extrapolated along its secant slope (and curvature), start the iteration, and its Jacobian is
/// reused, extrapolated with jacobianPerSpeed when that is set. Throws TrimError on failure.
TrimResult calcTrim(const VehicleModel& model, double speed, const TrimOptions& options = {},
                    const TrimResult* warmStart = nullptr);

/// calcTrim in place, without copying a State: `trim` (a trim at a nearby speed) is the warm start
/// and becomes the trim at `speed` (m/s). Throws TrimError on failure; `trim` then holds the last
/// iterate and the Jacobian it used, without the predictor data (slopes, curvature).
void updTrim(const VehicleModel& model, double speed, const TrimOptions& options, TrimResult& trim);

/// The trim's summary, y and inputs.
TrimPoint makeTrimPoint(const VehicleModel& model, const TrimResult& trim);
/// A TrimResult with `point`'s values in a copy of the model's default state.
TrimResult restoreTrim(const VehicleModel& model, const TrimPoint& point);

}  // namespace motostab
