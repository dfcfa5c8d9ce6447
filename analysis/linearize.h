#pragma once
// Linearisation about a trim: x' = A x + B u in named, independent, non-cyclic coordinates.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "analysis/mode_label.h"
#include "analysis/trim.h"

namespace motostab::analysis {

/// Columns of A evaluated together (Curtis, Powell & Reid, IMA J. Appl. Math. 13 (1974) 117):
/// columns whose possibly nonzero rows do not overlap share one pair of evaluations. On a
/// laterally symmetric vehicle the in-plane and lateral columns pair up.
struct ColumnGrouping {
  std::vector<std::string> states;            ///< names of the linear states (rows and columns)
  std::vector<Slot> slots;                    ///< q, u or z of each state
  std::vector<vehicle::StateRole> roles;      ///< the role of each state
  /// Removed coordinates whose rows the samples keep (LinearModel::removedRows, e.g. the Whipple
  /// bicycle's yaw): grouped columns fill these rows too.
  std::vector<std::string> removedStates;
  /// pattern(i, j): A(i, j) may be nonzero; rows: `states`, then `removedStates`; columns: `states`.
  Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic> pattern;
  std::vector<std::vector<int>> groups;       ///< column indices into `states`; singletons omitted (but see useMirror)
  /// Proposed mirror image (y -> -y) of the states: -1 for the pattern's connected block holding
  /// `roll` (the lateral states), +1 for the others; empty when the pattern does not split.
  std::vector<int> mirror;
  std::vector<double> rowScale;  ///< largest |A(i, j)| of pattern row i over the samples (1/s, ...)
  /// Set by checkMirrorSymmetry: each group of lateral columns then needs one evaluation, f(x0 - h d)
  /// being the mirror image of f(x0 + h d); `groups` then hold every column (singletons too), lateral
  /// groups merged with in-plane ones where that saves evaluation cost.
  bool useMirror = false;
};

struct LinearizeOptions {
  int order = 4;            ///< central-difference order: 2 or 4
  /// Perturbation (rad, m, rad/s, m/s; scaled by max(1, |value|)). Below the static deflection of the
  /// stiffest tyre (Sharp's 1e7 N/m radial tyres: about 0.1 mm), which a larger step lifts off the
  /// ground: at 1e-3 his machine's roots were off by up to 26 % (its slow roots in a turn by 0.08 1/s).
  double step = 1e-5;
  double zeroColumnTolerance = 1e-9;
  /// Differentiate along the cyclic coordinates too (to verify that their columns vanish); sweeps
  /// skip them, which the test suite justifies.
  bool computeCyclicColumns = true;
  /// Yaw is removed when no kept row depends on it (-1, automatic), always (1) or never (0).
  /// Sweeps fix it so that every speed has the same states.
  int removeYaw = -1;
  /// Compute B (sweeps do not need it: B is then empty).
  bool computeB = true;
  /// Grouped column evaluation (sweeps: from calcColumnGrouping); empty groups: one by one.
  ColumnGrouping grouping;
  /// Compute LinearModel::massMatrix and the mode labels (labelModes, analysis/modes.h).
  bool labelModes = true;
};

/// One state of the linear model: its name (files, people), the q, u or z it stands for, its role and
/// wheel (vehicle::StateInfo).
struct LinearState {
  std::string name;
  StateEntry entry;
  vehicle::StateRole role = vehicle::StateRole::Other;
  vehicle::WheelSide wheel = vehicle::WheelSide::None;
  /// Coordinate (q), rate (u) or auxiliary state (z).
  vehicle::StateKind getKind() const {
    return entry.slot == Slot::Q ? vehicle::StateKind::Coordinate
                                 : entry.slot == Slot::U ? vehicle::StateKind::Rate : vehicle::StateKind::Auxiliary;
  }
};

/// x' = A x + B u about a trim, restricted to the constraint tangent space (docs/simbody.md:
/// T = [I; -G_dep^-1 G_ind]) with the cyclic coordinates removed.
///
/// About a steady turn (TrimSummary::turn) the model is in the heading frame (docs/cornering.md): the
/// states named after the rates of x and y are the rear wheel centre's velocity along and across the
/// heading, and yaw is cyclic (removed like x and y).
struct LinearModel {
  double speed = 0;  ///< m/s
  double roll = 0;   ///< rad, the trim's roll (0 for straight running)
  bool headingFrame = false;  ///< linearised about a steady turn
  std::vector<LinearState> states;
  std::vector<std::string> inputNames;  ///< steer_torque, drive_torque, roll_torque (N m)
  Eigen::MatrixXd A, B;
  /// Columns of the removed cyclic coordinates over the kept rows (zero for a correct model).
  std::vector<std::pair<std::string, Eigen::VectorXd>> removedColumns;
  /// Rows of the removed coordinates over the kept states: d(coordinate)/dt = row x (e.g. the yaw
  /// rate of a model on rolling constraints, whose yaw rate is a dependent speed, not a state).
  std::vector<std::pair<std::string, Eigen::RowVectorXd>> removedRows;
  Eigen::VectorXcd eigenvalues;   ///< 1/s
  Eigen::MatrixXcd eigenvectors;  ///< column k belongs to eigenvalue k, unit 2-norm
  /// The mass matrix over the rate states (Slot::U, in their order): T^T M T, M Simbody's mass matrix
  /// at the trim and T the tangent-space map from those rates to every u (kg, kg m, kg m^2).
  Eigen::MatrixXd massMatrix;
  /// labels[k]: the mode of eigenvalue k (labelModes); empty when LinearizeOptions::labelModes is off.
  std::vector<ModeLabel> labels;

  int findState(const std::string& name) const;
  /// The first state with this role and kind; -1 if none.
  int findState(vehicle::StateRole role, vehicle::StateKind kind) const;
  /// The state standing for entry `e`; -1 if none.
  int findState(const StateEntry& e) const;
  /// The row c with d(name)/dt = c x: a kept state's row of A, or a removed coordinate's row;
  /// empty if `name` is neither.
  Eigen::RowVectorXd getRateRow(const std::string& name) const;
};

/// Greedy choice of dependent columns of G in `priority` order, keeping them linearly independent
/// (QR rank, threshold 1e-9), until there are as many as G has rows.
std::vector<int> chooseDependentColumns(const Eigen::MatrixXd& G, const std::vector<int>& priority);

/// The trim's Newton Jacobian d[udot; zdot]/d(getTrimUnknowns) read off A and B (the block of
/// A and B), for models without constraints whose linearisation kept every u and z; columns of removed
/// coordinates are zero. Without B the input columns (M^-1 times a unit mobility force: configuration
/// only, so nearly speed-independent) are copied from `previous`, a trim Jacobian of the same model.
/// Empty when neither holds (then the trim differentiates).
/// About a turn (`trimOptions`, lin in the heading frame) the rows of the heading-frame velocities are
/// the turn residual's, and the speed equation's row (TurnCondition::Speed) is copied from `previous`.
Eigen::MatrixXd calcTrimJacobian(const vehicle::VehicleModel& model, const LinearModel& lin, const Eigen::MatrixXd& previous = {},
                                 const TrimOptions& trimOptions = {});

/// The union sparsity pattern of `samples` (linear models with the same states; an entry counts if
/// above `tolerance` times its row's largest: symmetry zeros come out below 1e-13, and a dropped
/// entry leaks at most tolerance x row scale into its group partner, which matters in stiff rows) and a greedy grouping of its columns, coordinates
/// first so that cheap rate columns share the evaluations of position columns. Empty if the samples
/// differ in their states.
ColumnGrouping calcColumnGrouping(const std::vector<const LinearModel*>& samples, double tolerance = 1e-11);

/// For a laterally symmetric vehicle f(S y) = S f(y), S the mirror image y -> -y (S = diag(mirror)),
/// so at a symmetric trim y0 the central difference of a lateral direction d needs only f(y0 + h d):
/// f(y0 - h d) = S f(y0 + h d). Checks this at `trim` for every group of lateral columns of
/// `grouping` (model without constraints, linear states from a linearisation with these options):
/// the mirror defect |f_i(y0 - h d) - S_i f_i(y0 + h d)| / 2h must stay below `tolerance` times
/// rowScale[i] in every row i, i.e. the one-evaluation column equals the central one to that
/// fraction of each row's scale (a force that is not mirror-symmetric at second order fails). On
/// success sets grouping.useMirror and regroups the columns for one-evaluation lateral groups
/// (lateral and in-plane groups merged where that saves cost). Costs two evaluations per lateral
/// group; `trim` is restored. `defect`, if given, receives the worst ratio (infinite when the check
/// does not apply: constraints, no proposed mirror, or a trim whose lateral states or steer and
/// roll torques exceed 1e-9 of the difference step).
bool checkMirrorSymmetry(const vehicle::VehicleModel& model, TrimResult& trim, const LinearizeOptions& options,
                         ColumnGrouping& grouping, double tolerance = 1e-8, double* defect = nullptr);

/// Linearises `model` about `trim` (seed eq. 26) and computes eigenvalues and eigenvectors.
LinearModel linearize(const vehicle::VehicleModel& model, const TrimResult& trim, const LinearizeOptions& options = {});
/// linearize without copying the State: perturbs `trim.state` and, on return, has put every value
/// back exactly (only its realization cache is spent).
LinearModel linearizeInPlace(const vehicle::VehicleModel& model, TrimResult& trim, const LinearizeOptions& options = {});

}  // namespace motostab::analysis
