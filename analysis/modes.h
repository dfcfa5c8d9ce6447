#pragma once
// Modes: where each eigenvector's energy is (by state role), its label from that content at each
// operating point (docs/methods.md, "Mode labels"), and tracking across speed.
#include <array>
#include <complex>
#include <string>
#include <vector>

#include "analysis/linearize.h"

namespace motostab::analysis {

using vehicle::StateRole;
using vehicle::kNumStateRoles;

/// Where an eigenvector's energy is: shares by state role (sum 1, unit-free). Mechanical roles share
/// (1 - auxiliary share) in proportion to their kinetic plus potential energy, summed over the role's
/// degrees of freedom i: Re(conj(u_i) (M u)_i) + |K_ii| |q_i|^2 (M the mass matrix over the rate states,
/// K = -M A_uq; a role whose sum is negative counts as none); auxiliary states (tyre lags, controllers)
/// take their participation factors |l_ki v_ik| (normalised over all states). docs/methods.md gives the
/// reasons.
struct ModeContent {
  std::array<double, kNumStateRoles> role{};
  double frontLag = 0, rearLag = 0;  ///< the TyreLag share by wheel

  double get(StateRole r) const { return role[static_cast<int>(r)]; }
  /// Roll, yaw and lateral (the lateral rigid-body motion without the steer).
  double calcRollYawLateral() const;
  /// Pitch, height and rear suspension.
  double calcInPlane() const;
  /// Forward motion and wheel spin.
  double calcLongitudinal() const;
  /// Every compliance role (isComplianceRole).
  double calcCompliance() const;
  /// Tyre lags, controllers and other auxiliary states.
  double calcAuxiliary() const;
};

/// Content of every eigenvector of `lin` (needs lin.massMatrix; without it M = identity).
std::vector<ModeContent> calcModeContents(const LinearModel& lin);
/// Content of eigenvector k of `lin`.
ModeContent calcModeContent(const LinearModel& lin, int k);

/// The label of every eigenvalue of `lin` (index k), from its content and eigenvalue by the rules of
/// docs/methods.md: at most one weave, wobble, capsize and castor, one of each in-plane, compliance and
/// tyre-relaxation label (a complex pair counts once; a split weave may be two real roots).
std::vector<ModeLabel> labelModes(const LinearModel& lin);

/// Modal assurance criterion |a^H b|^2 / (|a|^2 |b|^2) over the states both models share.
double calcMac(const LinearModel& a, int ka, const LinearModel& b, int kb);

/// A root followed across speed, with its label at every speed.
struct ModeBranch {
  ModeLabel label = ModeLabel::Other;       ///< the label it carries at most speeds (the first of a tie)
  std::vector<ModeLabel> labels;            ///< per speed: LinearModel::labels of that speed's eigenvalue
  std::vector<std::complex<double>> eigenvalue;  ///< per speed of the sweep, 1/s
  std::vector<int> index;                         ///< eigenvalue index in that speed's LinearModel
};

/// Match cost of every eigenvalue of `prev` (rows) against every one of `cur` (columns): calcMatchCost.
Eigen::MatrixXd calcMatchCosts(const LinearModel& prev, const LinearModel& cur);

/// Eigenvalues tracked from speed to speed by eigenvector similarity (MAC) and eigenvalue proximity;
/// each branch takes the labels of its eigenvalues at every speed (LinearModel::labels, labelModes
/// where empty). costs[s] (s >= 1) may hold calcMatchCosts(models[s - 1], models[s]) already (sweep
/// workers compute them as they go); missing ones and the labels are computed on up to `threads`
/// threads; the assignment is serial.
std::vector<ModeBranch> trackModes(const std::vector<LinearModel>& models, int threads = 1,
                                   std::vector<Eigen::MatrixXd> costs = {});

/// Sets each branch's labels from the labels of its eigenvalues at every speed (labels[s][k]: of
/// eigenvalue k at speed s) and its label to the most frequent of them.
void labelBranches(const std::vector<std::vector<ModeLabel>>& labels, std::vector<ModeBranch>& branches);

/// The branch labelled `label` at speed index k: the upper member of a complex pair (imaginary part > 0;
/// of two pairs, a wobble coupled with the pitch in a turn, the one with the larger real part), or
/// nullptr when no branch has that label there.
const ModeBranch* findLabelledBranch(const std::vector<ModeBranch>& branches, ModeLabel label, size_t k);

/// Cost of matching eigenvalue ka of `a` to kb of `b` (0 = identical).
double calcMatchCost(const LinearModel& a, int ka, const LinearModel& b, int kb);
/// The same cost from the two eigenvalues (1/s) and their MAC (0..1).
double calcMatchCost(std::complex<double> la, std::complex<double> lb, double mac);
/// The same cost from |la - lb|, |la| and |lb| (1/s) and the MAC.
double calcMatchCost(double distance, double absA, double absB, double mac);

/// Index of the eigenvalue of `b` that best continues eigenvalue ka of `a`.
int findBestMatch(const LinearModel& a, int ka, const LinearModel& b);

}  // namespace motostab::analysis
