#pragma once
// Evaluation of the vehicle's first-order dynamics y' = f(y) on a working Simbody State, and
// stage-aware finite differences of it (docs/simbody.md: perturb q/u/z in place, realize, restore).
#include <Eigen/Dense>
#include <functional>

#include "vehicle/vehicle_model.h"

namespace motostab::analysis {

/// Which slot of the state a perturbation targets.
enum class Slot { Q, U, Z, Input };

/// One scalar entry of the state or of the inputs.
struct StateEntry {
  Slot slot;
  int index;  ///< q/u/z index, or the Input enum value
};

/// Evaluates derivatives and constraint errors on one reusable State (copying a State costs more
/// than two realizes).
class StateFunction {
 public:
  explicit StateFunction(const vehicle::VehicleModel& model) : model_(model) {}

  /// ydot = [qdot; udot; zdot] (realizes to Acceleration).
  void calcYDot(const SimTK::State& s, Eigen::VectorXd& ydot) const;
  /// [qerr; uerr]: holonomic position errors (m), then velocity-level errors (m/s).
  void calcConstraintErrors(const SimTK::State& s, Eigen::VectorXd& err) const;
  /// Trim residual [udot; zdot; qerr; uerr].
  void calcTrimResidual(const SimTK::State& s, Eigen::VectorXd& r) const;

  double get(const SimTK::State& s, const StateEntry& e) const;
  void set(SimTK::State& s, const StateEntry& e, double value) const;

  /// Central-difference derivative of `fn` along the direction sum_k dir[k].second * e_{dir[k].first},
  /// with step h. order 2 or 4 (five-point stencil). The state is restored afterwards.
  void calcDirectionalDerivative(SimTK::State& s, const std::vector<std::pair<StateEntry, double>>& dir, double h,
                                 int order,
                                 const std::function<void(const SimTK::State&, Eigen::VectorXd&)>& fn,
                                 Eigen::VectorXd& out) const;

  /// `fn` at the state displaced by `step` times the direction (as above); the state is restored.
  void calcDisplaced(SimTK::State& s, const std::vector<std::pair<StateEntry, double>>& dir, double step,
                     const std::function<void(const SimTK::State&, Eigen::VectorXd&)>& fn,
                     Eigen::VectorXd& out) const;

  const vehicle::VehicleModel& getModel() const { return model_; }

 private:
  const vehicle::VehicleModel& model_;
};

}  // namespace motostab::analysis
