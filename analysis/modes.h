#pragma once
// Mode content, labelling and tracking across speed.
#include <array>
#include <complex>
#include <string>
#include <vector>

#include "analysis/linearize.h"

namespace motostab::analysis {

/// Degree-of-freedom groups of an eigenvector, as shares of its squared magnitude (sum = 1).
/// Lateral displacement is made an angle by dividing by the wheelbase (seed sec. 4, Fig. 12).
enum class DofGroup { Roll, Steer, Yaw, Lateral, Pitch, Bounce, Forward, Compliance, Relaxation, Suspension };
constexpr int kNumDofGroups = 10;
using ModeContent = std::array<double, kNumDofGroups>;

/// Compliance coordinates: swingarm_*, and the issue-10 extensions fork_bending, fork_torsion and
/// rider_lean. An oscillatory mode they dominate is labelled with the leading coordinate's name.
bool isComplianceCoordinate(const std::string& coordinateName);

/// The group a linear state belongs to, from its name.
DofGroup getDofGroup(const std::string& stateName);

/// Content of eigenvector k of `lin`. Rates without a coordinate state count as rate / max(1, |lambda|);
/// wheel spin rates are left out; lateral and forward displacements are divided by the wheelbase.
ModeContent calcModeContent(const LinearModel& lin, int k, double wheelbase);

/// Modal assurance criterion |a^H b|^2 / (|a|^2 |b|^2) over the states both models share.
double calcMac(const LinearModel& a, int ka, const LinearModel& b, int kb);

/// A mode followed across speed. Labels: weave, capsize, castor, wobble, swingarm_bending,
/// swingarm_torsion, swingarm_twist, fork_bending, fork_torsion, rider_lean, bounce, pitch, rear_hop, relaxation, neutral, other.
struct ModeBranch {
  std::string label;
  std::vector<std::complex<double>> eigenvalue;  ///< per speed of the sweep
  std::vector<int> index;                         ///< eigenvalue index in that speed's LinearModel
};

/// Match cost of every eigenvalue of `prev` (rows) against every one of `cur` (columns): calcMatchCost.
Eigen::MatrixXd calcMatchCosts(const LinearModel& prev, const LinearModel& cur);

/// Eigenvalues tracked from speed to speed by eigenvector similarity (MAC) and eigenvalue
/// proximity, then labelled from each branch's content over the whole sweep. costs[s] (s >= 1) may
/// hold calcMatchCosts(models[s - 1], models[s]) already (sweep workers compute them as they go);
/// missing ones and the branch statistics are computed on up to `threads` threads; the assignment is serial.
std::vector<ModeBranch> trackModes(const std::vector<LinearModel>& models, double wheelbase, int threads = 1,
                                   std::vector<Eigen::MatrixXd> costs = {});

/// Sets each branch's label from its mean content over the sweep (see modes.cpp for the rules).
void labelBranches(const std::vector<LinearModel>& models, double wheelbase, std::vector<ModeBranch>& branches,
                   int threads = 1);

/// Cost of matching eigenvalue ka of `a` to kb of `b` (0 = identical).
double calcMatchCost(const LinearModel& a, int ka, const LinearModel& b, int kb);
/// The same cost from the two eigenvalues (1/s) and their MAC (0..1).
double calcMatchCost(std::complex<double> la, std::complex<double> lb, double mac);
/// The same cost from |la - lb|, |la| and |lb| (1/s) and the MAC.
double calcMatchCost(double distance, double absA, double absB, double mac);

/// Index of the eigenvalue of `b` that best continues eigenvalue ka of `a`.
int findBestMatch(const LinearModel& a, int ka, const LinearModel& b);

}  // namespace motostab::analysis
